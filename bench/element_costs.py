#!/usr/bin/env python3
"""Measures the cost of one element-cycle per element kind and formulation: the METIS vertex weights of the
decomposition (src/parallel/partition.cpp, docs/parallel.md "Weights").

Each case is the square steel tube of decks/tube_impact (50 x 50 x 200 mm, 5 mm mesh, Johnson-Cook steel, a 20 kg
sled on its rear section, 10 m/s into a rigid wall) meshed with one element kind and formulation: 4-node shells,
3-node shells (each quad cut in two) or one layer of bricks through the 1.2 mm wall. The cost is the element phase
of the run's CPU time (the process's user + system time, times the element phase's share of the wall time in
NAME.summary.json's "profile", so that other work on a shared machine does not count) over elements x cycles;
each case runs REPEATS times and the median is kept:

    bench/element_costs.py build/release/src/crumple [REPEATS [FILTER]]   (FILTER: only cases whose name has it)
"""
import json
import resource
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

SIDE, LENGTH, SIZE, THICK = 50.0, 200.0, 5.0, 1.2
N_SIDE, N_LENGTH = int(SIDE / SIZE), int(LENGTH / SIZE)


def i10(v):
    return f"{v:>10d}"


def r20(v):
    return f"{v:>20.10g}"


def ring(half):
    """Points around a square section of half-width `half`, counter-clockwise, N_SIDE per side."""
    step = 2 * half / N_SIDE
    pts = [(-half + k * step, -half) for k in range(N_SIDE)] + [(half, -half + k * step) for k in range(N_SIDE)]
    pts += [(half - k * step, half) for k in range(N_SIDE)] + [(-half, half - k * step) for k in range(N_SIDE)]
    return pts


def material_cards():
    return ["/MAT/PLAS_JOHNS/1\nmild steel\n", r20(7.85e-6) + "\n", r20(210.0) + r20(0.3) + i10(0) + "\n",
            r20(0.25) + r20(0.45) + r20(0.4) + r20(0.0) + r20(0.6) + "\n",
            r20(0.0) + r20(0.0) + i10(0) + i10(0) + r20(0.0) + r20(0.0) + "\n"]


def shell_property(ishell, points):
    return ["/PROP/SHELL/1\nwall\n", i10(ishell) + i10(0) + i10(2) + i10(0) + "\n", "\n",
            i10(points) + i10(0) + r20(THICK) + r20(0.0) + i10(1) + i10(1) + "\n"]


def solid_property(isolid, icpre, ismstr=0):
    return ["/PROP/SOLID/1\nwall\n", i10(isolid) + i10(ismstr) + i10(0) + i10(icpre) + "\n",
            r20(0.0) + r20(0.0) + r20(0.0) + "\n", r20(0.0) + "\n"]


def node_layers(layers):
    """Node lines and ids: for each layer half-width, rings along the tube. Returns (lines, id[(layer, j, k)])."""
    lines, ids, nid = ["/NODE\n"], {}, 1
    for layer, half in enumerate(layers):
        for j in range(N_LENGTH + 1):
            for k, (y, z) in enumerate(ring(half)):
                ids[(layer, j, k)] = nid
                lines.append(i10(nid) + r20(1.0 + j * SIZE) + r20(y) + r20(z) + "\n")
                nid += 1
    return lines, ids, nid


def elements(kind, ids):
    """Element lines and count: quads, triangles (two per quad) or bricks (inner ring to outer ring)."""
    n_ring, out, eid = 4 * N_SIDE, [f"/{ {'shell4': 'SHELL', 'shell3': 'SH3N', 'brick': 'BRICK'}[kind] }/1\n"], 1
    for j in range(N_LENGTH):
        for k in range(n_ring):
            k1 = (k + 1) % n_ring
            quad = [(j, k), (j + 1, k), (j + 1, k1), (j, k1)]
            if kind == "shell4":
                rows = [[ids[(0,) + q] for q in quad]]
            elif kind == "shell3":
                rows = [[ids[(0,) + q] for q in quad[:3]], [ids[(0,) + q] for q in (quad[0], quad[2], quad[3])]]
            else:  # outward normal of the quad points from layer 0 (inner) to layer 1 (outer)
                rows = [[ids[(0,) + q] for q in reversed(quad)] + [ids[(1,) + q] for q in reversed(quad)]]
            for row in rows:
                out.append(i10(eid) + "".join(i10(n) for n in row) + "\n")
                eid += 1
    return out, eid - 1


