#!/usr/bin/python3
"""Runs Crumple on the shared QA decks and draws, per deck, its internal and kinetic energy against the reference
listing's, with the reference's time marked (docs/validation.md).

usage: tools/validation_plots.py CRUMPLE_EXE QA_DIR OUT_DIR [CASE ...]

For each case folder QA_DIR/CASE (one NAME_0000.rad, the engine decks beside it and reference/NAME_000N.out):
runs `crumple run` into a temporary folder, reads the histories of NAME.h5 and the energy rows of every reference
engine listing (a continued run's listings follow each other in time), and writes OUT_DIR/CASE_energies.png.
Prints one line per case with the values at the reference's time (the TIME of ref.extract).
"""
import glob
import os
import subprocess
import sys
import tempfile

import h5py
import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def reference_rows(folder, name):
    """time, internal, kinetic (translational + rotational) of every energy row of the engine listings."""
    t, ie, ke = [], [], []
    for listing in sorted(glob.glob(os.path.join(folder, "reference", name + "_0[0-9][0-9][1-9].out"))):
        rows = False
        for line in open(listing, errors="replace"):
            if "I-ENERGY" in line and "CYCLE" in line:
                rows = True
                continue
            parts = line.split()
            # an energy row: CYCLE TIME TIME-STEP, then what sets the step (a word), its id, ERROR...
            if not rows or len(parts) < 10 or not parts[0].isdigit() or not parts[3][0].isalpha():
                continue
            try:
                # CYCLE TIME TIME-STEP ELEMENT id ERROR I-ENERGY K-ENERGY-T K-ENERGY-R EXT-WORK ...
                t.append(float(parts[1]))
                ie.append(float(parts[6]))
                ke.append(float(parts[7]) + float(parts[8]))
            except ValueError:
                continue
    return np.array(t), np.array(ie), np.array(ke)


def reference_time(folder):
    for line in open(os.path.join(folder, "ref.extract")):
        parts = line.split()
        if len(parts) >= 3 and parts[1] == "TIME":
            return float(parts[2])
    return None


def main():
    exe, qa, out = sys.argv[1], sys.argv[2], sys.argv[3]
    cases = sys.argv[4:] or sorted(os.path.basename(os.path.dirname(p)) for p in glob.glob(os.path.join(qa, "*/ref.extract")))
    os.makedirs(out, exist_ok=True)
    for case in cases:
        folder = os.path.join(qa, case)
        starter = glob.glob(os.path.join(folder, "*_0000.rad"))[0]
        name = os.path.basename(starter)[: -len("_0000.rad")]
        with tempfile.TemporaryDirectory() as tmp:
            subprocess.run([exe, "run", starter, "-o", tmp], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            h = h5py.File(os.path.join(tmp, name + ".h5"), "r")["history"]
            t = h["time"][:]
            ie = h["internal"][:]
            ke = h["kinetic_translational"][:] + h["kinetic_rotational"][:]
        rt, rie, rke = reference_rows(folder, name)
        tref = reference_time(folder)
        fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4))
        for axis, ours, ref, label in ((a, ie, rie, "internal energy"), (b, ke, rke, "kinetic energy (trans. + rot.)")):
            axis.plot(rt, ref, "k.", ms=3, label="reference listing")
            axis.plot(t, ours, "r-", label="Crumple")
            if tref is not None:
                axis.axvline(tref, color="0.6", ls="--", lw=0.8, label="reference's time")
            axis.set_xlabel("time")
            axis.set_ylabel(label)
            axis.legend()
        fig.suptitle(case)
        fig.tight_layout()
        fig.savefig(os.path.join(out, case + "_energies.png"), dpi=100)
        plt.close(fig)
        print("%-24s t %.4e  IE %.5g  KE %.5g" % (case, tref, np.interp(tref, t, ie), np.interp(tref, t, ke)))


if __name__ == "__main__":
    main()
