#!/usr/bin/env bash
# The cost of writing results and histories (docs/performance.md, "Output cost"): the example tube with 20 frames
# (/ANIM/DT every 0.15 of its 3.0) and 1000 history rows (/TFILE 0.003), against the same run writing one frame
# and one history row at the end (/ANIM/DT and /TFILE past the end time). Both in one invocation, three times each
# alternately; prints the wall times (the summary's wall_seconds), the phase profile's output share and the ratio.
#   bench/output_cost.sh [CRUMPLE]     (default build/release/src/crumple)
set -euo pipefail
cd "$(dirname "$0")/.."
crumple=${1:-build/release/src/crumple}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp decks/tube_impact/TUBE_0000.rad "$work/"
engine() {  # $1 folder, $2 anim interval, $3 history interval
  mkdir -p "$work/$1"
  cp "$work/TUBE_0000.rad" "$work/$1/"
  printf '/RUN/TUBE/1\n3.0\n/TFILE\n%s\n/ANIM/DT\n0.0 %s\n/PRINT/-1000\n/DT\n0.9 0.0\n' "$3" "$2" > "$work/$1/TUBE_0001.rad"
}
engine full 0.15 0.003
engine none 10 10
for round in 1 2 3; do
  for c in full none; do
    "$crumple" run "$work/$c/TUBE_0000.rad" -o "$work/$c/out" --quiet > /dev/null 2>&1
    /usr/bin/python3 - "$work/$c/out/TUBE.summary.json" "$c" "$work/$c/out/TUBE.h5" <<'PY'
import json, sys, h5py
s = json.load(open(sys.argv[1])); p = s["profile"]
total = p["elements"] + p["contact"] + p["loads"] + p["update"] + p["output"]
with h5py.File(sys.argv[3]) as f:
    frames, rows = len(f["frames"]), f["history/time"].shape[0]
print(f"{sys.argv[2]:5s} wall {s['wall_seconds']:.3f} s  output phase {p['output']:.3f} s ({100*p['output']/total:.2f} %)  "
      f"frames {frames}  history rows {rows}")
PY
  done
done
