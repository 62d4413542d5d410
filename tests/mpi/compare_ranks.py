#!/usr/bin/env python3
"""Runs a deck as one process and under mpirun with N ranks, and checks that every result is the same bit for bit
(docs/parallel.md): the summary's energies, cycles and time, and every dataset of NAME.h5 (frames, histories,
mesh), the run metadata (date, commit, ranks) aside.

usage: compare_ranks.py CRUMPLE MPIRUN DECK WORK_DIR N [N ...] [OPTION ...]   (options of `crumple run`)
Exit 0 when every rank count gives the one-process results, 1 otherwise (each difference printed).
"""
import json
import os
import shutil
import subprocess
import sys

import h5py
import numpy as np

ENERGIES = ("internal", "kinetic_translational", "kinetic_rotational", "contact", "hourglass", "external_work",
            "total", "error_percent")


def run(command, log):
    with open(log, "w") as out:
        return subprocess.run(command, stdout=out, stderr=subprocess.STDOUT, timeout=1200).returncode


def summary_of(folder):
    [name] = [f for f in os.listdir(folder) if f.endswith(".summary.json")]
    return json.load(open(os.path.join(folder, name))), os.path.join(folder, name.replace(".summary.json", ".h5"))


def datasets(h5):
    """Every dataset of the file: path -> array."""
    out = {}
    h5.visititems(lambda path, item: out.__setitem__(path, item[()]) if isinstance(item, h5py.Dataset) else None)
    return out


def same(a, b):
    a, b = np.asarray(a), np.asarray(b)
    if a.shape != b.shape or a.dtype != b.dtype:
        return False
    if a.dtype == object:  # variable-length strings
        return a.tolist() == b.tolist()
    return a.tobytes() == b.tobytes()


def compare(serial, parallel, ranks):
    problems = []
    (s, s_h5), (p, p_h5) = summary_of(serial), summary_of(parallel)
    for key in ("cycles", "cycles_total", "time", "dt", "status"):
        if s[key] != p[key]:
            problems.append(f"{key}: {s[key]!r} one process, {p[key]!r} with {ranks} ranks")
    for key in ENERGIES:
        if float(s["energy"][key]).hex() != float(p["energy"][key]).hex():
            problems.append(f"energy {key}: {s['energy'][key]!r} one process, {p['energy'][key]!r} with {ranks} ranks")
    if s.get("parts") != p.get("parts"):  # the part table: the same numbers to their 17 digits
        problems.append(f"parts: {s.get('parts')!r} one process, {p.get('parts')!r} with {ranks} ranks")
    if p.get("ranks") != ranks:
        problems.append(f"summary ranks {p.get('ranks')}, expected {ranks}")
    with h5py.File(s_h5, "r") as a, h5py.File(p_h5, "r") as b:
        da, db = datasets(a), datasets(b)
        if set(da) != set(db):
            problems.append(f"datasets differ: {sorted(set(da) ^ set(db))[:5]}")
        for path in sorted(set(da) & set(db)):
            if not same(da[path], db[path]):
                problems.append(f"dataset {path} differs")
    return problems


def main(crumple, mpirun, deck, work, counts, options):
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    serial = os.path.join(work, "serial")
    if run([crumple, "run", deck, "-o", serial, "--quiet", *options], os.path.join(work, "serial.log")) != 0:
        print("the one-process run failed:", open(os.path.join(work, "serial.log")).read())
        return 1
    failed = False
    for n in counts:
        folder = os.path.join(work, f"np{n}")
        log = os.path.join(work, f"np{n}.log")
        code = run([mpirun, "--allow-run-as-root", "--oversubscribe", "--mca", "mpi_yield_when_idle", "1",
                    "-np", str(n), crumple, "run", deck, "-o", folder, "--quiet", *options], log)
        if code != 0:
            print(f"{n} ranks: exit code {code}:\n{open(log).read()}")
            failed = True
            continue
        problems = compare(serial, folder, n)
        print(f"{n} ranks: " + ("bit for bit the one-process run" if not problems else f"{len(problems)} differences"))
        for p in problems[:20]:
            print("   ", p)
        failed = failed or bool(problems)
    return 1 if failed else 0


if __name__ == "__main__":
    if len(sys.argv) < 6:
        print(__doc__)
        sys.exit(2)
    # rank counts, then any options of `crumple run` (e.g. --accuracy draft)
    counts = [a for a in sys.argv[5:] if a.isdigit()]
    sys.exit(main(sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4], [int(n) for n in counts],
                  [a for a in sys.argv[5:] if not a.isdigit()]))
