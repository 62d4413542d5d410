# Generates the peer decks of the interface nodal step's normal dashpot and of the step's growth
# (docs/theory/time-step.md, T-4c and T-5): a free 1 mm steel plate of Ishell 1 shells over a fixed 20 x 20 mm plate
# of four shells, TYPE7 with Gapmin 0.5 and the default VisS.
#   contact_step_dashpot: one 5 mm square resting on the gap, pressed by 0.05 kN a node (its nodal step holds
#     VisS sqrt(2 Kt M) / dt beside Kt, T-4c).
#   contact_step_growth: four 5 mm membrane squares (N = 1) dropped flat at 10 mm/ms onto the plate with Stfac 10
#     (after the bounce the step climbs back by 1.1 a cycle, T-5; a membrane, so that no bending mode rings at the
#     step's limit after the impact).
# Run from the folder that is to hold the decks' folders.
import os
I = lambda *v: "".join("%10d" % x for x in v)
R = lambda *v: "".join("%20.10g" % x for x in v)


def deck(name, n_upper, z0, stfac, press, drop, points=2):
    s = "#RADIOSS STARTER\n/BEGIN\n%s\n      2019         0\n%20s%20s%20s\n%20s%20s%20s\n" % (name, 'kg', 'mm', 'ms', 'kg', 'mm', 'ms')
    s += "/MAT/ELAST/1\nsteel\n" + R(7.85e-6) + "\n" + R(210.0, 0.3) + "\n"
    s += "/PROP/SHELL/1\nsheet\n" + I(1, 0, 0, 0) + "\n" + R(0, 0, 0, 0, 0) + "\n" + I(points, 0) + R(1.0) + "\n"
    s += "/PART/1\nlower\n" + I(1, 1) + "\n/PART/2\nupper\n" + I(1, 1) + "\n"
    nodes, lower, upper = [], [], []
    for j in range(3):
        for i in range(3):
            nodes.append((len(nodes) + 1, 10.0 * i, 10.0 * j, 0.0)); lower.append(len(nodes))
    side = 5.0 * n_upper
    grid = {}
    for j in range(n_upper + 1):
        for i in range(n_upper + 1):
            nodes.append((len(nodes) + 1, 2.5 + side * i / n_upper, 2.5 + side * j / n_upper, z0))
            upper.append(len(nodes)); grid[(i, j)] = len(nodes)
    s += "/NODE\n" + "".join(I(k) + R(x, y, z) + "\n" for k, x, y, z in nodes)
    s += "/SHELL/1\n"
    for j in range(2):
        for i in range(2):
            a = 1 + i + 3 * j
            s += I(1 + i + 2 * j, a, a + 1, a + 4, a + 3) + "\n"
    s += "/SHELL/2\n"
    e = 5
    for j in range(n_upper):
        for i in range(n_upper):
            s += I(e, grid[(i, j)], grid[(i + 1, j)], grid[(i + 1, j + 1)], grid[(i, j + 1)]) + "\n"; e += 1
    s += "/GRNOD/NODE/1\nlower\n" + I(*lower) + "\n/GRNOD/NODE/2\nupper\n"
    for k in range(0, len(upper), 10): s += I(*upper[k:k + 10]) + "\n"
    s += "/BCS/1\nfixed\n   111 111         0         1\n/SURF/PART/1\nlower\n" + I(1) + "\n"
    s += "/INTER/TYPE7/1\ncontact\n" + I(2, 1, 0, 0, 0) + "\n" + R(0, 0, 0) + "\n" + R(0, 0, 0, 0) + I(0, 0) + "\n"
    s += R(stfac, 0, 0.5, 0, 0) + "\n" + "       000" + " " * 20 + I(0) + R(0, 0, 0) + "\n" + I(0, 0) + R(0) + I(0, 0, 0) + R(0) + I(0) + "\n"
    if press:
        s += "/FUNCT/1\nheld\n" + R(0, 1) + "\n" + R(1000, 1) + "\n"
        s += "/CLOAD/1\npress\n" + I(1) + "         Z" + I(0, 0, 2) + " " * 10 + R(0, -press) + "\n"
    if drop:
        s += "/INIVEL/TRA/1\ndown\n" + R(0, 0, -drop) + I(2) + "\n"
    return s + "/END\n"


def write(folder, name, starter, end, every):
    os.makedirs(folder, exist_ok=True)
    open(os.path.join(folder, name + "_0000.rad"), "w").write(starter)
    open(os.path.join(folder, name + "_0001.rad"), "w").write(
        "#RADIOSS ENGINE\n/RUN/%s/1\n%20g\n/PRINT/-%d\n/TFILE/4\n%20g\n/END\n" % (name, end, every, 1e-5))


write("contact_step_dashpot", "CSD", deck("CSD", 1, 0.5, 0.0, 0.05, 0.0), 0.3, 10)
write("contact_step_growth", "CSG", deck("CSG", 2, 0.95, 10.0, 0.0, 10.0, points=1), 0.075, 5)
