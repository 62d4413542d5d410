# Generates the peer decks of /PROP/TYPE32 pretensioners (docs/theory/spring.md, SP-22): springs from a held node to
# a node moving along their axis. Run from the folder that is to hold the decks; each folder's ref.extract is the
# reference solver's last printed row on its deck (run-or.sh, then or-extract.py). Units kg, m, s.
#   spring_pretension_locks: two springs, Ilock 2 and 0 (F1 100 N, D1 0.1 m), their end nodes driven alike: pulled
#     out (K0 alone before the sensor at 0.01 s), let in (the pretension floor), out past the floor (the Ilock 2
#     spring locks), in and out again; a third spring without a sensor, given E1 and K1, pulls from the start.
#   spring_pretension_cycles: a pretensioner given F1 and E1 on a free 1 kg node, the sensor at 0.005 s: the floor
#     pulls the node in over its stroke, then the node rings on K0; beside it one given D1 and K1, Ilock 2.
#   spring_pretension_functions: the locks deck's drive on three pretensioners in function mode (SP-22b, SP-22c): the
#     pretension of the elongation fct_ID1 with a stroke D1 and Scale_d 2; of the time fct_ID2 with Scale_t 2; both,
#     with Scale_f 2 and Ilock 2 (F1 and E1 given, which function mode ignores).
import os
I = lambda *v: "".join("%10d" % x for x in v)
R = lambda *v: "".join("%20.10g" % x for x in v)


def pretensioner(pid, sensor, ilock, k0, f1=0.0, d1=0.0, e1=0.0, k1=0.0, functions=(0, 0), scales=(0, 0, 0)):
    return ("/PROP/SPR_PRE/%d\npretensioner %d\n" % (pid, pid) + R(0.001) + " " * 30 + I(sensor, ilock) + "\n"
            + R(k0, f1, d1, e1, k1) + "\n" + I(*functions) + " " * 20 + R(*scales) + "\n")


def deck(name, run, props, drive, end, mass=0.0, every=20, functions=""):
    s = "/BEGIN\n%s\n      2019         0\n%20s%20s%20s\n%20s%20s%20s\n" % (run, 'kg', 'm', 's', 'kg', 'm', 's')
    n = len(props)
    s += "/NODE\n" + "".join(I(10 * k + 1) + R(0, k, 0) + "\n" + I(10 * k + 2) + R(1, k, 0) + "\n" for k in range(n))
    for k, prop in enumerate(props):
        s += "/SPRING/%d\n" % (k + 1) + I(k + 1, 10 * k + 1, 10 * k + 2) + "\n"
        s += "/PART/%d\npretensioner %d\n" % (k + 1, k + 1) + I(k + 1, 0) + "\n" + prop
    s += "/SENSOR/TIME/1\nsensor\n" + R(drive[0]) + "\n"
    s += "/GRNOD/NODE/1\nheld\n" + I(*[10 * k + 1 for k in range(n)]) + "\n"
    s += "/GRNOD/NODE/2\nmoving\n" + I(*[10 * k + 2 for k in range(n)]) + "\n"
    s += "/BCS/1\nheld\n   111 111" + I(0, 1) + "\n/BCS/2\nalong x\n   011 111" + I(0, 2) + "\n"
    if mass > 0.0:
        s += "/ADMAS/0/1\nmass\n" + R(mass) + I(2) + "\n"
    if drive[1]:
        s += "/FUNCT/90\ndrive\n" + "".join(R(t, v) + "\n" for t, v in drive[1])
        s += "/IMPVEL/1\ndrive\n" + I(90) + "%10s" % "X" + I(0, 0, 2) + "\n" + R(1, 1, 0, 0) + "\n"
    s += functions
    s += "/TH/SPRING/1\nsprings\nDEF\n" + "".join(I(k + 1) + "\n" for k in range(n)) + "/END\n"
    os.makedirs(name, exist_ok=True)
    open(os.path.join(name, run + "_0000.rad"), "w").write(s)
    open(os.path.join(name, run + "_0001.rad"), "w").write("/RUN/%s/1\n%g\n/TFILE\n%g\n/PRINT/-%d\n" % (run, end, end / 100, every))


cycles = ((0, 0.2), (0.01, 0.2), (0.010001, -1), (0.06, -1), (0.060001, 1), (0.08, 1), (0.080001, -1), (0.09, -1),
          (0.090001, 1), (0.1, 1), (0.100001, -1), (0.2, -1), (0.200001, 1), (2, 1))
deck("spring_pretension_locks", "SPRELOCK",
     [pretensioner(1, 1, 2, 1e5, f1=100, d1=0.1), pretensioner(2, 1, 0, 1e5, f1=100, d1=0.1),
      pretensioner(3, 0, 0, 1e5, e1=5, k1=1000)], (0.01, cycles), 0.25)
deck("spring_pretension_cycles", "SPRECYC",
     [pretensioner(1, 1, 0, 1e5, f1=1000, e1=50), pretensioner(2, 1, 2, 1e5, d1=0.05, k1=2000)], (0.005, None), 0.3, mass=1.0, every=1)
deck("spring_pretension_functions", "SPREFCT",
     [pretensioner(1, 1, 0, 1e5, d1=0.12, functions=(71, 0), scales=(0, 2, 0)),
      pretensioner(2, 1, 0, 1e5, functions=(0, 72), scales=(2, 0, 0)),
      pretensioner(3, 1, 2, 1e5, f1=50, e1=3, functions=(71, 72), scales=(0, 0, 2))], (0.01, cycles), 0.25,
     functions="/FUNCT/71\nof the elongation\n" + R(-0.2, 0) + "\n" + R(-0.05, 60) + "\n" + R(0, 100) + "\n" + R(0.2, 300) + "\n"
     + "/FUNCT/72\nof the time\n" + R(0, 20) + "\n" + R(0.02, 100) + "\n" + R(0.2, 40) + "\n")
