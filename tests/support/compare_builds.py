#!/usr/bin/env python3
"""Runs two builds of crumple on the same decks and says whether their results are the same to the last bit: every
numeric dataset of NAME.h5 (frames and histories), NAME.xdmf, the listing NAME.out but its clock lines, and
`crumple check`'s output. A refactoring must keep them all (docs/architecture.md, "Element kinds as data").

    compare_builds.py OLD_CRUMPLE NEW_CRUMPLE [--work DIR] [--jobs N] [--timeout S] DECK_OR_FOLDER...

A folder stands for every NAME_0000.rad under it. Run with the system Python (/usr/bin/python3, for h5py). Exits 1
when a result differs, 0 when every one is the same.
"""
import argparse
import concurrent.futures
import pathlib
import subprocess
import sys

import h5py
import numpy as np

CLOCK_WORDS = ("ELAPSED", "STARTED", "TIME PROFILE", "Crumple ")  # lines that name the time, the date or the build


def decks_of(paths):
    for p in map(pathlib.Path, paths):
        yield from (sorted(p.rglob("*_0000.rad")) if p.is_dir() else [p])


def run(binary, deck, out, timeout):
    out.mkdir(parents=True, exist_ok=True)
    try:
        subprocess.run([binary, "run", "-q", "-o", str(out), str(deck)], stdout=subprocess.DEVNULL,
                       stderr=subprocess.DEVNULL, check=False, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None
    return subprocess.run([binary, "check", str(deck)], capture_output=True, text=True, check=False).stdout


def datasets(path):
    found = {}
    with h5py.File(path, "r") as f:
        f.visititems(lambda name, o: found.__setitem__(name, o[()]) if isinstance(o, h5py.Dataset) else None)
    return found


def same_h5(a, b):
    da, db = datasets(a), datasets(b)
    if da.keys() != db.keys():
        return [f"datasets {sorted(set(da) ^ set(db))}"]
    bad = []
    for name, x in da.items():
        y = db[name]
        if isinstance(x, np.ndarray) and x.dtype.kind in "fiu":
            if x.shape != y.shape or x.tobytes() != y.tobytes():
                bad.append(name)
    return bad


def listing(path):
    return [l for l in path.read_text(errors="replace").splitlines() if not any(w in l for w in CLOCK_WORDS)]


def compare(old, new, deck, work, timeout):
    name = f"{deck.parent.name}_{deck.stem}"
    check_old = run(old, deck, work / "old" / name, timeout)
    check_new = run(new, deck, work / "new" / name, timeout) if check_old is not None else None
    if check_old is None or check_new is None:
        return name, [f"not compared: a run took more than {timeout} s"]
    problems = [] if check_old == check_new else ["crumple check"]
    for a in sorted((work / "old" / name).glob("*")):
        b = work / "new" / name / a.name
        if not b.exists():
            problems.append(f"{a.name} missing")
        elif a.suffix == ".h5":
            problems += [f"{a.name}:{d}" for d in same_h5(a, b)]
        elif a.suffix == ".out":
            problems += [] if listing(a) == listing(b) else [a.name]
        elif a.suffix == ".xdmf":
            problems += [] if a.read_bytes() == b.read_bytes() else [a.name]
    return name, problems


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("old"), ap.add_argument("new"), ap.add_argument("decks", nargs="+")
    ap.add_argument("--work", default="compare_builds.work"), ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--timeout", type=float, default=300.0, help="seconds a run may take (default 300)")
    args = ap.parse_args()
    work = pathlib.Path(args.work)
    decks = list(decks_of(args.decks))
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        results = list(pool.map(lambda d: compare(args.old, args.new, d, work, args.timeout), decks))
    differ = skipped = 0
    for name, problems in results:
        if problems and problems[0].startswith("not compared"):
            print(f"{name}: {problems[0]}")
            skipped += 1
            continue
        print(f"{name}: {'same' if not problems else 'DIFFERS ' + ', '.join(problems[:5])}")
        differ += bool(problems)
    print(f"{len(results) - differ - skipped} of {len(results)} decks give the same results, {differ} differ, "
          f"{skipped} not compared")
    return 1 if differ or skipped else 0


if __name__ == "__main__":
    sys.exit(main())
