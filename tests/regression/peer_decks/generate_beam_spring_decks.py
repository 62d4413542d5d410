# Generates the peer decks of /PROP/TYPE13 beam-type springs (docs/theory/spring.md, SP-15 to SP-18): a cantilever
# of four springs along x, node 1 clamped, every other node free in all six degrees of freedom. Run from the folder
# that is to hold the decks; each folder's ref.extract is the reference solver's last printed row on its deck
# (run-or.sh, then or-extract.py). The figures Crumple gives against them are in docs/validation.md.
#   beam_spring_cantilever: the tip driven sideways in y and z and out and back in x (tension hysteresis, H 7);
#     shear, torsion and bending linear with dashpots; the middle nodes released at 1 m/s in z and spun about x.
#   beam_spring_oblique: the same cantilever along (1, 2, 2) / 3, its frame from global Y, the tip driven in x
#     and z; shear hardening 1 in the spring's Y, bending hardening 2.
#   beam_spring_coincident: one spring between two nodes at the same place (a spot weld's usual model, SP-15a),
#     node 2 driven out and back in x, across in y, turned about x and z.
import os
I = lambda *v: "".join("%10d" % x for x in v)
R = lambda *v: "".join("%20.10g" % x for x in v)
CURVE = ((-1, -515), (-0.01, -20), (0, 0), (0.01, 20), (1, 515))  # 20 N at 0.01 m, then 500 N/m
UNLOADING = ((-1, -200), (-0.01, -5), (0, 0), (0.01, 5), (1, 200))
MOMENT = ((-10, -100), (-0.1, -5), (0, 0), (0.1, 5), (10, 100))


def funct(fid, pts):
    return "/FUNCT/%d\nf%d\n" % (fid, fid) + "".join(R(x, y) + "\n" for x, y in pts)


def law(k=0.0, c=0.0, fct=0, h=0, fct3=0):  # one degree of freedom: its three lines
    return R(k, c, 1, 0, 0) + "\n" + I(fct, h, 0, fct3, 0) + " " * 10 + R(0, 0) + "\n" + R(0, 0, 1, 0) + "\n"


def beam_prop(oblique):
    laws = ([law(2000, 0, 1, 7, 3), law(2000, 0.5, 1, 1), law(500, 0.5), law(20, 0.01), law(40, 0, 4, 2), law(40, 0.02)]
            if oblique else
            [law(2000, 0, 1, 7, 3), law(500, 0.5), law(500, 0.5), law(20, 0.01), law(40, 0.02), law(40, 0.02)])
    s = "/PROP/TYPE13/1\nbeam springs\n" + R(0.5, 0.02) + I(0, 0, 0, 0, 0, 0) + "\n" + "".join(laws)
    return s + R(1, 1, 0) + I(0) + "\n" + "".join(R(0, 0, 1, 2) + "\n" for _ in range(6))


def cantilever(name, run, oblique=False, end=2.0, every=50):
    step = (1 / 30, 2 / 30, 2 / 30) if oblique else (0.1, 0.0, 0.0)
    s = "/BEGIN\n%s\n      2019         0\n%20s%20s%20s\n%20s%20s%20s\n" % (run, 'kg', 'm', 's', 'kg', 'm', 's')
    s += "/NODE\n" + "".join(I(i + 1) + R(step[0] * i, step[1] * i, step[2] * i) + "\n" for i in range(5))
    s += "/SPRING/1\n" + "".join(I(i + 1, i + 1, i + 2) + "\n" for i in range(4))
    s += "/PART/1\nbeam springs\n" + I(1, 0) + "\n" + beam_prop(oblique)
    s += funct(1, CURVE) + funct(3, UNLOADING) + funct(4, MOMENT)
    s += funct(6, ((0, 0.1), (0.5, 0.1), (0.5001, -0.1), (1.5, -0.1), (1.5001, 0.1), (100, 0.1)))  # out, back, out
    s += funct(7, ((0, 1), (100, 1)))
    s += "/GRNOD/NODE/1\nclamped\n" + I(1) + "\n/GRNOD/NODE/2\nmiddle\n" + I(2, 3, 4) + "\n"
    s += "/GRNOD/NODE/3\ntip\n" + I(5) + "\n/BCS/1\nclamped\n   111 111" + I(0, 1) + "\n"
    drives = (("X", 6, 1.0), ("Z", 7, 0.05)) if oblique else (("X", 6, 1.0), ("Y", 7, 0.05), ("Z", 7, -0.03))
    for k, (d, f, scale) in enumerate(drives):
        s += "/IMPVEL/%d\ndrive %s\n" % (k + 1, d) + I(f) + "%10s" % d + I(0, 0, 3) + "\n" + R(1, scale, 0, 0) + "\n"
    s += "/INIVEL/TRA/1\nz\n" + R(0.0, 0.0, 1.0) + I(2) + "\n/INIVEL/ROT/2\nxx\n" + R(2.0, 0.0, 0.0) + I(2) + "\n"
    s += "/TH/SPRING/1\nsprings\nDEF       \n" + "".join(I(i + 1) + "\n" for i in range(4)) + "/END\n"
    os.makedirs(name, exist_ok=True)
    open(os.path.join(name, run + "_0000.rad"), "w").write(s)
    open(os.path.join(name, run + "_0001.rad"), "w").write(
        "/RUN/%s/1\n%g\n/TFILE\n0.01\n/PRINT/-%d\n/DT\n0.5 0\n" % (run, end, every))


def coincident(name, run, end=2.0, every=50):
    s = "/BEGIN\n%s\n      2019         0\n%20s%20s%20s\n%20s%20s%20s\n" % (run, 'kg', 'm', 's', 'kg', 'm', 's')
    s += "/NODE\n" + I(1) + R(0, 0, 0) + "\n" + I(2) + R(0, 0, 0) + "\n"
    s += "/SPRING/1\n" + I(1, 1, 2) + "\n/PART/1\nspot weld\n" + I(1, 0) + "\n" + beam_prop(False)
    s += funct(1, CURVE) + funct(3, UNLOADING) + funct(6, ((0, 0.1), (0.5, 0.1), (0.5001, -0.1), (1.5, -0.1),
                                                          (1.5001, 0.1), (100, 0.1)))
    s += funct(7, ((0, 1), (100, 1)))
    s += "/GRNOD/NODE/1\nfixed\n" + I(1) + "\n/GRNOD/NODE/3\nmoving\n" + I(2) + "\n/BCS/1\nfixed\n   111 111" + I(0, 1) + "\n"
    for k, (d, f, scale) in enumerate((("X", 6, 1.0), ("Y", 7, 0.03), ("XX", 7, 0.5), ("ZZ", 6, 2.0))):
        s += "/IMPVEL/%d\ndrive %s\n" % (k + 1, d) + I(f) + "%10s" % d + I(0, 0, 3) + "\n" + R(1, scale, 0, 0) + "\n"
    s += "/TH/SPRING/1\nweld\nDEF       \n" + I(1) + "\n/END\n"
    os.makedirs(name, exist_ok=True)
    open(os.path.join(name, run + "_0000.rad"), "w").write(s)
    open(os.path.join(name, run + "_0001.rad"), "w").write(
        "/RUN/%s/1\n%g\n/TFILE\n0.01\n/PRINT/-%d\n/DT\n0.5 0\n" % (run, end, every))


cantilever("beam_spring_cantilever", "BSPR")
coincident("beam_spring_coincident", "BSPRCOIN")
cantilever("beam_spring_oblique", "BSPROBL", oblique=True)
