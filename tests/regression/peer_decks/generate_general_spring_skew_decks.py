# Generates the peer decks of /PROP/TYPE8 general springs in a skew's axes (docs/theory/spring.md, SP-9b): one
# spring from node 1 (clamped) to node 2 at (0.5, 0, 0), its six laws of different stiffnesses, node 2 driven along
# and about all three axes. Run from the folder that is to hold the decks; each folder's ref.extract is the
# reference solver's last printed row on its deck (run-or.sh, then or-extract.py).
#   general_spring_fixed_skew: the laws in a /SKEW/FIX turned 30 degrees about z.
#   general_spring_moving_skew: the laws in a /SKEW/MOV on nodes 1, 3 and 4, node 3 driven across so that the skew
#     turns about z as the spring moves: the offset is taken in the skew's current axes against the rest offset in
#     its axes at rest, the rotations' increments in the axes of each step.
import math, os
I = lambda *v: "".join("%10d" % x for x in v)
R = lambda *v: "".join("%20.10g" % x for x in v)


def law(k, c=0.0):
    return R(k, c, 1, 0, 0) + "\n" + I(0, 0, 0, 0, 0) + " " * 10 + R(0, 0) + "\n" + R(0, 0, 1, 0) + "\n"


def deck(name, run, skew_card):
    s = "/BEGIN\n%s\n      2019         0\n%20s%20s%20s\n%20s%20s%20s\n" % (run, 'kg', 'm', 's', 'kg', 'm', 's')
    s += "/NODE\n" + I(1) + R(0, 0, 0) + "\n" + I(2) + R(0.5, 0, 0) + "\n" + I(3) + R(1, 0, 0) + "\n"
    s += I(4) + R(0, 1, 0) + "\n"
    s += "/SPRING/1\n" + I(1, 1, 2) + "\n/PART/1\nspring\n" + I(1, 0) + "\n"
    s += "/PROP/TYPE8/1\ngeneral spring\n" + R(1e-3, 1e-3) + I(5, 0, 0, 0, 0, 0) + "\n"
    for k, c in ((1000, 0.5), (3000, 0), (5000, 0), (100, 0), (200, 0.01), (300, 0)):
        s += law(k, c)
    s += I(0) + R(0) + "\n" + skew_card
    s += "/FUNCT/9\nv\n" + R(0, 1) + "\n" + R(0.05, 1) + "\n" + R(0.0501, -1) + "\n" + R(100, -1) + "\n"
    s += "/GRNOD/NODE/1\nfixed\n" + I(1, 4) + "\n/GRNOD/NODE/2\nmoving\n" + I(2) + "\n/GRNOD/NODE/3\nskew\n" + I(3) + "\n"
    s += "/BCS/1\nfixed\n   111 111" + I(0, 1) + "\n/BCS/2\nskew\n   101 111" + I(0, 3) + "\n"
    s += "/ADMAS/0/1\nskew nodes\n" + R(1e-3) + I(3) + "\n/ADMAS/0/2\nfixed\n" + R(1e-3) + I(1) + "\n"
    drives = (("X", 1.0), ("Y", 0.5), ("Z", 0.2), ("XX", 0.3), ("YY", 0.7), ("ZZ", 1.0))
    for k, (d, scale) in enumerate(drives):
        s += "/IMPVEL/%d\ndrive %s\n" % (k + 1, d) + I(9) + "%10s" % d + I(0, 0, 2) + "\n" + R(1, scale, 0, 0) + "\n"
    s += "/IMPVEL/7\nskew turns\n" + I(9) + "%10s" % "Y" + I(0, 0, 3) + "\n" + R(1, 3.0, 0, 0) + "\n"
    s += "/TH/SPRING/1\nspring\nDEF       \n" + I(1) + "\n/END\n"
    os.makedirs(name, exist_ok=True)
    open(os.path.join(name, run + "_0000.rad"), "w").write(s)
    open(os.path.join(name, run + "_0001.rad"), "w").write(
        "/RUN/%s/1\n0.07\n/TFILE\n0.001\n/PRINT/-50\n/DT\n0.9 0\n" % run)


a = math.radians(30)
deck("general_spring_fixed_skew", "GSKEWF",
     "/SKEW/FIX/5\nturned 30 degrees about z\n" + R(0, 0, 0) + "\n" + R(-math.sin(a), math.cos(a), 0) + "\n" + R(0, 0, 1) + "\n")
deck("general_spring_moving_skew", "GSKEWM", "/SKEW/MOV/5\non nodes 1, 3, 4\n" + I(1, 3, 4) + "\n")
