# Generates the peer decks of trusses (/TRUSS with /PROP/TYPE2, docs/theory/truss.md). Run from the folder that is
# to hold the decks; each folder's ref.extract is the reference solver's last printed row on its deck (run-or.sh,
# then or-extract.py). Units kg, m, s; steel E = 2.1e11, rho = 7800. The figures Crumple gives against them are in
# docs/validation.md.
#   truss_bar_poisson: a bar of four trusses along x, one end held, the other pulled at 20 m/s by /IMPVEL; LAW2
#     (a = 2e8, b = 5e8, n = 0.5) with nu = 0.3, so that the area shrinks (TR-3) and the bar hardens (TR-2b).
#   truss_bar_fails: the same with n = 1, nu = 0 and EPS_max = 0.05: the truss that reaches it lets go over eleven
#     cycles (TR-7).
#   truss_bar_rate: the same with the strain-rate term c = 0.05, which the reference's trusses ignore (TR-2c).
#   truss_gap: a bar of four trusses with Gap_ini = 0.01 m, its end mass of 50 kg launched at -2 m/s towards the held
#     end, beside a truss without gap that bounds the step (a truss with a gap bounds none, TR-6).
#   truss_tower, truss_tower_fails: a space truss of three 0.3 m cubes with face diagonals (76 trusses, A = 2e-5),
#     its base held, a 2 kg mass on each top node pulled sideways and down by a ramped load; LAW2 (a = 2.5e8,
#     b = 6e8, n = 0.4, nu = 0.3); in the second the load is 1.5 times higher and EPS_max = 0.01 (members break).
import os
I = lambda *v: "".join("%10d" % x for x in v)
R = lambda *v: "".join("%20.10g" % x for x in v)


def header(run):
    return "/BEGIN\n%s\n      2019         0\n%20s%20s%20s\n%20s%20s%20s\n" % (run, 'kg', 'm', 's', 'kg', 'm', 's')


def law2(a, b, n, nu, epsmax=0.0, c=0.0, sigmax=0.0):
    return ("/MAT/LAW2/1\nsteel\n" + R(7800) + "\n" + R(2.1e11, nu) + "\n" + R(a, b, n, epsmax, sigmax) + "\n" +
            R(c, 1.0) + I(0, 0) + R(0, 0) + "\n")


def write(name, run, s, end, every):
    os.makedirs(name, exist_ok=True)
    open(os.path.join(name, run + "_0000.rad"), "w").write(s + "/END\n")
    open(os.path.join(name, run + "_0001.rad"), "w").write("/RUN/%s/1\n%g\n/TFILE\n%g\n/PRINT/-%d\n" % (run, end, end / 100, every))


def bar(name, run, material, end, v, pulled=True, gap=0.0, end_mass=50.0):
    n = 4
    s = header(run) + "/NODE\n" + "".join(I(i + 1) + R(0.25 * i, 0.0, 0.0) + "\n" for i in range(n + 1))
    s += "/TRUSS/1\n" + "".join(I(i + 1, i + 1, i + 2) + "\n" for i in range(n))
    s += "/PART/1\nbar\n" + I(1, 1) + "\n/PROP/TRUSS/1\nbar\n" + R(1e-4, gap) + "\n" + material
    held = [1]
    if gap > 0.0:  # a truss without gap beside the bar, which bounds the step
        s += "/NODE\n" + I(101) + R(0, 1, 0) + "\n" + I(102) + R(0.25, 1, 0) + "\n/TRUSS/2\n" + I(101, 101, 102) + "\n"
        s += "/PART/2\nclock\n" + I(2, 1) + "\n/PROP/TRUSS/2\nclock\n" + R(1e-4, 0) + "\n"
        held = [1, 101, 102]
    s += "/GRNOD/NODE/1\nheld\n" + I(*held) + "\n/GRNOD/NODE/3\nend\n" + I(n + 1) + "\n"
    s += "/BCS/1\nheld\n   111 000" + I(0, 1) + "\n"
    s += "/BCS/2\nline\n   011 000" + I(0, 4) + "\n/GRNOD/NODE/4\nfree\n" + I(*range(2, n + 2)) + "\n"
    s += "/ADMAS/0/1\nend mass\n" + R(end_mass) + I(3) + "\n"
    if pulled:
        s += "/FUNCT/1\nconst\n" + R(0, 1) + "\n" + R(1e3, 1) + "\n/IMPVEL/1\npull\n" + I(1) + "         X" + I(0, 0, 3, 0, 0) + "\n"
        s += R(1.0, v, 0, 1e30) + "\n"
    else:
        s += "/INIVEL/TRA/1\nv\n" + R(v, 0.0, 0.0) + I(3) + "\n"
    s += "/TH/TRUSS/1\nbar\nDEF       A         L\n" + "".join(I(i + 1) + "\n" for i in range(n))
    write(name, run, s, end, 20)


