#!/usr/bin/env python3
"""Does a model with springs and beams keep the shells' throughput (issue 28)? The tube of bench/element_costs.py (QEPH shells,
N = 3, Johnson-Cook steel, 10 m/s into a wall) run as it is and with springs numbering 10 % of its shells, each
joining a node to the node two rings further along the tube, so soft and light that the tube deforms as without them (the same plastic flow in the shells). The measure is the
element phase's CPU time (element_costs.py's) over the SHELL element-cycles: the springs' own cost is in it, so a
ratio within 1.05 means the shells run as fast with the springs beside them and the springs cost little. A third
model has half of those springs (5 % of the shells) and as many beams (/PROP/TYPE3, LAW1) on the same pattern, as soft
and light (a wave speed that never sets the step):

    bench/spring_mix.py build/release/src/crumple [REPEATS]
"""
import statistics
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
import element_costs as ec  # noqa: E402


def with_springs(starter, shells):
    nodes, ids, _ = ec.node_layers(ec.SHELL)
    n_ring = 4 * ec.N_SIDE
    lines, eid = ["/SPRING/2\n"], 1
    for j in range(ec.N_LENGTH - 2):
        for k in range(n_ring):
            if eid > shells // 10:
                break
            lines.append(ec.i10(eid) + ec.i10(ids[(0, j, k)]) + ec.i10(ids[(0, j + 2, k)]) + "\n")
            eid += 1
    cards = "".join(lines) + "/PART/2\nsprings\n" + ec.i10(2) + ec.i10(0) + "\n"
    # M 1e-7 kg (the nodes have about 2e-4), K 1e-9 kN/mm: step sqrt(M/K) = 10 ms, never the step
    cards += "/PROP/SPRING/2\nspring\n" + ec.r20(1e-7) + "\n" + ec.r20(1e-9) + ec.r20(0.0) + "\n" + ec.i10(0) + "\n"
    cards += ec.r20(0.0) + "\n"
    return starter.replace("/END\n", cards + "/END\n"), eid - 1


def with_springs_and_beams(starter, shells):
    half, springs = with_springs(starter, shells // 2)
    nodes, ids, _ = ec.node_layers(ec.SHELL)
    n_ring = 4 * ec.N_SIDE
    lines, eid, count = ["/BEAM/3\n"], 1, 0
    for j in range(1, ec.N_LENGTH - 2):  # one ring on from the springs, so that they do not share every node
        for k in range(n_ring):
            if count >= springs:
                break
            lines.append(ec.i10(eid) + ec.i10(ids[(0, j, k)]) + ec.i10(ids[(0, j + 2, k)]) + ec.i10(ids[(0, j, (k + 1) % n_ring)]) + "\n")
            eid, count = eid + 1, count + 1
    cards = "".join(lines) + "/PART/3\nbeams\n" + ec.i10(3) + ec.i10(3) + "\n"
    # A 1e-4 mm2, E 1e-9 GPa, rho 1e-6 kg/mm3: a wave speed of 0.03 mm/ms, a step of some 100 ms, never the step
    cards += "/PROP/BEAM/3\nbeam\n" + " " * 10 + ec.i10(0) + "\n" + ec.r20(0.0) + ec.r20(0.0) + "\n"
    cards += ec.r20(1e-4) + ec.r20(1e-9) + ec.r20(1e-9) + ec.r20(2e-9) + "\n" + "   000 000" + ec.i10(0) + "\n"
    cards += "/MAT/LAW1/3\nsoft\n" + ec.r20(1e-6) + "\n" + ec.r20(1e-9) + ec.r20(0.3) + "\n"
    return half.replace("/END\n", cards + "/END\n"), springs, count


def main():
    crumple, repeats = sys.argv[1], int(sys.argv[2]) if len(sys.argv) > 2 else 3
    starter, engine, shells = ec.deck("shell4", ec.shell_property(24, 3), ec.SHELL, 0.6)
    mixed, springs = with_springs(starter, shells)
    both, half_springs, beams = with_springs_and_beams(starter, shells)
    rows = {}
    with tempfile.TemporaryDirectory() as tmp:
        for _ in range(repeats):  # alternated, so that a slow spell of the machine falls on all
            for name, deck in (("shells alone", starter), (f"shells and {springs} springs", mixed),
                               (f"shells, {half_springs} springs and {beams} beams", both)):
                seconds, cycles = ec.element_phase_seconds(crumple, Path(tmp), deck, engine, name)
                rows.setdefault(name, []).append(seconds / (shells * cycles) * 1e9)
    base = statistics.median(rows["shells alone"])
    print(f"| model | shells | ns per shell element-cycle (median of {repeats}) | runs | ratio |")
    print("|---|---|---|---|---|")
    for name, costs in rows.items():
        print(f"| {name} | {shells} | {statistics.median(costs):.0f} | " + ", ".join(f"{c:.0f}" for c in costs)
              + f" | {statistics.median(costs) / base:.3f} |")


if __name__ == "__main__":
    main()
