# Generates the peer decks of beams (/BEAM with /PROP/TYPE3, docs/theory/beam.md). Run from the folder that is to
# hold the decks; each folder's ref.extract is the reference solver's last printed row on its deck (run-or.sh, then
# or-extract.py). Units kg, m, s; steel E = 2.1e11, nu = 0.3, rho = 7800. The figures Crumple gives against them
# are in docs/validation.md.
#   beam_cantilever_struck: a cantilever of ten beams (1 m, A = 1e-4, Iyy = 1e-9, Izz = 4e-9, Ixx = 3e-9) along
#     (1, 1, 0) / sqrt(2), its tip struck by a constant force across it and a torque about it (no ramp), so that it
#     vibrates in both bending planes and in torsion (the nodes' inertia, BM-6; the default df, BM-7).
#   beam_frame_plastic: a portal frame of beams (two legs of 1 m, a beam of 1.2 m across, diagonals), its feet
#     clamped, its top pushed sideways and down past yield; LAW2 (a = 2.5e8, b = 6e8, n = 0.4), Ishear 0, df 0.02.
#   beam_frame_euler: the same with Ishear 1 (no shear flexibility) and Ismstr 1.
#   beam_bar_rate_fails: one beam of 0.1 m, its end pulled at 0.5 m/s and turned at 3 rad/s about z, LAW2 with
#     c = 0.1 at 0.01 /s (the work-conjugate rate of axial force and bending, BM-5c) and EPS_max 0.05 (BM-9).
#   beam_frame_rate: beam_frame_plastic with LAW2's strain rate, c = 0.5 at 1e-6 /s (BM-5c).
#   beam_frame_fails: beam_frame_plastic 1.3 times loaded, EPS_max = 1e-4: members break (BM-9).
import os
I = lambda *v: "".join("%10d" % x for x in v)
R = lambda *v: "".join("%20.10g" % x for x in v)


def header(run):
    return "/BEGIN\n%s\n      2019         0\n%20s%20s%20s\n%20s%20s%20s\n" % (run, 'kg', 'm', 's', 'kg', 'm', 's')


def prop(pid, a, iyy, izz, ixx, ismstr=0, dm=0.0, df=0.0, ishear=0):
    return ("/PROP/BEAM/%d\nbeam\n" % pid + " " * 10 + I(ismstr) + "\n" + R(dm, df) + "\n" + R(a, iyy, izz, ixx) + "\n"
            + "   000 000" + I(ishear) + "\n")


def write(name, run, s, end, every):
    os.makedirs(name, exist_ok=True)
    open(os.path.join(name, run + "_0000.rad"), "w").write(s + "/END\n")
    open(os.path.join(name, run + "_0001.rad"), "w").write("/RUN/%s/1\n%g\n/TFILE\n%g\n/PRINT/-%d\n" % (run, end, end / 100, every))


def cantilever(name, run):
    d = (2 ** -0.5, 2 ** -0.5, 0.0)
    s = header(run) + "/NODE\n" + "".join(I(i + 1) + R(0.1 * i * d[0], 0.1 * i * d[1], 0.0) + "\n" for i in range(11))
    s += I(99) + R(0.0, 0.0, 1.0) + "\n"  # the orientation node: local y up (global z)
    s += "/BEAM/1\n" + "".join(I(i + 1, i + 1, i + 2, 99) + "\n" for i in range(10))
    s += "/PART/1\nbeam\n" + I(1, 1) + "\n" + prop(1, 1e-4, 1e-9, 4e-9, 3e-9)
    s += "/MAT/LAW1/1\nsteel\n" + R(7800) + "\n" + R(2.1e11, 0.3) + "\n"
    s += "/GRNOD/NODE/1\nclamped\n" + I(1, 99) + "\n/BCS/1\nclamped\n   111 111" + I(0, 1) + "\n"
    s += "/GRNOD/NODE/2\ntip\n" + I(11) + "\n/FUNCT/1\nstep\n" + R(0, 1) + "\n" + R(100, 1) + "\n"
    for k, (dirn, f) in enumerate((("X", -0.7), ("Y", 0.7), ("Z", 0.4), ("XX", 0.05), ("YY", 0.05))):
        s += "/CLOAD/%d\nload\n" % (k + 1) + I(1) + "%10s" % dirn + I(0, 0, 2) + " " * 10 + R(1.0, f) + "\n"
    s += "/TH/BEAM/1\nbeams\nDEF       \n" + "".join(I(i + 1) + "\n" for i in range(10))
    write(name, run, s, 0.05, 500)


