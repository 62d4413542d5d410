#!/usr/bin/env python3
"""Writes BOXG_0000.rad / BOXG_0001.rad: boxes (/BOX/RECTA, /CYLIN, /SPHER, /BOX) cutting through a 4x4 shell
plate, a strip of 3-node shells and a 3x3x3 brick block, and the groups made from them (/GRNOD/BOX, /GRSHEL/BOX,
/BOX2, /GRSH3N/BOX, /BOX2, /GRBRIC/BOX, /BOX2). /IOFLAG Ipri = 5 makes the reference's starter listing print
every group's members. Run: python3 make_deck.py (writes next to this script)."""
import os

H = 0.01
here = os.path.dirname(os.path.abspath(__file__))
out = []


def w(s=""):
    out.append(s)


def i10(*v):
    return "".join(f"{x:10d}" for x in v)


def r20(*v):
    return "".join(f"{x:20.6g}" for x in v)


def plate(i, j):
    return 1 + i + 5 * j


def strip(i, j):
    return 101 + i + 5 * j


def block(i, j, k):
    return 201 + i + 4 * j + 16 * k


w("#RADIOSS STARTER")
w("# Crumple: boxes and box groups against the reference (tests/regression/decks/box_groups/README.md)")
w("/BEGIN\nBOXG\n      2019         0")
w("                  kg                   m                   s")
w("                  kg                   m                   s")
w("/IOFLAG\n" + i10(5, 0, 0, 0, 0, 0))
w("/NODE")
for j in range(5):
    for i in range(5):
        w(i10(plate(i, j)) + r20(i * H, j * H, 0.0))
for j in range(2):
    for i in range(5):
        w(i10(strip(i, j)) + r20(i * H, j * H, 0.05))
for k in range(4):
    for j in range(4):
        for i in range(4):
            w(i10(block(i, j, k)) + r20(0.1 + i * H, j * H, k * H))
w("/SHELL/1")
for j in range(4):
    for i in range(4):
        w(i10(1 + i + 4 * j, plate(i, j), plate(i + 1, j), plate(i + 1, j + 1), plate(i, j + 1)))
w("/SH3N/2")
for i in range(4):
    w(i10(101 + 2 * i, strip(i, 0), strip(i + 1, 0), strip(i + 1, 1)))
    w(i10(102 + 2 * i, strip(i, 0), strip(i + 1, 1), strip(i, 1)))
w("/BRICK/3")
for k in range(3):
    for j in range(3):
        for i in range(3):
            n = [block(i, j, k), block(i + 1, j, k), block(i + 1, j + 1, k), block(i, j + 1, k)]
            n += [x + 16 for x in n]
            w(i10(201 + i + 3 * j + 9 * k, *n))
for p, pid, title in ((1, 1, "plate"), (2, 1, "strip"), (3, 2, "block")):
    w(f"/PART/{p}\n{title}\n" + i10(pid, 1, 0))
w("/PROP/SHELL/1\nshell\n" + i10(24, 0, 0, 0) + "\n" + r20(0) + "\n" + i10(3, 0) + r20(0.001))
w("/PROP/SOLID/2\nsolid\n" + i10(1, 0, 0, 0))
w("/MAT/ELAST/1\nsteel\n" + r20(7800) + "\n" + r20(2.1e11, 0.3))
# Skew 1: Y' along (-1, 1, 0), Z' along Z, so X' along (1, 1, 0): 45 degrees about Z. Skew 2: the same axes about
# another origin.
w("/SKEW/FIX/1\nrotated 45 degrees about Z\n" + r20(0, 0, 0) + "\n" + r20(-1, 1, 0) + "\n" + r20(0, 0, 1))
w("/SKEW/FIX/2\nskew 1 about another origin\n" + r20(0.02, 0.02, 0) + "\n" + r20(-1, 1, 0) + "\n" + r20(0, 0, 1))
# Skew 3: moving, X from node 1 to node 7, also 45 degrees about Z at the start.
w("/SKEW/MOV/3\nmoving, X along nodes 1 to 7\n" + i10(1, 7, 2) + "         X")


def recta(bid, title, n1, n2, skew, p1, p2):
    w(f"/BOX/RECTA/{bid}\n{title}")
    w("".join(f"{x:10d}" if x else " " * 10 for x in (n1, n2, skew)))
    w(r20(*p1) + "\n" + r20(*p2))


def cylin(bid, title, n1, n2, d, p1, p2):
    w(f"/BOX/CYLIN/{bid}\n{title}")
    w("".join(f"{x:10d}" if x else " " * 10 for x in (n1, n2)) + " " * 10 + r20(d))
    w(r20(*p1) + "\n" + r20(*p2))


