# Generates the peer decks of /RBE3 (docs/theory/rigid-bodies.md, RI-1 to RI-6). Run from the folder that is to hold
# the decks; each folder's ref.extract is the reference solver's last printed row on its deck (run-or.sh, then
# or-extract.py). Units kg, mm, ms; steel E = 210 GPa, rho = 7.8e-6 kg/mm^3, LAW2 (a = 0.3, b = 0.5, n = 0.3 GPa).
# A plate of 8 x 4 shells (100 x 50 mm, 1.5 mm, Ishell 1), its edge x = 0 clamped; an /RBE3 whose dependent node
# (150, 25, 10) carries a ramped load:
#   rbe3_two_columns: independent nodes the last two columns of the plate, Trarot_Mi blank (111 000, as the
#     reference reads it); a force along z and a moment about x on the dependent node: bending and torsion past yield.
#   rbe3_edge_rotations: the free edge alone, Trarot_Mi 111 111: the nodes' rotations take moments (RI-2, weighted by
#     Lc^2), a force along z and a moment about y.
#   rbe3_weights_modified: two sets, the two columns before the free edge with weight 1 (111 000) and the free edge
#     with weight 3 in x and y only (110 000), I_modif 1: the z weights scaled by W / W_z = 2.5 (RI-2); a force along
#     x, y and z. (One column alone in z, on one line, holds no rotation about it: the reference's error 706; a node
#     in two sets of different weights is its error 705.)
#   rbe3_mass_dependent: rbe3_two_columns with 0.02 kg of /ADMAS on the dependent node, spread over the
#     independent nodes (RI-5), and the plate launched at 2 mm/ms along z.
import os
I = lambda *v: "".join("%10d" % x for x in v)
R = lambda *v: "".join("%20.10g" % x for x in v)


def header(run):
    return "/BEGIN\n%s\n      2019         0\n%20s%20s%20s\n%20s%20s%20s\n" % (run, 'kg', 'mm', 'ms', 'kg', 'mm', 'ms')


def write(name, run, s, end, every):
    os.makedirs(name, exist_ok=True)
    open(os.path.join(name, run + "_0000.rad"), "w").write(s + "/END\n")
    open(os.path.join(name, run + "_0001.rad"), "w").write("/RUN/%s/1\n%g\n/TFILE\n%g\n/PRINT/-%d\n" % (run, end, end / 100, every))


def node_id(i, j):
    return 1 + i + 9 * j


def plate(run):
    s = header(run) + "/NODE\n"
    for j in range(5):
        for i in range(9):
            s += I(node_id(i, j)) + R(12.5 * i, 12.5 * j, 0) + "\n"
    s += I(100) + R(150, 25, 10) + "\n/SHELL/1\n"
    e = 0
    for j in range(4):
        for i in range(8):
            e += 1
            s += I(e, node_id(i, j), node_id(i + 1, j), node_id(i + 1, j + 1), node_id(i, j + 1)) + "\n"
    s += "/PART/1\nplate\n" + I(1, 1) + "\n/PROP/SHELL/1\nplate\n" + I(1, 0, 0, 0) + "\n" + R(0, 0, 0, 0, 0) + "\n"
    s += I(5, 0) + R(1.5, 0) + I(0, 0) + "\n"
    s += "/MAT/LAW2/1\nsteel\n" + R(7.8e-6) + "\n" + R(210, 0.3) + "\n" + R(0.3, 0.5, 0.3, 0, 0) + "\n" + R(0, 1) + I(0, 0) + R(0, 0) + "\n"
    s += "/GRNOD/NODE/1\nclamped\n" + I(*[node_id(0, j) for j in range(5)]) + "\n/BCS/1\nclamped\n   111 111" + I(0, 1) + "\n"
    s += "/GRNOD/NODE/2\nedge\n" + I(*[node_id(8, j) for j in range(5)]) + "\n"
    s += "/GRNOD/NODE/3\ncolumn\n" + I(*[node_id(7, j) for j in range(5)]) + "\n"
    s += "/GRNOD/NODE/4\ntwo columns\n" + I(*[node_id(i, j) for i in (7, 8) for j in range(5)]) + "\n"
    s += "/GRNOD/NODE/7\ncolumns 6, 7\n" + I(*[node_id(i, j) for i in (6, 7) for j in range(5)]) + "\n"
    s += "/GRNOD/NODE/5\ndependent\n" + I(100) + "\n"
    s += "/FUNCT/1\nramp\n" + R(0, 0) + "\n" + R(1, 1) + "\n" + R(1e3, 1) + "\n"
    return s


def rbe3(sets, ref="       ", imodif=0):
    s = "/RBE3/1\nspread\n" + I(100) + "   " + ref + I(len(sets), imodif) + "\n"
    for w, codes, group in sets:
        s += R(w) + "   " + codes + I(0, group) + "\n"
    return s


def cload(k, dirn, f):
    return "/CLOAD/%d\nload\n" % k + I(1) + "%10s" % dirn + I(0, 0, 5) + " " * 10 + R(1.0, f) + "\n"


def th():
    return "/TH/NODE/1\nnodes\nDEF       \n" + "".join(I(n) + "\n" for n in (100, 9, 45)) 


def two_columns(name, run, mass=0.0):
    s = plate(run) + rbe3([(1.0, "       ", 4)]) + cload(1, "Z", 0.15) + cload(2, "XX", 3.0) + th()
    if mass > 0.0:
        s += "/ADMAS/0/1\nmass\n" + R(mass) + I(5) + "\n/GRNOD/NODE/6\nall\n"
        s += "".join(I(*range(k, min(k + 10, 46))) + "\n" for k in range(1, 46, 10))
        s += "/INIVEL/TRA/1\nlaunch\n" + R(0, 0, 2.0) + I(6) + "\n"
    write(name, run, s, 2.0, 50)


def edge_rotations(name, run):
    s = plate(run) + rbe3([(1.0, "111 111", 2)]) + cload(1, "Z", 0.1) + cload(2, "YY", 4.0) + th()
    write(name, run, s, 2.0, 50)


def weights_modified(name, run):
    s = plate(run) + rbe3([(1.0, "111 000", 7), (3.0, "110 000", 2)], imodif=1)
    s += cload(1, "X", 2.0) + cload(2, "Y", 0.5) + cload(3, "Z", 0.1) + th()
    write(name, run, s, 2.0, 50)


two_columns("rbe3_two_columns", "RBE3TC")
edge_rotations("rbe3_edge_rotations", "RBE3ER")
weights_modified("rbe3_weights_modified", "RBE3WM")
two_columns("rbe3_mass_dependent", "RBE3MD", mass=0.02)
