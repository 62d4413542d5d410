# Generates the peer decks of tied interfaces (/INTER/TYPE2, docs/theory/tied-interfaces.md): a spot weld between two
# elastic plates of non-matching meshes, 5 mm apart, as a /PROP/TYPE13 spring whose two nodes are tied to the plates
# by one TYPE2 interface each. The weld's nodes lie off-centre in their segments and 0.5 mm off the plates' planes.
# The lower plate is clamped along x = 0, the upper one pulled along its edge x = 100 across (y) and up (z), and
# twisted by a moment about x at one corner, so that the ties pass forces, moments and shear. One deck per
# formulation (Spotflag 1, 2, 4, 5). Run from the folder that is to hold the decks; each folder's ref.extract is the
# reference solver's last printed row on its deck (run-or.sh, then or-extract.py). The figures Crumple gives
# against them are in docs/validation.md.
import os
I = lambda *v: "".join("%10d" % x for x in v)
R = lambda *v: "".join("%20.10g" % x for x in v)


def plate(first_node, first_shell, xs, ys, z, part):
    nodes, shells = "", ""
    nx = len(xs)
    for j, y in enumerate(ys):
        for i, x in enumerate(xs):
            nodes += I(first_node + j * nx + i) + R(x, y, z) + "\n"
    e = first_shell
    for j in range(len(ys) - 1):
        for i in range(nx - 1):
            n1 = first_node + j * nx + i
            shells += I(e, n1, n1 + 1, n1 + 1 + nx, n1 + nx) + "\n"
            e += 1
    return nodes, "/SHELL/%d\n" % part + shells


def law(k, c=0.0):  # one degree of freedom of the weld, linear
    return R(k, c, 1, 0, 0) + "\n" + I(0, 0, 0, 0, 0) + " " * 10 + R(0, 0) + "\n" + R(0, 0, 1, 0) + "\n"


def deck(name, run, spotflag, end=3.0, every=100):
    s = "/BEGIN\n%s\n      2019         0\n%20s%20s%20s\n%20s%20s%20s\n" % (run, 'kg', 'mm', 'ms', 'kg', 'mm', 'ms')
    lower_nodes, lower = plate(1, 1, (0, 30, 65, 100), (0, 35, 70, 100), 0.0, 1)
    upper_nodes, upper = plate(101, 101, (0, 40, 70, 100), (0, 30, 60, 100), 5.0, 2)
    s += "/NODE\n" + lower_nodes + upper_nodes + I(201) + R(50, 50, 0.5) + "\n" + I(202) + R(50, 50, 4.5) + "\n"
    s += "/MAT/LAW1/1\nsteel\n" + R(7.8e-6) + "\n" + R(210.0, 0.3) + "\n"
    for part, title in ((1, "lower plate"), (2, "upper plate")):
        s += "/PART/%d\n%s\n" % (part, title) + I(1, 1) + "\n"
    s += "/PART/3\nweld\n" + I(3, 0) + "\n"
    s += "/PROP/SHELL/1\nplates\n" + I(1, 0, 0, 0) + "\n" + R(0, 0, 0, 0, 0) + "\n" + I(0, 0) + R(1.0, 0) + I(0, 0) + "\n"
    s += "/PROP/TYPE13/3\nweld\n" + R(1e-4, 1e-3) + I(0, 0, 0, 0, 0, 0) + "\n"
    s += law(20.0, 0.01) + law(10.0, 0.01) + law(10.0, 0.01) + law(500.0, 0.05) + law(800.0, 0.05) + law(800.0, 0.05)
    s += R(1, 1, 0) + I(0) + "\n" + "".join(R(0, 0, 1, 2) + "\n" for _ in range(6))
    s += lower + upper + "/SPRING/3\n" + I(1, 201, 202) + "\n"
    s += "/FUNCT/1\nramp\n" + R(0, 0) + "\n" + R(1, 1) + "\n" + R(100, 1) + "\n"
    s += "/GRNOD/NODE/1\nclamped edge\n" + I(1, 5, 9, 13) + "\n/BCS/1\nclamped\n   111 111" + I(0, 1) + "\n"
    s += "/GRNOD/NODE/2\npulled edge\n" + I(104, 108, 112, 116) + "\n"
    s += "/CLOAD/1\nacross\n" + I(1) + "         Y" + I(0, 0, 2) + " " * 10 + R(1.0, 0.05) + "\n"
    s += "/CLOAD/2\nup\n" + I(1) + "         Z" + I(0, 0, 2) + " " * 10 + R(1.0, 0.02) + "\n"
    s += "/GRNOD/NODE/3\ncorner\n" + I(116) + "\n"
    s += "/CLOAD/3\ntwist\n" + I(1) + "        XX" + I(0, 0, 3) + " " * 10 + R(1.0, 0.5) + "\n"
    for k, (node, surf, part) in enumerate(((201, 5, 1), (202, 6, 2))):
        s += "/INTER/TYPE2/%d\nweld to plate %d\n" % (k + 1, part) + I(10 + k, surf, 0, spotflag, 0, 0, 0) + "\n"
        s += "/GRNOD/NODE/%d\nweld node %d\n" % (10 + k, k + 1) + I(node) + "\n/SURF/PART/%d\nplate %d\n" % (surf, part) + I(part) + "\n"
    s += "/TH/SPRING/1\nweld\nDEF       \n" + I(1) + "\n/TH/INTER/2\nties\nDEF       \n" + I(1, 2) + "\n/END\n"
    os.makedirs(name, exist_ok=True)
    open(os.path.join(name, run + "_0000.rad"), "w").write(s)
    open(os.path.join(name, run + "_0001.rad"), "w").write(
        "/RUN/%s/1\n%g\n/TFILE\n0.01\n/PRINT/-%d\n/DT\n0.9 0\n" % (run, end, every))


for spotflag, run in ((1, "TIEDSW1"), (2, "TIEDSW2"), (4, "TIEDSW4"), (5, "TIEDSW5")):
    deck("tied_spot_weld_spotflag%d" % spotflag, run, spotflag)