def spher(bid, title, n1, d, p):
    w(f"/BOX/SPHER/{bid}\n{title}")
    w((f"{n1:10d}" if n1 else " " * 10) + " " * 20 + r20(d))
    w(r20(*p))


recta(1, "cuts plate shells", 0, 0, 0, (0.005, -0.001, -0.001), (0.025, 0.015, 0.001))
recta(2, "faces on nodes, flat in z", 0, 0, 0, (0.01, 0.01, 0.0), (0.03, 0.02, 0.0))
recta(3, "box 1 with its corners swapped", 0, 0, 0, (0.025, 0.015, 0.001), (0.005, -0.001, -0.001))
recta(4, "corners at nodes 7 and 19 (coordinates ignored)", 7, 19, 0, (5, 5, 5), (-5, -5, -5))
recta(5, "corner 1 at node 1 (coordinates ignored), corner 2 at node 25", 1, 25, 0, (5, 5, 5), (0.015, 0.015, 0.0))
recta(6, "skew 1", 0, 0, 1, (0.02, -0.001, -0.001), (0.02, 0.041, 0.001))
cylin(7, "axis along z through node 13", 0, 0, 0.025, (0.02, 0.02, -0.001), (0.02, 0.02, 0.001))
cylin(8, "axis along x, ends at x 0.005 and 0.025", 0, 0, 0.025, (0.005, 0.02, 0.0), (0.025, 0.02, 0.0))
cylin(9, "axis from node 11 to node 15", 11, 15, 0.005, (5, 5, 5), (-5, -5, -5))
spher(10, "centre at node 13 by coordinates", 0, 0.03, (0.02, 0.02, 0.0))
spher(11, "centre at node 2", 2, 0.025, (5, 5, 5))
for bid, title, ids in ((12, "box 4 minus box 7", (4, -7)), (13, "minus box 7, then box 4", (-7, 4)),
                        (14, "box 1 and box 11", (1, 11)), (15, "boxes 12 and 14", (12, 14))):
    w(f"/BOX/BOX/{bid}\n{title}\n" + i10(*ids))
recta(16, "cuts the strip", 0, 0, 0, (0.005, -0.001, 0.049), (0.025, 0.011, 0.051))
spher(17, "corner of the block", 201, 0.045, (0, 0, 0))
recta(18, "slab of the block", 0, 0, 0, (0.105, -1, -1), (0.125, 1, 0.015))
recta(19, "box 6 in skew 2", 0, 0, 2, (0.02, -0.001, -0.001), (0.02, 0.041, 0.001))
w("/BOX/BOX/20\nbox 1, minus box 7, box 4\n" + i10(1, -7, 4))
recta(21, "box 6 in moving skew 3", 0, 0, 3, (0.02, -0.001, -0.001), (0.02, 0.041, 0.001))
w("/BOX/BOX/22\nthe plate outside the diamond\n" + i10(5, -6))

for bid in range(1, 23):
    w(f"/GRNOD/BOX/{100 + bid}\nnodes in box {bid}\n" + i10(bid))
for gid, kind, bid in ((301, "BOX", 1), (302, "BOX2", 1), (303, "BOX", 7), (304, "BOX2", 7), (305, "BOX", 4),
                       (306, "BOX2", 4)):
    w(f"/GRSHEL/{kind}/{gid}\nshells {kind} {bid}\n" + i10(bid))
for gid, kind in ((401, "BOX"), (402, "BOX2")):
    w(f"/GRSH3N/{kind}/{gid}\n3-node shells {kind} 16\n" + i10(16))
for gid, kind, bid in ((501, "BOX", 17), (502, "BOX2", 17), (503, "BOX", 18), (504, "BOX2", 18)):
    w(f"/GRBRIC/{kind}/{gid}\nbricks {kind} {bid}\n" + i10(bid))
# Observable in a run: the plate held on the skewed diamond of box 6 and launched at 1 m/s in z outside it (box 22).
# Energies compared with the reference (README.md).
w("/BCS/1\nhold the diamond\n   111 111         0       106")
w("/INIVEL/TRA/1\nlaunch the plate\n" + r20(0, 0, 1) + i10(122))
w("/END")

with open(os.path.join(here, "BOXG_0000.rad"), "w") as f:
    f.write("\n".join(out) + "\n")
with open(os.path.join(here, "BOXG_0001.rad"), "w") as f:
    f.write("/RUN/BOXG/1\n2e-4\n/PRINT/-10\n/TFILE\n1e-5\n/END\n")