def deck(kind, prop, layers, end_time):
    nodes, ids, sled = node_layers(layers)
    elems, count = elements(kind, ids)
    rear = [ids[(layer, N_LENGTH, k)] for layer in range(len(layers)) for k in range(4 * N_SIDE)]
    out = ["/BEGIN\nCOST\n", i10(2019) + i10(0) + "\n", f"{'kg':>20}{'mm':>20}{'ms':>20}\n" * 2]
    out += material_cards() + prop + ["/PART/1\nwall\n", i10(1) + i10(1) + "\n"] + nodes
    out += [i10(sled) + r20(1.0 + LENGTH) + r20(0.0) + r20(0.0) + "\n"] + elems
    out += ["/GRNOD/PART/10\nwall\n", i10(1) + "\n", "/GRNOD/NODE/11\nrear\n"]
    out += ["".join(i10(n) for n in rear[s:s + 10]) + "\n" for s in range(0, len(rear), 10)]
    out += ["/GRNOD/NODE/12\nall\n", "".join(i10(n) for n in (sled,)) + "\n", "/GRNOD/PART/13\nall\n", i10(1) + "\n"]
    out += ["/INIVEL/TRA/1\nimpact\n", r20(-10.0) + r20(0.0) + r20(0.0) + i10(13) + i10(0) + "\n"]
    out += ["/INIVEL/TRA/2\nsled\n", r20(-10.0) + r20(0.0) + r20(0.0) + i10(12) + i10(0) + "\n"]
    out += ["/RBODY/1\nsled\n", i10(sled) + i10(0) + i10(0) + i10(0) + r20(20.0) + i10(11) + i10(0) + i10(0) + i10(0)
            + "\n", r20(0.0) * 3 + "\n", r20(0.0) * 3 + "\n", i10(0) + i10(0) + "\n"]
    out += ["/RWALL/PLANE/1\nwall\n", i10(0) + i10(0) + i10(10) + i10(0) + "\n", r20(0.0) * 4 + i10(0) + "\n",
            r20(0.0) * 3 + "\n", r20(1.0) + r20(0.0) + r20(0.0) + "\n", "/END\n"]
    engine = f"/RUN/COST/1\n{end_time}\n/PRINT/-1000\n/DT\n0.9 0.0\n"
    return "".join(out), engine, count


SHELL, BRICK = [SIDE / 2], [SIDE / 2 - THICK / 2, SIDE / 2 + THICK / 2]
CASES = [  # name, kind, property cards, node layers (half-widths), end time [ms]
    ("shell4 Ishell 1, N 1", "shell4", shell_property(1, 1), SHELL, 0.6),
    ("shell4 Ishell 1, N 5", "shell4", shell_property(1, 5), SHELL, 0.6),
    ("shell4 Ishell 24, N 1", "shell4", shell_property(24, 1), SHELL, 0.6),
    ("shell4 Ishell 24, N 3", "shell4", shell_property(24, 3), SHELL, 0.6),
    ("shell4 Ishell 24, N 5", "shell4", shell_property(24, 5), SHELL, 0.6),
    ("shell4 Ishell 24, N 9", "shell4", shell_property(24, 9), SHELL, 0.6),
    ("shell4 Ishell 24, N 0 (resultant)", "shell4", shell_property(24, 0), SHELL, 0.6),
    ("shell4 Ishell 12, N 1", "shell4", shell_property(12, 1), SHELL, 0.6),
    ("shell4 Ishell 12, N 5", "shell4", shell_property(12, 5), SHELL, 0.6),
    ("shell3 Ish3n 2, N 1", "shell3", shell_property(24, 1), SHELL, 0.6),
    ("shell3 Ish3n 2, N 5", "shell3", shell_property(24, 5), SHELL, 0.6),
    ("brick Isolid 1", "brick", solid_property(1, 0), BRICK, 0.25),
    ("brick Isolid 2", "brick", solid_property(2, 0), BRICK, 0.25),
    ("brick Isolid 24", "brick", solid_property(24, 1), BRICK, 0.25),
    ("brick Isolid 14", "brick", solid_property(14, 1), BRICK, 0.25),
    ("brick Isolid 17", "brick", solid_property(17, 0), BRICK, 0.25),
    ("brick Isolid 18", "brick", solid_property(18, 1, 4), BRICK, 0.25),
]


def element_phase_seconds(crumple, folder, starter, engine, name="COST"):
    """Runs the deck COST in `folder`: the element phase's CPU seconds (the process's CPU time times the phase's
    share of the wall time) and the cycles."""
    (folder / "COST_0000.rad").write_text(starter)
    (folder / "COST_0001.rad").write_text(engine)
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    done = subprocess.run([crumple, "run", str(folder / "COST_0000.rad"), "-o", str(folder), "-q"],
                          capture_output=True, text=True)
    if done.returncode != 0:
        raise SystemExit(f"{name}: crumple run failed\n{done.stdout}\n{done.stderr}")
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime
    summary = json.loads((folder / "COST.summary.json").read_text())
    return cpu * summary["profile"]["elements"] / summary["wall_seconds"], summary["cycles"]


def run_case(crumple, folder, case):
    name, kind, prop, layers, end_time = case
    starter, engine, count = deck(kind, prop, layers, end_time)
    seconds, cycles = element_phase_seconds(crumple, folder, starter, engine, name)
    return seconds / (count * cycles) * 1e9, count, cycles


def main():
    crumple, repeats = sys.argv[1], int(sys.argv[2]) if len(sys.argv) > 2 else 3
    only = sys.argv[3] if len(sys.argv) > 3 else ""
    print("| case | elements | cycles | ns per element-cycle (median of %d) | runs |" % repeats)
    print("|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as tmp:
        for case in (c for c in CASES if only in c[0]):
            costs = []
            for _ in range(repeats):
                cost, count, cycles = run_case(crumple, Path(tmp), case)
                costs.append(cost)
            print(f"| {case[0]} | {count} | {cycles} | {statistics.median(costs):.0f} | "
                  + ", ".join(f"{c:.0f}" for c in costs) + " |", flush=True)


if __name__ == "__main__":
    main()
