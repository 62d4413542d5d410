#!/usr/bin/python3
"""Plots internal and kinetic energy against time from a Crumple listing (NAME.out) beside the reference
engine listing of a QA case (reference/*_0001.out).

usage: tools/plot_energies.py CRUMPLE_LISTING REFERENCE_LISTING OUTPUT.png [TITLE]
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def number(text):
    return float(text.replace("%", ""))


def crumple_listing(path):
    t, ie, ke = [], [], []
    rows = False
    for line in open(path):
        if line.strip().startswith("CYCLE"):
            rows = True
            continue
        parts = line.split()
        if not rows or len(parts) < 10 or not parts[0].isdigit():
            continue
        # CYCLE TIME DT ELEMENT ERROR IE KE_T KE_R EXT HG CONTACT MAS.ERR TOTAL_MASS MASS_ADDED, the element in two
        # words (SHELL 31) or four (INTER 2 NODE 31): the energies counted from the end of the row.
        t.append(number(parts[1]))
        ie.append(number(parts[-9]))
        ke.append(number(parts[-8]))
    return t, ie, ke


def reference_listing(path):
    t, ie, ke = [], [], []
    rows = False
    for line in open(path, errors="replace"):
        if "I-ENERGY" in line and "CYCLE" in line:
            rows = True
            continue
        parts = line.split()
        if not rows or len(parts) < 12 or not parts[0].isdigit():
            continue
        try:
            t.append(number(parts[1]))
            ie.append(number(parts[6]))
            ke.append(number(parts[7]))
        except ValueError:
            continue
    return t, ie, ke


def main():
    ours, ref, out = sys.argv[1], sys.argv[2], sys.argv[3]
    title = sys.argv[4] if len(sys.argv) > 4 else ""
    t, ie, ke = crumple_listing(ours)
    rt, rie, rke = reference_listing(ref)
    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4))
    a.plot(rt, rie, "k.", ms=3, label="reference listing")
    a.plot(t, ie, "r-", label="Crumple")
    a.set_xlabel("time")
    a.set_ylabel("internal energy")
    a.legend()
    b.plot(rt, rke, "k.", ms=3, label="reference listing")
    b.plot(t, ke, "r-", label="Crumple")
    b.set_xlabel("time")
    b.set_ylabel("translational kinetic energy")
    b.legend()
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    main()
