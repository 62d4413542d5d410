# Generates the peer decks of /PROP/TYPE8 general springs (docs/theory/spring.md, SP-9 to SP-11): a chain of four
# springs along x, node 1 fixed, node 5 driven by /IMPVEL, every degree of freedom with its own law. Run from the
# folder that is to hold the decks; each folder's ref.extract is the reference solver's last printed row on its deck
# (run-or.sh, then or-extract.py). The figures Crumple gives against them are in docs/validation.md.
#   general_spring_chain: X hardening 5 (residual elongation 0.5 delta_max), Y hardening 1, Z linear with a dashpot
#     and the middle nodes released at 1 m/s in z, XX hardening 2 on a moment curve, YY linear with a dashpot and
#     the middle nodes spun at 2 rad/s, ZZ a nonlinear elastic moment curve; node 5 driven out and back in x and
#     in y, and turned about x and z.
#   general_spring_breaks: the same chain pulled in y until a spring's Y elongation passes delta_max = 0.03 m: the
#     whole spring goes (uni-directional failure, Ifail 0).
#   springs_mixed_damped: the chain of general springs beside a chain of /PROP/TYPE4 springs and one of /PROP/TYPE13
#     beam-type springs that share its nodes, under /DAMP (alpha and beta): the MPI deck of every spring kind
#     beside soft elasto-plastic trusses (/PROP/TYPE2, LAW2, nu = 0.3) between every other node: the MPI deck of
#     every spring kind and the trusses (tests/mpi). Its step is its nodes' (SP-19), 19 % longer than its shortest
#     spring's.
import os
I = lambda *v: "".join("%10d" % x for x in v)
R = lambda *v: "".join("%20.10g" % x for x in v)
CURVE = ((-1, -515), (-0.01, -20), (0, 0), (0.01, 20), (1, 515))  # 20 N at 0.01 m, then 500 N/m
MOMENT = ((-10, -100), (-0.1, -5), (0, 0), (0.1, 5), (10, 100))    # 5 N m at 0.1 rad, then 9.6 N m/rad
STIFFENING = ((-2, -40), (-1, -10), (0, 0), (1, 10), (2, 40))       # a stiffening moment curve [N m, rad]


def funct(fid, pts):
    return "/FUNCT/%d\nf%d\n" % (fid, fid) + "".join(R(x, y) + "\n" for x, y in pts)


def law(k=0.0, c=0.0, fct=0, h=0, fct3=0, dmax=0.0):  # one degree of freedom: its three lines
    return R(k, c, 1, 0, 0) + "\n" + I(fct, h, 0, fct3, 0) + " " * 10 + R(0, dmax) + "\n" + R(0, 0, 1, 0) + "\n"


def general_prop(pid, dmax_y=0.0):
    return ("/PROP/TYPE8/%d\ngeneral\n" % pid + R(0.5, 0.01) + I(0, 0, 0, 0, 0, 0) + "\n"
            + law(2000, 0, 1, 5, 3)                 # X: H 5, residual g(delta_max) = 0.5 delta_max
            + law(2000, 0, 1, 1, 0, dmax_y)         # Y: H 1 on the same curve
            + law(1000, 2.0)                        # Z: linear, a dashpot
            + law(100, 0, 4, 2)                     # XX: H 2 on a moment curve
            + law(50, 0.05)                         # YY: linear, a dashpot
            + law(20, 0, 5, 0)                      # ZZ: a nonlinear elastic moment curve
            + I(0) + R(0) + "\n")


