#!/usr/bin/env python3
"""Crumple's listing beside the reference solver's, row by row at the reference's printed times.

  compare_listings.py CRUMPLE_DIR/NAME.out REF_DIR/NAME_0001.out [--every K]

Crumple's rows are interpolated linearly in time to each reference row; the columns are the internal energy,
the translational and rotational kinetic energies, Crumple's hourglass energy and each solver's step.
"""
import argparse
import re

NUM = re.compile(r"^[-+]?\d")


def rows(path, crumple):
    out = []
    inside = False
    for line in open(path, errors="replace"):
        if "CYCLE" in line and "TIME" in line and "I-ENERGY" in line:
            inside = True
            continue
        if inside and ("RESTART FILES" in line or "TERMINATION" in line or "CPU" in line):
            break
        t = line.split()
        if not inside or len(t) < 10 or not t[0].isdigit():
            continue
        try:
            if crumple:
                r = dict(cycle=int(t[0]), time=float(t[1]), dt=float(t[2]), ie=float(t[-9]), ket=float(t[-8]),
                         ker=float(t[-7]), ext=float(t[-6]), hg=float(t[-5]), contact=float(t[-4]))
            else:
                r = dict(cycle=int(t[0]), time=float(t[1]), dt=float(t[2]), ie=float(t[-7]), ket=float(t[-6]),
                         ker=float(t[-5]), ext=float(t[-4]), hg=0.0, contact=0.0)
        except ValueError:
            continue
        out.append(r)
    return out


def at(rs, time):
    for a, b in zip(rs, rs[1:]):
        if a["time"] <= time <= b["time"]:
            w = 0 if b["time"] == a["time"] else (time - a["time"]) / (b["time"] - a["time"])
            return {k: a[k] + w * (b[k] - a[k]) for k in a}
    return rs[-1] if rs and time >= rs[-1]["time"] else None


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("crumple")
    p.add_argument("reference")
    p.add_argument("--every", type=int, default=1)
    a = p.parse_args()
    cr, ref = rows(a.crumple, True), rows(a.reference, False)
    print(f"{'time':>9} {'IE ref':>10} {'IE cr':>10} {'dIE%':>6} {'KE ref':>10} {'KE cr':>10} {'KR ref':>9} "
          f"{'KR cr':>9} {'HG cr':>9} {'cyc ref':>7} {'cyc cr':>8} {'dt ref':>9} {'dt cr':>9}")
    for k, r in enumerate(ref):
        if k % a.every and k != len(ref) - 1:
            continue
        c = at(cr, r["time"])
        if c is None:
            continue
        d = 100 * (c["ie"] - r["ie"]) / r["ie"] if r["ie"] else 0.0
        print(f"{r['time']:9.4g} {r['ie']:10.4g} {c['ie']:10.4g} {d:6.1f} {r['ket']:10.4g} {c['ket']:10.4g} "
              f"{r['ker']:9.3g} {c['ker']:9.3g} {c['hg']:9.3g} {r['cycle']:7d} {c['cycle']:8.0f} {r['dt']:9.3e} "
              f"{c['dt']:9.3e}")


if __name__ == "__main__":
    main()
