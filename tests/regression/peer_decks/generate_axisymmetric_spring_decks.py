# Generates the peer decks of /PROP/TYPE25 axisymmetric springs (docs/theory/spring.md, SP-20). Run from the folder
# that is to hold the decks; each folder's ref.extract is the reference solver's last printed row on its deck
# (run-or.sh, then or-extract.py). Units kg, m, s. Each deck is one spring of 1 m along x, node 1 held.
#   spring_axi_swinging_mass: a 2 kg mass on node 2, free in y and z, launched at (0, 0.3, 0.4) m/s: the radial shear
#     law (20 N at 0.01 m, then 500 N/m; nonlinear elastic) with a dashpot C = 5 on the radial rate only swings
#     it out and back along its launch direction (one law of the magnitude, whatever the direction).
#   spring_axi_bending_breaks: node 2 turned about y and z at 1.2 and 1.6 rad/s: the radial bending law (5 N m at 0.1
#     rad, then 9.6 N m/rad) breaks the spring when the magnitude of the rotation reaches delta_max = 0.25 rad
#     (about 0.125 s), not when a component does (0.16 s).
#   spring_axi_circling: node 2 taken round a circle of 0.01 m about the axis at 0.2 m/s, the shear a nonlinear
#     elastic law with C = 20: the dashpot acts on the radial rate only, so on the circle it does nothing
#     (measured: the reference's tangential force is 0 there).
#   spring_axi_unit_length: a spring of 0.5 m given per unit length (Ileng 1, SP-21), pulled at 0.03 m/s and sheared
#     at 0.1 m/s for 0.06 s: its stiffnesses K / L0, its shear curve of the strain, and its tension limit delta_max =
#     0.002 m a length (read as a strain, 0.001 m, it would break the spring near 0.033 s; the reference's holds).
#   spring_axi_fail_rate, spring_axi_fail_moment, spring_axi_fail_energy: spring_axi_bending_breaks with Ifail2 1, 2
#     and 3 (SP-5b): the bending's limit 0.25 rad, 6 N m or 0.8 J raised by c |rate| / Wo, the rate the magnitude's
#     (2 rad/s): it breaks at 0.35 rad (0.175 s), 7 N m (0.154 s) or 1 J (0.116 s).
#   spring_axi_fail_shear_rate: node 2 driven across at (0.06, 0.08) m/s, the shear's limit 0.01 m raised by
#     0.004 (0.1 / 0.05): it breaks at 0.018 m (0.18 s).
import math
import os
I = lambda *v: "".join("%10d" % x for x in v)
R = lambda *v: "".join("%20.10g" % x for x in v)
CURVE = [(-1, -515), (-0.01, -20), (0, 0), (0.01, 20), (1, 515)]   # N against m
MOMENT = [(-10, -100), (-0.1, -5), (0, 0), (0.1, 5), (10, 100)]    # N m against rad


def law(k, c=0.0, fct=0, h=0, dmax=0.0):  # one law's three lines in TYPE25's layout
    return R(k, c, 1, 0, 0) + "\n" + I(fct, h, 0, 0) + R(0, 0, dmax) + "\n" + R(1, 0) + I(0) + R(0) + "\n"


def axi(tension, shear, torsion, bending, ileng=0, ifail2=0, rates=(0, 0), failure=()):
    """The property; `failure`: its four lines c, n, alpha, beta (tension, shear, torsion, bending), after Vo, Wo."""
    s = ("/PROP/TYPE25/1\naxisymmetric spring\n" + R(0.01, 0.001) + I(0, 0, 0, 0, ileng, ifail2) + "\n" + tension +
         shear + torsion + bending + R(*rates) + "\n")
    return s + "".join(R(*line) + "\n" for line in failure)


def functions(extra=()):
    s = ""
    for fid, pts in [(1, CURVE), (4, MOMENT), (99, [(0, 1), (100, 1)])] + list(extra):
        s += "/FUNCT/%d\nf%d\n" % (fid, fid) + "".join(R(x, y) + "\n" for x, y in pts)
    return s


