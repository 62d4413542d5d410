# Generates the peer decks of /RBE2 (docs/theory/rigid-bodies.md, RE-1 to RE-5). Run from the folder that is to hold
# the decks; each folder's ref.extract is the reference solver's last printed row on its deck (run-or.sh, then
# or-extract.py). Units kg, mm, ms; steel E = 210 GPa, rho = 7.8e-6 kg/mm^3, LAW2 (a = 0.3, b = 0.5, n = 0.3 GPa).
# A plate of 8 x 4 shells (100 x 50 mm, 1.5 mm, Ishell 1), its edge x = 0 clamped, carries an /RBE2:
#   rbe2_edge_twisted: its edge x = 100 on a main node off the plate (150, 25, 0), Trarot 111 111, turned about x
#     at 0.2 rad/ms by /IMPVEL: the edge turns rigidly about the main node and twists the plate past yield.
#   rbe2_edge_pulled_iflag1: the same edge with Trarot 111 001 and Iflag 1; the main node moves 2 mm/ms along y and
#     turns about z at 0.02 rad/ms: in-plane bending past yield, the edge nodes' own x, y rotations free.
#   rbe2_bolt_beam: four nodes about the point (75, 25) on a main node 10 mm above the plate (Iflag 0), which a beam
#     of 40 mm joins to a node pulled up and sideways: a bolt through the plate pulled out.
#   rbe2_heavy_edge: the edge on a main node with 0.05 kg of /ADMAS launched at 5 mm/ms along z (/INIVEL on the
#     main node alone moves the group): a plate that swings a rigid mass about its clamped edge.
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
    s += "/SHELL/1\n"
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
    return s


def rbe2(main, trarot, group, iflag):
    return "/RBE2/1\nlink\n" + I(main) + "   " + trarot + I(0, group, iflag) + "\n"


def impvel(k, group, dirn, v):
    return ("/IMPVEL/%d\ndrive\n" % k + I(1) + "%10s" % dirn + I(0, 0, group, 0, 0) + "\n" + R(1.0, v, 0, 1e30) + "\n")


def th(nodes):
    return "/TH/NODE/1\nnodes\nDEF       \n" + "".join(I(n) + "\n" for n in nodes)


def constant():
    return "/FUNCT/1\nconst\n" + R(0, 1) + "\n" + R(1e3, 1) + "\n"


def edge_twisted(name, run):
    s = plate(run) + "/NODE\n" + I(100) + R(150, 25, 0) + "\n" + rbe2(100, "111 111", 2, 0)
    s += "/GRNOD/NODE/3\nmain\n" + I(100) + "\n/BCS/2\nmain\n   111 011" + I(0, 3) + "\n" + constant()
    s += impvel(1, 3, "XX", 0.2) + th([100, 9, 45])
    write(name, run, s, 2.0, 50)


def edge_pulled_iflag1(name, run):
    s = plate(run) + "/NODE\n" + I(100) + R(150, 25, 0) + "\n" + rbe2(100, "111 001", 2, 1)
    s += "/GRNOD/NODE/3\nmain\n" + I(100) + "\n/BCS/2\nmain\n   101 110" + I(0, 3) + "\n" + constant()
    s += impvel(1, 3, "Y", 2.0) + impvel(2, 3, "ZZ", 0.02) + th([100, 9, 45])
    write(name, run, s, 2.0, 50)


def bolt_beam(name, run):
    s = plate(run) + "/NODE\n" + I(100) + R(75, 25, 10) + "\n" + I(101) + R(75, 25, 50) + "\n" + I(102) + R(0, 25, 80) + "\n"
    s += "/GRNOD/NODE/4\nbolt\n" + I(node_id(6, 2), node_id(5, 2), node_id(6, 1), node_id(6, 3)) + "\n" + rbe2(100, "111 111", 4, 0)
    s += "/BEAM/2\n" + I(101, 100, 101, 102) + "\n/PART/2\nbolt\n" + I(2, 2) + "\n"
    s += "/PROP/BEAM/2\nbolt\n" + " " * 10 + I(0) + "\n" + R(0, 0) + "\n" + R(50.0, 200.0, 200.0, 400.0) + "\n"
    s += "   000 000" + I(0) + "\n"
    s += "/MAT/LAW1/2\nbolt\n" + R(7.8e-6) + "\n" + R(210, 0.3) + "\n"
    s += "/GRNOD/NODE/5\npulled\n" + I(101) + "\n" + constant() + impvel(1, 5, "Z", 1.0) + impvel(2, 5, "X", 0.5)
    s += th([100, 101, node_id(6, 2)])
    write(name, run, s, 3.0, 50)


def heavy_edge(name, run):
    s = plate(run) + "/NODE\n" + I(100) + R(110, 25, 0) + "\n" + rbe2(100, "111 111", 2, 0)
    s += "/GRNOD/NODE/3\nmain\n" + I(100) + "\n/ADMAS/0/1\nmass\n" + R(0.05) + I(3) + "\n"
    s += "/INIVEL/TRA/1\nlaunch\n" + R(0, 0, 5.0) + I(3) + "\n" + th([100, 9, 45])
    write(name, run, s, 3.0, 50)


edge_twisted("rbe2_edge_twisted", "RBETW")
edge_pulled_iflag1("rbe2_edge_pulled_iflag1", "RBEPL")
bolt_beam("rbe2_bolt_beam", "RBEBOLT")
heavy_edge("rbe2_heavy_edge", "RBEHVY")
