#!/usr/bin/env bash
# A scene pays only for what it uses (issue 13; docs/performance.md, "Unused features"): runs a deck without
# contact, rigid walls, rigid bodies, time-history requests and yielding (the ball and plate of
# decks/generate_bench.py, no interface, 0.1 m/s, 0.2 ms) under `perf record`, and prints the share of the samples
# in the code of each of those features. Each must be 0: their code is not entered, not merely cheap.
#
# usage: bench/unused_features.sh CRUMPLE [ELEMENTS]     (needs perf; Release build)
set -euo pipefail
crumple=${1:?usage: bench/unused_features.sh CRUMPLE [ELEMENTS]}
elements=${2:-10000}
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 "$here/../decks/generate_bench.py" ball_plate --elements "$elements" --no-contact --speed 0.1 --end-time 0.2 \
  --out "$work/deck" > /dev/null
if grep -q -E '^/(TH|INTER|RWALL|RBODY)' "$work/deck/BALL_0000.rad"; then
  echo "unused_features.sh: the deck has a feature it must not have" >&2
  exit 1
fi
perf record -q -o "$work/perf.data" "$crumple" run "$work/deck/BALL_0000.rad" -o "$work/out" --quiet > /dev/null 2>&1
report=$(perf report -i "$work/perf.data" --no-children --stdio --sort symbol 2> /dev/null | grep -E '^ +[0-9]+\.[0-9]+%')
share() {  # summed share [%] of the symbols matching the pattern
  printf '%s\n' "$report" | grep -E "$1" | awk '{gsub("%", "", $1); s += $1} END {printf "%.2f", s + 0}'
}
printf 'deck: ball and plate, %s shells, no contact, walls, rigid bodies or /TH, 0.1 m/s (no point yields)\n' "$elements"
printf '%-40s %s\n' "feature (symbols)" "share of the samples [%]"
printf '%-40s %s\n' "contact (crumple::contact::)" "$(share 'crumple::contact::')"
printf '%-40s %s\n' "rigid walls (rigid_wall, apply_rigid_walls)" "$(share '[Rr]igid_?[Ww]all')"
printf '%-40s %s\n' "rigid bodies (rigid_bod, rbody)" "$(share 'rigid_bod|rbody|RigidBod')"
printf '%-40s %s\n' "histories (the /TFILE global rows only)" "$(share 'history|History|th_channel')"
printf '%-40s %s\n' "plastic flow (hardening slope, yield_and_slope)" "$(share 'yield_and_slope|Hardening::slope')"
printf '%-40s %s\n' "shell elements (shell_forces, section)" "$(share 'shell_forces|shell_section')"