def chain(name, run, end=2.5, pull_y=0.05, dmax_y=0.0, mixed=False, every=50):
    s = "/BEGIN\n%s\n      2019         0\n%20s%20s%20s\n%20s%20s%20s\n" % (run, 'kg', 'm', 's', 'kg', 'm', 's')
    s += "/NODE\n" + "".join(I(i + 1) + R(0.1 * i, 0.0, 0.0) + "\n" for i in range(5))
    s += "/SPRING/1\n" + "".join(I(i + 1, i + 1, i + 2) + "\n" for i in range(4))
    s += "/PART/1\ngeneral springs\n" + I(1, 0) + "\n" + general_prop(1, dmax_y)
    if mixed:  # TYPE4 springs between every other node, on the same nodes
        s += "/SPRING/2\n" + "".join(I(10 + i, i + 1, i + 3) + "\n" for i in range(3))
        s += ("/PART/2\naxial springs\n" + I(2, 0) + "\n/PROP/SPRING/2\naxial\n" + R(0.2) + " " * 30 + I(0, 0, 0)
              + "\n" + R(500, 1.0, 1, 0, 0) + "\n" + I(0, 0, 0, 0, 0) + " " * 10 + R(0, 0) + "\n" + R(0, 0, 0, 0) + "\n")
        # and beam-type springs (TYPE13) along the chain, on the same nodes
        s += "/SPRING/3\n" + "".join(I(20 + i, i + 1, i + 2) + "\n" for i in range(4))
        s += ("/PART/3\nbeam springs\n" + I(3, 0) + "\n/PROP/TYPE13/3\nbeam\n" + R(0.3, 0.005) + I(0, 0, 0, 0, 0, 0)
              + "\n" + law(800, 0.5) + law(300, 0.2) + law(300, 0.2) + law(5, 0.01) + law(10, 0.01) + law(10, 0.01)
              + R(1, 1, 0) + I(0) + "\n" + "".join(R(0, 0, 1, 2) + "\n" for _ in range(6)))
        # and soft elasto-plastic trusses between every other node, beside the axial springs
        s += "/TRUSS/4\n" + "".join(I(30 + i, i + 1, i + 3) + "\n" for i in range(3))
        s += "/PART/4\ntrusses\n" + I(4, 1) + "\n/PROP/TRUSS/4\ntruss\n" + R(1e-4, 0) + "\n"
        s += ("/MAT/LAW2/1\nsoft\n" + R(5000) + "\n" + R(1e6, 0.3) + "\n" + R(2e4, 1e5, 1, 0, 0) + "\n" + R(0, 0)
              + I(0, 0) + R(0, 0) + "\n")
    s += funct(1, CURVE) + funct(3, ((-1, -0.5), (0, 0), (1, 0.5))) + funct(4, MOMENT) + funct(5, STIFFENING)
    s += funct(6, ((0, 0.1), (0.5, 0.1), (0.5001, -0.1), (1.5, -0.1), (1.5001, 0.1), (100, 0.1)))  # out, back, out
    s += funct(7, ((0, 1), (100, 1)))
    s += funct(8, ((0, 0.2), (1.0, 0.2), (1.0001, -0.2), (100, -0.2)))  # a turn about x, then back
    s += "/GRNOD/NODE/1\nfixed\n" + I(1) + "\n/GRNOD/NODE/2\nmiddle\n" + I(2, 3, 4) + "\n"
    s += "/GRNOD/NODE/3\nend\n" + I(5) + "\n/GRNOD/NODE/4\nall\n" + I(1, 2, 3, 4, 5) + "\n"
    s += "/BCS/1\nfixed\n   111 111" + I(0, 1) + "\n"
    for k, (d, f, scale) in enumerate((("X", 6, 1.0), ("Y", 7, pull_y), ("XX", 8, 1.0), ("ZZ", 7, 0.1))):
        s += "/IMPVEL/%d\ndrive %s\n" % (k + 1, d) + I(f) + "%10s" % d + I(0, 0, 3) + "\n" + R(1, scale, 0, 0) + "\n"
    s += "/INIVEL/TRA/1\nz\n" + R(0.0, 0.0, 1.0) + I(2) + "\n"
    s += "/INIVEL/ROT/2\nyy\n" + R(0.0, 2.0, 0.0) + I(2) + "\n"
    if mixed: s += "/DAMP/1\nrayleigh\n" + R(1.0, 0.001) + I(4, 0) + R(0, 0) + "\n"
    s += "/TH/SPRING/1\nsprings\nDEF       \n" + "".join(I(i + 1) + "\n" for i in range(4)) + "/END\n"
    os.makedirs(name, exist_ok=True)
    open(os.path.join(name, run + "_0000.rad"), "w").write(s)
    open(os.path.join(name, run + "_0001.rad"), "w").write(
        "/RUN/%s/1\n%g\n/TFILE\n0.01\n/PRINT/-%d\n/DT\n0.5 0\n" % (run, end, every))


chain("general_spring_chain", "GSPR")
chain("general_spring_breaks", "GSPRBRK", end=1.0, pull_y=0.1, dmax_y=0.03, every=25)
chain("springs_mixed_damped", "SPRMIX", mixed=True)