def frame(name, run, ishear, ismstr, df, c=0.0, epsmax=0.0, load=1.0):
    nodes = {1: (0, 0, 0), 2: (0, 0, 0.5), 3: (0, 0, 1.0), 4: (0.6, 0, 1.0), 5: (1.2, 0, 1.0), 6: (1.2, 0, 0.5),
             7: (1.2, 0, 0), 8: (0.3, 0.4, 1.0), 9: (0.9, -0.4, 1.0), 99: (0.6, 5.0, 0.5)}
    members = [(1, 2), (2, 3), (3, 4), (4, 5), (5, 6), (6, 7), (2, 4), (4, 6), (3, 8), (8, 4), (4, 9), (9, 5)]
    s = header(run) + "/NODE\n" + "".join(I(k) + R(*p) + "\n" for k, p in nodes.items())
    s += "/BEAM/1\n" + "".join(I(e + 1, a, b, 99) + "\n" for e, (a, b) in enumerate(members))
    s += "/PART/1\nframe\n" + I(1, 1) + "\n" + prop(1, 4e-4, 1.2e-8, 2.4e-8, 2.0e-8, ismstr, 0.0, df, ishear)
    s += ("/MAT/LAW2/1\nsteel\n" + R(7800) + "\n" + R(2.1e11, 0.3) + "\n" + R(2.5e8, 6e8, 0.4, epsmax, 0) + "\n"
          + R(c, 1e-6 if c else 0.0) + I(0, 0) + R(0, 0) + "\n")
    s += "/GRNOD/NODE/1\nfeet\n" + I(1, 7, 99) + "\n/BCS/1\nfeet\n   111 111" + I(0, 1) + "\n"
    s += "/GRNOD/NODE/2\ntop\n" + I(3, 5, 8, 9) + "\n/ADMAS/0/1\ntop mass\n" + R(1.0) + I(2) + "\n"
    s += "/FUNCT/1\nramp\n" + R(0, 0) + "\n" + R(0.01, 1) + "\n" + R(1, 1) + "\n"
    for k, (dirn, f) in enumerate((("X", 3000.0), ("Y", 1500.0), ("Z", -2000.0))):
        s += "/CLOAD/%d\nload\n" % (k + 1) + I(1) + "%10s" % dirn + I(0, 0, 2) + " " * 10 + R(1.0, f * load) + "\n"
    s += "/TH/BEAM/1\nbeams\nDEF       \n" + "".join(I(e + 1) + "\n" for e in range(len(members)))
    write(name, run, s, 0.02, 20)


def driven_bar(name, run):
    s = header(run) + "/NODE\n" + I(1) + R(0, 0, 0) + "\n" + I(2) + R(0.1, 0, 0) + "\n" + I(99) + R(0.05, 1, 0) + "\n"
    s += "/BEAM/1\n" + I(1, 1, 2, 99) + "\n/PART/1\nbar\n" + I(1, 1) + "\n" + prop(1, 1e-4, 1e-9, 1e-9, 2e-9)
    s += ("/MAT/LAW2/1\nsteel\n" + R(7800) + "\n" + R(2.1e11, 0.3) + "\n" + R(2e8, 5e8, 0.5, 0.05, 0) + "\n"
          + R(0.1, 0.01) + I(0, 0) + R(0, 0) + "\n")
    s += "/GRNOD/NODE/1\nheld\n" + I(1, 99) + "\n/BCS/1\nheld\n   111 111" + I(0, 1) + "\n"
    s += "/GRNOD/NODE/2\nend\n" + I(2) + "\n/FUNCT/1\nconst\n" + R(0, 1) + "\n" + R(100, 1) + "\n"
    for k, (dirn, v) in enumerate((("X", 0.5), ("Y", 0.0), ("Z", 0.0), ("XX", 0.0), ("YY", 0.0), ("ZZ", 3.0))):
        s += "/IMPVEL/%d\ndrive\n" % (k + 1) + I(1) + "%10s" % dirn + I(0, 0, 2, 0, 0) + "\n" + R(1.0, v if v else 1e-30, 0, 1e30) + "\n"
    s += "/TH/BEAM/1\nbar\nDEF       \n" + I(1) + "\n"
    write(name, run, s, 0.04, 50)


cantilever("beam_cantilever_struck", "BCANT")
driven_bar("beam_bar_rate_fails", "BRATE")
frame("beam_frame_plastic", "BFRAME", 0, 0, 0.02)
frame("beam_frame_euler", "BFRAMEE", 1, 1, 0.0)
frame("beam_frame_rate", "BFRAMER", 0, 0, 0.02, c=0.5)
frame("beam_frame_fails", "BFRAMEF", 0, 0, 0.02, epsmax=1e-4, load=1.3)
