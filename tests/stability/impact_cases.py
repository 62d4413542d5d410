#!/usr/bin/env python3
"""Stability at the extremes of crash practice (issue 13; docs/stability.md), on the benchmark decks of
decks/generate_bench.py:
- the tube (1 600 shells, Ishell 24, Johnson-Cook, TYPE7 self contact, a 50 kg sled on a rigid body) driven onto a
  fixed rigid wall at impact speeds from 0.1 to 1000 m/s and with self-contact gaps from 0.001 t to t;
- the ball on the plate (1 000 shells, a steel shell ball dropped at 10 m/s on a clamped plate, TYPE7): a plate
  1 to 10^5 times softer than the ball, and the ball starting 99 % of the gap inside it for each Inacti.

Each case must
- run to its end time with status "normal" (a folding shell may be deleted, and is named in the listing), or,
  where the case says so (Inacti 0: the deck asks that nothing be done about the initial penetration), stop with
  the deck's /STOP energy-error limit named in the message: never NaN, never a hang;
- keep its energy balance: |energy error| below ERROR_BOUND_PERCENT, every energy finite;
- never take a step below 1/1000 of the elements' own without the listing's "WARNING: time step" line.

usage: impact_cases.py CRUMPLE GENERATOR --case NAME [--work DIR]   one case, exit 1 when it fails (the ctests)
       impact_cases.py CRUMPLE GENERATOR --all [--markdown]          every case, and the table of docs/stability.md
"""
import argparse
import json
import math
import pathlib
import re
import subprocess
import sys
import tempfile
import time

ERROR_BOUND_PERCENT = 1.0  # the tube's balance: its only losses are counted (plastic work, contact, hourglass)
STEP_DROP = 1e-3           # below this share of the elements' step the listing must say so

# name: (family, generator options, end time [ms], may stop on /STOP, what it shows); the cases whose contact must
# take the step far below the elements' (EXPECT_STEP_DROP) must show the listing's warning.
EXPECT_STEP_DROP = {"gap_0.001t", "gap_0.001t_mass_scaled"}
TUBE = ["--elements", "1600"]
BALL = ["--elements", "1000"]
CASES = {
    "speed_0.1": ("tube", TUBE + ["--speed", "0.1"], 0.5, False, "a slow push: elastic, no contact"),
    "speed_10": ("tube", TUBE + ["--speed", "10"], 0.5, False, "the benchmark's speed"),
    "speed_300": ("tube", TUBE + ["--speed", "300"], 0.5, False,
                  "the front folds at once; shells turned inside out are deleted"),
    "speed_1000": ("tube", TUBE + ["--speed", "1000"], 0.15, False, "150 mm of crush in 0.15 ms"),
    "gap_0.001t": ("tube", TUBE + ["--speed", "300", "--gap", "0.0015"], 0.2, False,
                   "a gap of 0.001 t: the contact bounds the step by (g - p) / (dp/dt)"),
    "gap_t": ("tube", TUBE + ["--speed", "300", "--gap", "1.5"], 0.5, False, "a gap of t = 1.5 mm, given"),
    "gap_0.001t_mass_scaled": ("tube", TUBE + ["--speed", "300", "--gap", "0.0015", "--noda-cst", "8e-5"], 0.2, False,
                               "the same with /DT/NODA/CST: the contact still bounds the step (T-3b)"),
    "stiffness_1": ("ball_plate", BALL, 1.0, False, "a steel ball on a steel plate"),
    "stiffness_1e3": ("ball_plate", BALL + ["--plate-modulus-ratio", "1e3"], 1.0, False,
                      "the plate 1 000 times softer (elastic)"),
    "stiffness_1e5": ("ball_plate", BALL + ["--plate-modulus-ratio", "1e5"], 1.0, False,
                      "the plate 10^5 times softer: foam on steel"),
}
for inacti in (0, 1, 2, 3, 5, 6):
    CASES[f"penetration_99_inacti{inacti}"] = (
        "ball_plate", BALL + ["--penetration", "0.99", "--inacti", str(inacti)], 0.5, inacti == 0,
        f"the ball starts 99 % of the gap inside it, Inacti {inacti}")


