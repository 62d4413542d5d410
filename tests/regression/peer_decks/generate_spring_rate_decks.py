# Generates the peer decks of the springs' rate effects (docs/theory/spring.md, SP-23): the force curve scaled by
# R / A, R = A + B ln(max(1, |r| / D)) + E g(r / F), and the rate force Hscale h(r / F) added. Run from the folder
# that is to hold the decks; each folder's ref.extract is the reference solver's last printed row on its deck
# (run-or.sh, then or-extract.py).
#   spring_rate_hardening: one /PROP/TYPE4 spring, isotropic hardening (H 1) on A f with A 2, every rate term
#     (B, D, g with E and F, h with Hscale, C), node 2 driven out at 0.1 m/s, back at 0.05 m/s past 0, out again.
#   spring_rate_beam: one /PROP/TYPE13 spring, node 2 driven out and back in x, across in y (reversed at 1 s) and
#     turned about y: tension on a curve with B and g (g even in the rate), shear Y on a curve with h (whose dashpot
#     enters the rotations' step too, SP-23b), shear Z linear with h, bending Y on a curve with B. Every motion is
#     imposed: a rate-dependent elastic law gives energy back where it unloads faster than it loaded, which makes a
#     free mesh of them chaotic (tried: four springs with free middle nodes, both solvers' energies swing below 0).
import os
I = lambda *v: "".join("%10d" % x for x in v)
R = lambda *v: "".join("%20.10g" % x for x in v)
CURVE = ((-1, -515), (-0.01, -20), (0, 0), (0.01, 20), (1, 515))  # 20 N at 0.01 m, then 500 N/m
RATE = ((-100, -5), (-10, -4), (-1, -3), (-0.1, -2), (-0.01, -1), (0, 0), (0.01, 1), (0.1, 2), (1, 3), (10, 4),
        (100, 5))  # odd and log-like: its steepest slope 100, between 0 and 0.01
RATE_EVEN = tuple((x, abs(y)) for x, y in RATE)  # the same of |r|: a factor that never turns the law active
MOMENT = ((-10, -100), (-0.1, -5), (0, 0), (0.1, 5), (10, 100))
OUT_BACK_OUT = ((0, 0.1), (0.5, 0.1), (0.5001, -0.05), (2.5, -0.05), (2.5001, 0.1), (100, 0.1))


def funct(fid, pts):
    return "/FUNCT/%d\nf%d\n" % (fid, fid) + "".join(R(x, y) + "\n" for x, y in pts)


def law(k=0.0, c=0.0, a=1.0, b=0.0, d=0.0, fct=0, h=0, g=0, hf=0, f=0.0, e=0.0, hscale=0.0):  # K C A B D / ...
    return (R(k, c, a, b, d) + "\n" + I(fct, h, g, 0, hf) + " " * 10 + R(0, 0) + "\n" + R(f, e, 1, hscale) + "\n")


def begin(run):
    return "/BEGIN\n%s\n      2019         0\n%20s%20s%20s\n%20s%20s%20s\n" % (run, 'kg', 'm', 's', 'kg', 'm', 's')


def write(name, run, starter, end, every, dt=0.5):
    os.makedirs(name, exist_ok=True)
    open(os.path.join(name, run + "_0000.rad"), "w").write(starter)
    open(os.path.join(name, run + "_0001.rad"), "w").write(
        "/RUN/%s/1\n%g\n/TFILE\n0.01\n/PRINT/-%d\n/DT\n%g 0\n" % (run, end, every, dt))


def hardening(name, run):
    s = begin(run) + "/NODE\n" + I(1) + R(0, 0, 0) + "\n" + I(2) + R(0, 1, 0) + "\n"
    s += "/BCS/1\nfix\n   111 111" + I(0, 1) + "\n/GRNOD/NODE/1\nfix\n" + I(1) + "\n"
    s += "/BCS/2\nfree\n   101 111" + I(0, 2) + "\n/GRNOD/NODE/2\nfree\n" + I(2) + "\n"
    s += "/PART/1\nspring\n" + I(4, 0, 0) + "\n/SPRING/1\n" + I(1, 1, 2) + "\n"
    s += "/PROP/SPRING/4\nspr\n" + R(2.0) + " " * 30 + I(0, 0, 0) + "\n"
    s += law(5000, 5, 2, 0.5, 0.01, fct=1, h=1, g=2, hf=2, f=0.5, e=0.3, hscale=2)
    s += funct(1, CURVE) + funct(2, RATE) + funct(9, OUT_BACK_OUT)
    s += "/IMPVEL/1\nv\n" + I(9) + "         Y" + I(0, 0, 2) + "\n" + R(1, 1, 0, 0) + "\n"
    s += "/TH/SPRING/1\nspr\nDEF       \n" + I(1) + "\n/END\n"
    write(name, run, s, 3.0, 100, dt=0.9)


def beam(name, run):
    laws = [law(2000, 0, 1, 0.3, 0.02, fct=1, g=3, f=2, e=0.2),      # tension: B and g
            law(2000, 0.5, 1, fct=1, hf=2, f=5, hscale=0.5),         # shear Y: h (SP-23b)
            law(500, 0.5, hf=2, f=5, hscale=0.2),                     # shear Z: linear with h
            law(20, 0.01),                                             # torsion
            law(40, 0.0, 1, 0.2, 0.05, fct=4),                         # bending Y: B
            law(40, 0.02)]                                             # bending Z
    prop = "/PROP/TYPE13/1\nbeam spring\n" + R(0.5, 0.02) + I(0, 0, 0, 0, 0, 0) + "\n" + "".join(laws)
    prop += R(1, 1, 0) + I(0) + "\n" + "".join(R(0, 0, 1, 2) + "\n" for _ in range(6))
    s = begin(run) + "/NODE\n" + I(1) + R(0, 0, 0) + "\n" + I(2) + R(0.2, 0, 0) + "\n"
    s += "/SPRING/1\n" + I(1, 1, 2) + "\n/PART/1\nbeam spring\n" + I(1, 0) + "\n" + prop
    s += funct(1, CURVE) + funct(2, RATE) + funct(3, RATE_EVEN) + funct(4, MOMENT)
    s += funct(6, OUT_BACK_OUT) + funct(7, ((0, 1), (1, 1), (1.0001, -1), (100, -1)))
    s += "/GRNOD/NODE/1\nclamped\n" + I(1) + "\n/GRNOD/NODE/2\nend\n" + I(2) + "\n"
    s += "/BCS/1\nclamped\n   111 111" + I(0, 1) + "\n/BCS/2\nend\n   001 101" + I(0, 2) + "\n"
    for k, (d, f, scale) in enumerate((("X", 6, 1.0), ("Y", 7, 0.05), ("YY", 7, 0.2))):
        s += "/IMPVEL/%d\ndrive %s\n" % (k + 1, d) + I(f) + "%10s" % d + I(0, 0, 2) + "\n" + R(1, scale, 0, 0) + "\n"
    s += "/TH/SPRING/1\nspring\nDEF       \n" + I(1) + "\n/END\n"
    write(name, run, s, 2.0, 200)


hardening("spring_rate_hardening", "SPRRATE")
beam("spring_rate_beam", "SPRRATEB")
