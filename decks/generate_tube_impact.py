#!/usr/bin/env python3
"""Writes decks/tube_impact: a thin-walled square steel tube driven into a rigid wall, and decks/tube_self_contact:
the same with a TYPE7 self contact of the tube (every tube node against the tube's surface, Fric 0.2), the
contact case of the time-profile benchmark (docs/performance.md).

Units: kg, mm, ms (so stresses in GPa, velocities in m/s, energies in J). The tube is 50 x 50 mm, 200 mm long,
1.2 mm thick, meshed with 5 mm shells; its rear end carries a 20 kg rigid body (a sled) and the whole tube moves
at 10 m/s towards the plane x = 0. Run: crumple run decks/tube_impact/TUBE_0000.rad

Write: python3 decks/generate_tube_impact.py [DIR] (DIR defaults to decks/, beside this script; a test writes
them elsewhere and compares them with the committed files).

The decks are written by the tube writer of decks/generate_bench.py (the benchmark decks of issue 13), with the
example's own values; the files are the same byte for byte as before that writer existed.
"""
import sys
from pathlib import Path

from generate_bench import JohnsonCook, TubeSetup, write_tube

ENGINE = ["/RUN/TUBE/1\n3.0\n", "/TFILE\n0.01\n", "/ANIM/DT\n0.0 0.5\n", "/ANIM/ELEM/VONM\n", "/ANIM/ELEM/ENER\n",
          "/PRINT/-1000\n", "/DT\n0.9 0.0\n", "/STOP\n0.1 0.1 0.0 0 0 0\n"]


def example_tube(self_contact):
    """The example: 5 mm shells, 1.2 mm wall, 20 kg sled, 1 mm from the wall, Fric 0.2 in the self contact."""
    return TubeSetup(origin="example deck, written by decks/generate_tube_impact.py", elements_per_side=10,
                     thickness=1.2, sled_mass=20.0, gap=1.0, steel=JohnsonCook(b=0.45, n=0.4, sig_max=0.6),
                     contact=self_contact, fric=0.2, engine=ENGINE)


def main(directory, self_contact=False):
    write_tube(directory / ("tube_self_contact" if self_contact else "tube_impact"), example_tube(self_contact),
               with_meta=False)


if __name__ == "__main__":
    target = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).parent
    main(target)
    main(target, self_contact=True)