def deck(name, run, prop, free, end, extra="", funcs=(), length=1.0):
    s = "/BEGIN\n%s\n      2019         0\n%20s%20s%20s\n%20s%20s%20s\n" % (run, 'kg', 'm', 's', 'kg', 'm', 's')
    s += "/NODE\n" + I(1) + R(0, 0, 0) + "\n" + I(2) + R(length, 0, 0) + "\n/SPRING/1\n" + I(1, 1, 2) + "\n"
    s += "/PART/1\nspring\n" + I(1, 0) + "\n" + prop + functions(funcs)
    s += "/GRNOD/NODE/1\nheld\n" + I(1) + "\n/BCS/1\nheld\n   111 111" + I(0, 1) + "\n"
    s += "/GRNOD/NODE/2\nend\n" + I(2) + "\n/BCS/2\nend\n   " + free + I(0, 2) + "\n" + extra
    s += "/TH/SPRING/1\nspring\nDEF       \n" + I(1) + "\n/END\n"
    os.makedirs(name, exist_ok=True)
    open(os.path.join(name, run + "_0000.rad"), "w").write(s)
    open(os.path.join(name, run + "_0001.rad"), "w").write("/RUN/%s/1\n%g\n/TFILE\n%g\n/PRINT/-20\n" % (run, end, end / 100))


def impvel(k, dirn, fid, scale):
    return "/IMPVEL/%d\ndrive\n" % k + I(fid) + "%10s" % dirn + I(0, 0, 2, 0, 0) + "\n" + R(1.0, scale, 0, 1e30) + "\n"


if __name__ == "__main__":
    deck("spring_axi_swinging_mass", "AXISWING", axi(law(1e4), law(2000, 5.0, 1), law(30), law(40)), "100 111", 0.4,
         "/ADMAS/0/1\nmass\n" + R(2.0) + I(2) + "\n/INIVEL/TRA/1\nlaunch\n" + R(0, 0.3, 0.4) + I(2) + "\n")
    deck("spring_axi_bending_breaks", "AXIBEND", axi(law(1e4), law(2000), law(30), law(50, 0, 4, 0, 0.25)), "111 100",
         0.2, impvel(1, "YY", 99, 1.2) + impvel(2, "ZZ", 99, 1.6))
    om, t0 = 20.0, 0.05
    fy = [(0, 1.0), (t0, 1.0)] + [(t0 + 1e-4 + k * 0.0025, -math.sin(om * k * 0.0025)) for k in range(400)]
    fz = [(0, 0.0), (t0, 0.0)] + [(t0 + 1e-4 + k * 0.0025, math.cos(om * k * 0.0025)) for k in range(400)]
    deck("spring_axi_circling", "AXICIRC", axi(law(1e4), law(2000, 20.0, 1), law(30), law(40)), "100 111", 0.4,
         impvel(1, "Y", 11, 0.2) + impvel(2, "Z", 12, 0.2), [(11, fy), (12, fz)])
    deck("spring_axi_unit_length", "AXILENG", axi(law(1e4, 0, 0, 0, 0.002), law(2000, 0, 1), law(30), law(40), ileng=1),
         "000 111", 0.06, impvel(1, "X", 99, 0.03) + impvel(2, "Y", 99, 0.1), length=0.5)
    # SP-5b on the radial laws (Ifail2 >= 1): the bending limit raised by c (|rate| / Wo)^n, the rate the magnitude's
    # (2 rad/s), read as a rotation, a moment or an energy; the shear's by its radial rate (0.1 m/s) over Vo.
    none = (0, 0, 0, 0)
    turned = impvel(1, "YY", 99, 1.2) + impvel(2, "ZZ", 99, 1.6)
    for name, ifail2, limit, c in (("spring_axi_fail_rate", 1, 0.25, 0.05), ("spring_axi_fail_moment", 2, 6.0, 0.5),
                                   ("spring_axi_fail_energy", 3, 0.8, 0.1)):
        deck(name, "AXIF%d" % ifail2, axi(law(1e4), law(2000), law(30), law(50, 0, 4, 0, limit), ifail2=ifail2,
                                          rates=(0, 1.0), failure=(none, none, none, (c, 1, 0, 0))), "111 100", 0.25,
             turned)
    deck("spring_axi_fail_shear_rate", "AXIFS", axi(law(1e4), law(2000, 0, 1, 0, 0.01), law(30), law(40), ifail2=1,
                                                     rates=(0.05, 0), failure=(none, (0.004, 1, 0, 0), none, none)),
         "100 111", 0.25, impvel(1, "Y", 99, 0.06) + impvel(2, "Z", 99, 0.08))
