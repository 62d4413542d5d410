#!/usr/bin/env bash
# A new user's walk through the README, recorded: runs each step as the README shows it, on the example deck, and
# writes what it printed into docs/walkthrough.md, with the pictures it made in docs/images/ (made here, by the
# project's own commands, never by hand). Run it after the quick start's build:
#   scripts/walkthrough.sh [CRUMPLE]   (default build/release/src/crumple; needs pvpython and xvfb-run)
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
crumple=$(realpath "${1:-$top/build/release/src/crumple}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
cp -r "$top/decks/tube_impact" deck
doc="$top/docs/walkthrough.md"

# One step: its title, the command as the user types it (with `crumple` for the binary), and what it printed.
step() {
  local title=$1 shown=$2
  shift 2
  local output code=0
  output=$("$@" 2>&1) || code=$?
  printf '\n### %s\n\n```\n$ %s\n%s\n```\n' "$title" "$shown" "$output" >> "$doc.partial"
  [ "$code" -eq 0 ] || printf '(exit code %s)\n' "$code" >> "$doc.partial"
}

cat > "$doc.partial" <<TEXT
# A new user's walk through the README

What the README's steps print on the example deck (\`decks/tube_impact\`: a square tube crushed on a rigid wall,
kg, mm, ms), recorded by \`scripts/walkthrough.sh\` (Crumple $("$crumple" --version | head -1 | awk '{print $2}')),
which runs each command below as written and made the pictures.
TEXT

step "Check the deck: counts, units by name, mass and step" "crumple check deck/TUBE_0000.rad" \
  "$crumple" check deck/TUBE_0000.rad
step "Run it" "crumple run deck/TUBE_0000.rad -o out -q" "$crumple" run deck/TUBE_0000.rad -o out -q
step "The listing names its units, its masses and every frame" "grep -E '^(UNITS|POINT|CYCLE .*FRAME|PART)' out/TUBE.out" \
  grep -E '^(UNITS|POINT|CYCLE .*FRAME|PART)' out/TUBE.out
step "Time histories with their units" "crumple th out/TUBE.h5 --csv --select internal 'rigid_wall_force/*' | head -3" \
  bash -c "'$crumple' th out/TUBE.h5 --csv --select internal 'rigid_wall_force/*' | head -3"
step "Plots, their axes in the deck's units" "crumple plot out/TUBE.h5 -o out/plots" "$crumple" plot out/TUBE.h5 -o out/plots
cp out/plots/TUBE_energy.png "$top/docs/images/TUBE_energy.png"
printf '\n![the energy balance, as crumple plot draws it](images/TUBE_energy.png)\n' >> "$doc.partial"

step "ParaView opens the run on its deformed shape, no filter" \
  "pvpython tests/support/check_paraview.py out/TUBE.xdmf tube.png   (as the test cli.paraview_tube does)" \
  xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" pvpython "$top/tests/support/check_paraview.py" out/TUBE.xdmf \
  tube.png
cp tube.png "$top/docs/images/tube_paraview.png"
printf '\n![the last frame as ParaView opens NAME.xdmf](images/tube_paraview.png)\n' >> "$doc.partial"

# A restart keeps every cycle: a run stopped half way with its snapshot, resumed into the same folder.
{ sed '2s/.*/1.5/' "$top/decks/tube_impact/TUBE_0001.rad"; printf '/RFILE\n100000\n'; } > deck/TUBE_0001.rad
step "A run to half time, its snapshot at its end" "crumple run deck/TUBE_0000.rad -o halves -q   (engine deck: end 1.5 ms, /RFILE)" \
  "$crumple" run deck/TUBE_0000.rad -o halves -q
cp "$top/decks/tube_impact/TUBE_0001.rad" deck/TUBE_0001.rad
step "Resumed into the same folder: the results go on, nothing is overwritten" \
  "crumple run deck/TUBE_0000.rad -o halves -q --restart halves/TUBE.rst" \
  "$crumple" run deck/TUBE_0000.rad -o halves -q --restart halves/TUBE.rst
step "One file, every row: the histories from t = 0 to the end" "crumple th halves/TUBE.h5 | head -1; crumple th out/TUBE.h5 | head -1" \
  bash -c "'$crumple' th halves/TUBE.h5 2>/dev/null | head -1; '$crumple' th out/TUBE.h5 2>/dev/null | head -1"

# A typo stops the run with its line and the nearest option.
sed 's|^/ANIM/DT|/ANIM/TD|' "$top/decks/tube_impact/TUBE_0001.rad" > deck/TUBE_0001.rad
step "A typo in an engine keyword stops the run, naming the line and the nearest keyword" \
  "crumple run deck/TUBE_0000.rad -o typo   (/ANIM/TD for /ANIM/DT)" "$crumple" run deck/TUBE_0000.rad -o typo
cp "$top/decks/tube_impact/TUBE_0001.rad" deck/TUBE_0001.rad

for a in draft fine; do "$crumple" run deck/TUBE_0000.rad --accuracy $a -o out_$a -q > /dev/null 2>&1; done
step "Runs compared: what --accuracy draft and fine change" \
  "crumple compare out/TUBE.h5 out_draft/TUBE.h5 out_fine/TUBE.h5 --nodes 1641 -o compare" \
  "$crumple" compare out/TUBE.h5 out_draft/TUBE.h5 out_fine/TUBE.h5 --nodes 1641 -o compare
mv "$doc.partial" "$doc"
echo "wrote $doc"