def tower(name, run, load, epsmax):
    nodes, idx = [], {}
    for k in range(4):
        for (i, j) in [(0, 0), (1, 0), (1, 1), (0, 1)]:
            idx[(i, j, k)] = len(nodes) + 1
            nodes.append((0.3 * i, 0.3 * j, 0.3 * k))
    sides = [((0, 0), (1, 0)), ((1, 0), (1, 1)), ((1, 1), (0, 1)), ((0, 1), (0, 0))]
    el = []
    for k in range(4):
        for a, b in sides + [((0, 0), (1, 1))]:
            el.append((idx[a + (k,)], idx[b + (k,)]))
    for k in range(3):
        for c in [(0, 0), (1, 0), (1, 1), (0, 1)]:
            el.append((idx[c + (k,)], idx[c + (k + 1,)]))
        for a, b in sides:
            el.append((idx[a + (k,)], idx[b + (k + 1,)]))
    s = header(run) + "/NODE\n" + "".join(I(i + 1) + R(*p) + "\n" for i, p in enumerate(nodes))
    s += "/TRUSS/1\n" + "".join(I(e + 1, a, b) + "\n" for e, (a, b) in enumerate(el))
    s += "/PART/1\nbars\n" + I(1, 1) + "\n/PROP/TRUSS/1\nbars\n" + R(2e-5, 0) + "\n" + law2(2.5e8, 6e8, 0.4, 0.3, epsmax)
    s += "/GRNOD/NODE/1\nbase\n" + I(1, 2, 3, 4) + "\n/BCS/1\nbase\n   111 000" + I(0, 1) + "\n"
    s += "/GRNOD/NODE/2\ntop\n" + I(13, 14, 15, 16) + "\n/ADMAS/0/1\ntop mass\n" + R(2.0) + I(2) + "\n"
    s += "/FUNCT/1\nramp\n" + R(0, 0) + "\n" + R(0.002, 1) + "\n" + R(1, 1) + "\n"
    for d, f in [("X", 12000.0), ("Y", 5000.0), ("Z", -8000.0)]:
        s += "/CLOAD/%d\nload\n" % ord(d) + I(1) + "         " + d + I(0, 0, 2) + " " * 10 + R(1.0, f * load) + "\n"
    s += "/TH/TRUSS/1\nbars\nDEF       \n" + "".join(I(e + 1) + "\n" for e in range(len(el)))
    write(name, run, s, 0.01, 10)


bar("truss_bar_poisson", "TRPOIS", law2(2e8, 5e8, 0.5, 0.3), 0.01, 20.0)
bar("truss_bar_fails", "TRFAIL", law2(2e8, 5e8, 1.0, 0.0, epsmax=0.05), 0.01, 20.0)
bar("truss_bar_rate", "TRRATE", law2(2e8, 5e8, 1.0, 0.0, c=0.05), 0.01, 20.0)
bar("truss_gap", "TRGAP", "/MAT/LAW1/1\nsteel\n" + R(7800) + "\n" + R(2.1e11, 0.0) + "\n", 0.02, -2.0, pulled=False,
    gap=0.01)
tower("truss_tower", "TOWER", 0.4, 0.0)
tower("truss_tower_fails", "TOWERF", 0.6, 0.01)
