#!/usr/bin/env python3
"""--accuracy draft never takes more cycles than the deck as written (docs/theory/time-step.md, T-3c): the step is
the larger of the mass-scaled one and the deck's own, its contacts' included.
  draft_not_slower.py CRUMPLE WORK_DIR DECK [DECK ...]
Runs each deck with --accuracy standard and draft; fails when draft ends abnormally or takes more cycles. Before
T-3c counted the contacts, ball_on_wall took 2 265 cycles under draft against 2 096 as written, crash_triangles
3 133 against 2 597.
"""
import json
import os
import subprocess
import sys


def cycles(crumple, deck, out, preset):
    done = subprocess.run([crumple, "run", deck, "-o", out, "--quiet", "--accuracy", preset], capture_output=True,
                          text=True)
    name = os.path.basename(deck).rsplit("_", 1)[0]
    summary = os.path.join(out, name + ".summary.json")
    if done.returncode != 0 or not os.path.exists(summary):
        return None, done.stderr.strip()[-300:]
    with open(summary) as f:
        s = json.load(f)
    return (s["cycles"] if s["status"] == "normal" else None), s["status"]


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    crumple, work, decks = sys.argv[1], sys.argv[2], sys.argv[3:]
    failed = False
    for deck in decks:
        name = os.path.basename(os.path.dirname(os.path.abspath(deck)))
        standard, why_s = cycles(crumple, deck, os.path.join(work, name, "standard"), "standard")
        draft, why_d = cycles(crumple, deck, os.path.join(work, name, "draft"), "draft")
        ok = standard is not None and draft is not None and draft <= standard
        print(f"{name:20} standard {standard if standard is not None else why_s}  draft "
              f"{draft if draft is not None else why_d}  {'pass' if ok else 'FAIL'}")
        failed |= not ok
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