def run_case(crumple, generator, name, work):
    family, options, end_time, may_stop, _ = CASES[name]
    deck_dir = pathlib.Path(work) / name
    subprocess.run([sys.executable, generator, family, *options, "--end-time", str(end_time), "--out", str(deck_dir)],
                   check=True, capture_output=True)
    run_name = "TUBE" if family == "tube" else "BALL"
    out = deck_dir / "out"
    started = time.monotonic()
    run = subprocess.run([crumple, "run", str(deck_dir / f"{run_name}_0000.rad"), "-o", str(out), "--quiet"],
                         capture_output=True, text=True, timeout=600)
    wall = time.monotonic() - started
    summary = json.loads((out / f"{run_name}.summary.json").read_text())
    listing = (out / f"{run_name}.out").read_text(errors="replace")
    steps, element_steps = [], []
    for line in listing.splitlines():
        m = re.match(r"^\s*\d+\s+[-+.0-9eE]+\s+([-+.0-9eE]+)\s", line)
        if m and float(m.group(1)) > 0.0:
            steps.append(float(m.group(1)))
    first_step = steps[0] if steps else float("nan")
    return {
        "name": name, "may_stop": may_stop, "exit": run.returncode, "status": summary["status"], "message": summary["message"],
        "time": summary["time"], "end_time": end_time, "cycles": summary["cycles"],
        "error": summary["energy"]["error_percent"],
        "finite": all(math.isfinite(v) for v in summary["energy"].values()),
        "deleted": summary["deleted_elements"], "smallest_printed_step": min(steps) if steps else float("nan"),
        "first_step": first_step, "step_warning": "WARNING: time step" in listing, "wall": wall,
        "listing_deletions": len(re.findall(r"DELETED: turned inside out", listing)),
    }


def failures(r):
    out = []
    if not r["finite"]:
        return ["an energy is NaN or infinite"]
    named_stop = r["exit"] == 1 and r["status"] in ("stopped", "error") and r["message"].startswith("/STOP: energy error")
    if r["may_stop"] and named_stop:
        return []  # the deck's own limit ended it, and said so
    if r["exit"] != 0 or r["status"] != "normal":
        out.append(f"status {r['status']} (exit {r['exit']}): {r['message']}")
    if not r["time"] >= r["end_time"] * (1 - 1e-9):
        out.append(f"stopped at {r['time']} before the end time {r['end_time']}")
    if not abs(r["error"]) < ERROR_BOUND_PERCENT:
        out.append(f"energy error {r['error']:.3g} % beyond {ERROR_BOUND_PERCENT} %")
    if r["name"] in EXPECT_STEP_DROP and not r["step_warning"]:
        out.append("the contact did not take the step below 1/1000 of the elements' (no step-drop warning)")
    if r["deleted"] > 0 and r["listing_deletions"] == 0:
        out.append(f"{r['deleted']} elements deleted without a line in the listing")
    # The printed rows show the smallest step only at their cycles; the warning is raised on every cycle's step.
    if r["smallest_printed_step"] < STEP_DROP * r["first_step"] and not r["step_warning"]:
        out.append(f"step {r['smallest_printed_step']:.3g} below {STEP_DROP} x the first {r['first_step']:.3g} "
                   "without the listing's warning")
    return out


def table(results):
    lines = ["| case | what it shows | end [ms] | status | cycles | energy error | deleted shells | "
             "smallest printed step / first | step warning | wall [s] |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for r in results:
        status = r["status"] if r["status"] == "normal" else f"{r['status']}: {r['message']}"
        lines.append(f"| {r['name']} | {CASES[r['name']][4]} | {r['end_time']} | {status} | {r['cycles']} | "
                     f"{r['error']:.3g} % | {r['deleted']} | {r['smallest_printed_step'] / r['first_step']:.2g} | "
                     f"{'yes' if r['step_warning'] else 'no'} | {r['wall']:.1f} |")
    return "\n".join(lines)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("crumple")
    p.add_argument("generator")
    which = p.add_mutually_exclusive_group(required=True)
    which.add_argument("--case", choices=sorted(CASES))
    which.add_argument("--all", action="store_true")
    p.add_argument("--work", help="folder for the decks and results (default: a temporary one)")
    p.add_argument("--markdown", action="store_true", help="with --all: print the table of docs/stability.md")
    a = p.parse_args()
    names = sorted(CASES, key=list(CASES).index) if a.all else [a.case]
    with tempfile.TemporaryDirectory() as tmp:
        results = [run_case(a.crumple, a.generator, n, a.work or tmp) for n in names]
    bad = 0
    for r in results:
        f = failures(r)
        bad += bool(f)
        print(f"{r['name']}: {'FAILED: ' + '; '.join(f) if f else 'passes'} (cycles {r['cycles']}, energy error "
              f"{r['error']:.3g} %, deleted {r['deleted']}, smallest printed step / first "
              f"{r['smallest_printed_step'] / r['first_step']:.2g}, wall {r['wall']:.1f} s)")
    if a.markdown:
        print(table(results))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
