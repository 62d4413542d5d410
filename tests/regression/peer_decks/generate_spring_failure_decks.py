# Generates the peer decks of the springs' failure criteria (Ifail, Ifail2; docs/theory/spring.md, SP-5b): a chain of
# three springs along x, node 1 held, the end node 4 pulled; each spring fails as a whole when its criterion is met.
# Run from the folder that is to hold the decks; each folder's ref.extract is the reference solver's last printed row
# (run-or.sh, then or-extract.py). Units kg, m, s.
#   spring_fail_combined: /PROP/TYPE13, Ifail 1, limits in tension (0.03 m) and in both shears (0.04 m); the end
#     pulled along (1, 1, 0.5): the springs go when (dx/0.03)^2 + (dy/0.04)^2 + (dz/0.04)^2 reaches 1, before any one
#     limit alone.
#   spring_fail_force_rate: /PROP/TYPE13, Ifail2 2: a force limit of 60 N in tension raised by c (|rate| / Vo)^n
#     (c 20 N, n 1, Vo 0.5 m/s), a dashpot C 10; the end pulled at 1 m/s.
#   spring_fail_energy: /PROP/TYPE8, Ifail 1, Ifail2 2: energy limits of 1.5 J in X and 2 J in Y (the work done on the
#     law, its dashpot's included), the end pulled along (1, 1, 0).
#   spring_unit_length_beam: spring_fail_combined's springs given per unit length (Ileng 1, SP-21) on a chain of
#     three lengths (0.1, 0.2 and 0.05 m): mass, inertia, stiffnesses, dashpot and limits (0.3 and 0.4 of the length)
#     follow each spring's length. In series the three strain alike; the first spring breaks at 0.78 s.
#   spring_unit_length_axial: /PROP/TYPE4 per unit length on the same chain, a curve of the strain (400 N per unit
#     strain to 0.02, then flat), a dashpot and a limit of 0.012 m that is not scaled: the longest spring, the
#     second, breaks at 0.42 s.
import os
I = lambda *v: "".join("%10d" % x for x in v)
R = lambda *v: "".join("%20.10g" % x for x in v)


def law(k=0.0, c=0.0, dmin=0.0, dmax=0.0):  # one degree of freedom: its three lines
    return R(k, c, 1, 0, 0) + "\n" + I(0, 0, 0, 0, 0) + " " * 10 + R(dmin, dmax) + "\n" + R(0, 0, 1, 0) + "\n"


def type13(laws, ifail=0, ifail2=0, vo=1.0, tails=None, ileng=0):
    s = "/PROP/TYPE13/1\nbeam springs\n" + R(0.005, 0.0002) + I(0, 0, 0, ifail, ileng, ifail2) + "\n" + "".join(laws)
    tails = tails or [(0, 0, 1, 2)] * 6
    return s + R(vo, 1, 0) + I(0) + "\n" + "".join(R(*t) + "\n" for t in tails)


def type8(laws, ifail=0, ifail2=0):
    return ("/PROP/TYPE8/1\ngeneral springs\n" + R(0.005, 0.0002) + I(0, 0, 0, ifail, ifail2, 0) + "\n" + "".join(laws)
            + I(0) + R(0) + "\n")


def type4(k=0.0, c=0.0, fct=0, dmax=0.0):
    return ("/PROP/TYPE4/1\nsprings\n" + R(0.05) + " " * 30 + I(0, 0, 1) + "\n" + R(k, c, 1, 0, 0) + "\n"
            + I(fct, 0, 0, 0, 0) + " " * 10 + R(0, dmax) + "\n" + R(0, 0, 1, 0) + "\n")


def chain(name, run, prop, drive, end, every=20, xs=(0.0, 0.1, 0.2, 0.3), extra=""):
    s = "/BEGIN\n%s\n      2019         0\n%20s%20s%20s\n%20s%20s%20s\n" % (run, 'kg', 'm', 's', 'kg', 'm', 's')
    s += "/NODE\n" + "".join(I(i + 1) + R(x, 0, 0) + "\n" for i, x in enumerate(xs))
    s += "/SPRING/1\n" + "".join(I(i + 1, i + 1, i + 2) + "\n" for i in range(3))
    s += "/PART/1\nsprings\n" + I(1, 0) + "\n" + prop + "/FUNCT/1\nconst\n" + R(0, 1) + "\n" + R(100, 1) + "\n" + extra
    s += "/GRNOD/NODE/1\nheld\n" + I(1) + "\n/BCS/1\nheld\n   111 111" + I(0, 1) + "\n"
    s += "/GRNOD/NODE/2\nmiddle\n" + I(2, 3) + "\n/BCS/2\nmiddle\n   000 111" + I(0, 2) + "\n"
    s += "/GRNOD/NODE/3\nend\n" + I(4) + "\n/BCS/3\nend\n   000 111" + I(0, 3) + "\n"
    s += "/ADMAS/0/1\nmasses\n" + R(0.002) + I(2) + "\n"
    for k, (d, v) in enumerate(drive):
        s += "/IMPVEL/%d\ndrive %s\n" % (k + 1, d) + I(1) + "%10s" % d + I(0, 0, 3) + "\n" + R(1, v, 0, 0) + "\n"
    s += "/TH/SPRING/1\nsprings\nDEF       \n" + "".join(I(i + 1) + "\n" for i in range(3)) + "/END\n"
    os.makedirs(name, exist_ok=True)
    open(os.path.join(name, run + "_0000.rad"), "w").write(s)
    open(os.path.join(name, run + "_0001.rad"), "w").write("/RUN/%s/1\n%g\n/TFILE\n%g\n/PRINT/-%d\n" % (run, end, end / 100, every))


shear = law(2000.0, 0.0, 0.0, 0.04)
chain("spring_fail_combined", "SFCOMB",
      type13([law(4000.0, 0.0, 0.0, 0.03), shear, shear, law(20.0), law(40.0), law(40.0)], ifail=1),
      (("X", 0.1), ("Y", 0.1), ("Z", 0.05)), 1.0)
chain("spring_fail_force_rate", "SFRATE",
      type13([law(4000.0, 10.0, 0.0, 60.0), law(2000.0), law(2000.0), law(20.0), law(40.0), law(40.0)], ifail2=2,
             vo=0.5, tails=[(20, 1, 1, 2)] + [(0, 0, 1, 2)] * 5),
      (("X", 1.0),), 0.2)
chain("spring_fail_energy", "SFENER",
      type8([law(4000.0, 2.0, 0.0, 1.5), law(2000.0, 0.0, 0.0, 2.0), law(2000.0), law(20.0), law(40.0), law(40.0)],
            ifail=1, ifail2=2),
      (("X", 0.1), ("Y", 0.1)), 1.5)

unit_shear = law(200.0, 0.0, 0.0, 0.4)
chain("spring_unit_length_beam", "SULBEAM",
      type13([law(400.0, 0.5, 0.0, 0.3), unit_shear, unit_shear, law(2.0), law(4.0), law(4.0)], ifail=1,
             ileng=1),
      (("X", 0.1), ("Y", 0.1), ("Z", 0.05)), 1.0, xs=(0.0, 0.1, 0.3, 0.35))
chain("spring_unit_length_axial", "SULAXIAL", type4(c=0.2, fct=2, dmax=0.012), (("X", 0.05),), 0.5,
      xs=(0.0, 0.1, 0.3, 0.35),
      extra="/FUNCT/2\nstrain\n" + R(-1, -8) + "\n" + R(-0.02, -8) + "\n" + R(0, 0) + "\n" + R(0.02, 8) + "\n" + R(1, 8) + "\n")
