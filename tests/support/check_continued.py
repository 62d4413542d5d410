#!/usr/bin/env python3
"""A run resumed into its folder holds every result of the same run made whole (docs/output-format.md, "Restart").

    check_continued.py CONTINUED.h5 WHOLE.h5

Every history row of WHOLE (its time and every global and /TH dataset's values, bit for bit) and every frame time
are in CONTINUED, in time order, none twice; CONTINUED may hold one more row and one more frame, the stopped run's
last state. Exit code 0 when all holds, 1 otherwise (with the reason)."""
import sys

import h5py
import numpy as np


def histories(f):
    out = {}
    f["history"].visititems(lambda name, item: out.__setitem__(name, item[:]) if isinstance(item, h5py.Dataset) else None)
    return out


def frame_times(f):
    return [float(f["frames"][n].attrs["time"]) for n in sorted(f["frames"], key=int)]


def main(continued, whole):
    problems = []
    with h5py.File(continued, "r") as c, h5py.File(whole, "r") as w:
        hc, hw = histories(c), histories(w)
        tc, tw = hc["time"], hw["time"]
        if np.any(np.diff(tc) <= 0):
            problems.append("the continued file's rows are not in time order, or one is written twice")
        rows = np.searchsorted(tc, tw)
        if np.any(rows >= len(tc)) or not np.array_equal(tc[np.minimum(rows, len(tc) - 1)], tw):
            problems.append("a row of the whole run is missing from the continued file")
        elif len(tc) > len(tw) + 1:
            problems.append(f"{len(tc)} rows against the whole run's {len(tw)}: more than the stopped run's last")
        else:
            for name in sorted(set(hw) - {"time"}):
                if name not in hc or hc[name][rows].tobytes() != hw[name].tobytes():
                    problems.append(f"/history/{name} differs from the whole run's")
        fc, fw = frame_times(c), frame_times(w)
        if fc != sorted(set(fc)):
            problems.append(f"frame times {fc} are not in order or repeat")
        if not set(fw) <= set(fc) or len(fc) > len(fw) + 1:
            problems.append(f"frame times {fc} against the whole run's {fw}")
    for p in problems:
        print("MISMATCH:", p)
    print("ok" if not problems else f"{len(problems)} mismatches")
    return 0 if not problems else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
