#!/usr/bin/env python3
"""Every accuracy preset on every reference deck (issue 26, docs/validation.md "Presets on the reference decks").

  preset_sweep.py CRUMPLE DIR [DIR ...] [--jobs N] [--timeout S] [--markdown]

Each folder under DIR holding a ref.extract and a NAME_0000.rad (../shared/qa, ../shared/peer-cases) is run with
`--accuracy draft`, `standard` and `fine`. A run is stable when it ends normally (or stops on the deck's own /STOP
limits as the reference does) with every energy finite and its energy error within ERROR_BOUND_PERCENT; a deck
Crumple refuses (exit 2, the named errors of a keyword it does not build) is listed as refused, not as unstable.
Against the reference, at the time of its ref.extract: the internal energy (%) and the kinetic energy (% of the
reference's internal plus kinetic energy). Long (about 15 minutes on two cores): not part of .ci/run.
Exit 1 when a preset is unstable on a deck the standard preset runs.
"""
import argparse
import concurrent.futures
import json
import math
import os
import pathlib
import subprocess
import sys
import tempfile

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "shell_probes"))
from compare_listings import at, rows  # noqa: E402

PRESETS = ("draft", "standard", "fine")
ERROR_BOUND_PERCENT = 5.0  # issue 26: a preset whose run passes 5 % says which knob to loosen


def reference(folder):
    """TIME, IENERGY and KENERGYT of ref.extract (the reference listing's last printed row)."""
    values = {}
    for line in (folder / "ref.extract").read_text().splitlines():
        words = line.split()
        if len(words) >= 3 and words[1] in ("TIME", "IENERGY", "KENERGYT", "CYCLE"):
            values[words[1]] = float(words[2])
    return values


def run(crumple, folder, preset, work, timeout):
    deck = next(folder.glob("*_0000.rad"))
    out = work / f"{folder.name}.{preset}"
    try:
        done = subprocess.run([crumple, "run", str(deck), "--accuracy", preset, "-o", str(out), "--quiet"],
                              capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return dict(deck=folder.name, preset=preset, verdict="timeout")
    if done.returncode == 2 and not list(out.glob("*.summary.json")):
        return dict(deck=folder.name, preset=preset, verdict="refused")
    summaries = list(out.glob("*.summary.json"))
    if not summaries:
        return dict(deck=folder.name, preset=preset, verdict=f"crashed (exit {done.returncode})")
    summary = json.loads(summaries[0].read_text())
    error = summary["energy"]["error_percent"]
    finite = all(isinstance(v, (int, float)) and math.isfinite(v) for v in summary["energy"].values()
                 if not isinstance(v, (dict, list, str)))
    status = summary["status"]
    stable = finite and abs(error) <= ERROR_BOUND_PERCENT and status in ("normal", "stopped")
    result = dict(deck=folder.name, preset=preset, verdict="stable" if stable else f"UNSTABLE ({status})",
                  error=error, cycles=summary["cycles"], seconds=summary["wall_seconds"])
    ref = reference(folder)
    listing = next(out.glob("*.out"), None)
    row = at(rows(str(listing), True), ref.get("TIME", 0.0)) if listing else None
    if row is not None and "IENERGY" in ref:
        scale = abs(ref["IENERGY"]) + abs(ref.get("KENERGYT", 0.0))
        result["ie"] = 100.0 * (row["ie"] - ref["IENERGY"]) / ref["IENERGY"] if ref["IENERGY"] else 0.0
        result["ke"] = 100.0 * (row["ket"] - ref.get("KENERGYT", 0.0)) / scale if scale else 0.0
        result["cycles_at_ref"] = row["cycle"]
    return result


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("crumple")
    p.add_argument("dirs", nargs="+")
    p.add_argument("--jobs", type=int, default=2)
    p.add_argument("--timeout", type=float, default=900.0)
    p.add_argument("--markdown", action="store_true")
    p.add_argument("--presets", default=",".join(PRESETS), help="a comma-separated subset of " + ", ".join(PRESETS))
    a = p.parse_args()
    folders = sorted(f.parent for d in a.dirs for f in pathlib.Path(d).glob("*/ref.extract"))
    work = pathlib.Path(tempfile.mkdtemp(prefix="crumple-presets-"))
    with concurrent.futures.ThreadPoolExecutor(a.jobs) as pool:
        results = list(pool.map(lambda job: run(a.crumple, *job, work, a.timeout),
                                [(f, preset) for f in folders for preset in a.presets.split(",")]))
    if a.markdown:
        print("| deck | preset | verdict | energy error % | cycles | IE vs ref % | KE vs ref (% of scale) | s |")
        print("|---|---|---|---|---|---|---|---|")
    for r in results:
        cells = [r["deck"], r["preset"], r["verdict"], f"{r['error']:+.2f}" if "error" in r else "",
                 str(r.get("cycles", "")), f"{r['ie']:+.1f}" if "ie" in r else "", f"{r['ke']:+.1f}" if "ke" in r else "",
                 f"{r['seconds']:.1f}" if "seconds" in r else ""]
        print("| " + " | ".join(cells) + " |" if a.markdown else "  ".join(f"{c:>12}" for c in cells))
    # the decks Crumple runs: those the standard preset runs (without it in --presets, those not refused)
    runs_standard = {r["deck"] for r in results if r["verdict"] == "stable" and r["preset"] == "standard"} \
        if "standard" in a.presets.split(",") else {r["deck"] for r in results if r["verdict"] != "refused"}
    bad = [r for r in results if r["deck"] in runs_standard and r["verdict"] != "stable"]
    print(f"{len(bad)} unstable of {sum(r['deck'] in runs_standard for r in results)} runs on the "
          f"{len(runs_standard)} decks the standard preset runs; work in {work}")
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
