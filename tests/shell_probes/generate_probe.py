#!/usr/bin/env python3
"""Small shell decks that probe one mechanism of a shell formulation (docs/theory/shell4.md, "Probes").

Each deck is a flat sheet in the x-y plane (kg, mm, ms, GPa), clamped or free, driven by imposed velocities on
chosen nodes, so that the same deck runs through Crumple and through the reference solver and their energy rows
can be compared. Kinds:

  strip      a cantilever strip nx x ny, clamped at x = 0; the tip nodes (x = L) driven along --drive
             (z: bending, x: membrane, y: in-plane bending) at --speed mm/ms for --time ms.
  mode       one element whose four nodes are driven in an hourglass pattern (--mode membrane, bending, twist,
             shear): each node's velocity is --speed times the pattern's sign. With --reverse T the drive turns
             back after T and stops after 2 T: the work left is what the mode dissipated (shell4.md, S-5b).
  fold       a strip nx x ny, clamped at x = 0, its far edge pushed along -x (buckling into a fold) at --speed.
  edge       a free sheet nx x ny whose tip nodes (x = L) move along --drive at --speed for --rise ms, then stop:
             the sheet rings, and what damps it and how its work is counted shows (shell4.md, S-9d, S-9e).
  pair       a free plate of side --top at --depth over a free 5 x 5 plate, inside a TYPE7 gap --type7: the first
             cycle's step is the interface nodal step's (docs/theory/time-step.md, T-4).
  held       one element, every degree of freedom held but those --held names (node:DOF[:sign], nodes 1 to 4 of
             the 1 x 1 mesh, e.g. "1:XX,1:YY"), each driven at sign times --speed: the energy is the element's
             stiffness on exactly those degrees of freedom (docs/theory/shell4.md, S-13a).

--tria splits each quadrilateral on its 1-3 diagonal into two 3-node shells. --law 1 is elastic steel, --law 2
Johnson-Cook steel (a 0.21, b 0.45, n 0.45, the shared rails' sheet), --law 36 /MAT/PLAS_TAB yielding at 2 GPa. --skew s moves the free corner nodes of
the mesh by s times the element size (distorted elements).

  generate_probe.py strip --tria --law 2 --out DIR     # writes DIR/PROBE_0000.rad and DIR/PROBE_0001.rad
"""
import argparse
import math
import os


def fmt_row(values, width=20):
    return "".join(f"{v:>{width}}" for v in values)


def ints(values):
    return "".join(f"{v:>10}" for v in values)


def mesh(nx, ny, dx, dy, skew):
    nodes = {}
    nid = 0
    for j in range(ny + 1):
        for i in range(nx + 1):
            nid += 1
            x, y = i * dx, j * dy
            if skew and 0 < i < nx and 0 < j < ny:
                x += skew * dx * (1 if (i + j) % 2 else -1)
                y += 0.5 * skew * dy * (1 if i % 2 else -1)
            nodes[nid] = (x, y, 0.0)
    quads = []
    for j in range(ny):
        for i in range(nx):
            n1 = j * (nx + 1) + i + 1
            quads.append((n1, n1 + 1, n1 + nx + 2, n1 + nx + 1))
    return nodes, quads


def material(law):
    if law == 36:  # /MAT/PLAS_TAB with a yield curve from 2 GPa: elastic in the probes that drive it gently
        return ("/MAT/PLAS_TAB/1\nsteel, tabulated\n" + fmt_row([7.85e-06]) + "\n" + fmt_row([210, 0.3]) + "\n"
                + ints([1, 0]) + fmt_row([0, 0]) + "\n" + ints([0]) + fmt_row([0]) + ints([0]) + "\n" + ints([5]) + "\n"
                + fmt_row([1]) + "\n" + fmt_row([0]) + "\n/FUNCT/5\nhardening\n" + fmt_row([0, 2]) + "\n"
                + fmt_row([1, 2.5]) + "\n")
    if law == 1:
        return """/MAT/ELAST/1
steel
#              RHO_I
            7.85e-06
#                  E                  Nu
                 210                 0.3
"""
    return """/MAT/PLAS_JOHNS/1
deep-drawing steel
#              RHO_I
            7.85e-06                   0
#                  E                  Nu     Iflag
                 210                 0.3         0
#                  a                   b                   n           EPS_p_max            SIG_max0
                0.21                0.45                0.45                   0                   0
#                  c           EPS_DOT_0       ICC   Fsmooth               F_cut               Chard
                   0                   0         0         0                   0                   0
#                  m              T_melt              rhoC_p                 T_r
                   0                   0                   0                   0
"""


def prop(a):
    return f"""/PROP/TYPE1/1
sheet
#   Ishell    Ismstr     Ish3n    Idrill                            P_thick_fail
{ints([a.ishell, a.ismstr, a.ish3n, 0])}                                       0
#                 hm                  hf                  hr                  dm                  dn
{fmt_row([a.hm, a.hf, a.hr, a.dm, a.dn])}
#        N   Istrain               Thick              Ashear              Ithick     Iplas
{ints([a.npt, 0])}{fmt_row([a.thick, 0])}{ints([0, 0])}
"""


def grnod(gid, title, ids):
    rows = [ints(ids[k:k + 10]) for k in range(0, len(ids), 10)]
    return f"/GRNOD/NODE/{gid}\n{title}\n" + "\n".join(rows) + "\n"


def impvel(iid, fid, direction, gid, scale):
    return f"""/IMPVEL/{iid}
drive {iid}
#funct_IDT       Dir   skew_ID sensor_ID  grnod_ID
{ints([fid])}{direction:>10}{ints([0, 0, gid])}
#           Ascale_x            Fscale_Y              Tstart               Tstop
{fmt_row([0, scale, 0, 0])}
"""


MODES = {  # node signs of the hourglass pattern (1, -1, 1, -1) and the dof it drives
    "membrane": ("X", (1, -1, 1, -1)),
    "bending": ("Z", (1, -1, 1, -1)),
    "twist": ("XX", (1, -1, 1, -1)),
    "twisty": ("YY", (1, -1, 1, -1)),
}


def type7(title, gapmin, fric=0.0, visf=0.0):
    """A TYPE7 interface of the secondary nodes of /GRNOD 90 on the surface /SURF 91, defaults but Gapmin, Fric and
    VisF."""
    return f"""/INTER/TYPE7/1
{title}
#  Slav_id   Mast_id      Istf      Ithe      Igap                Ibag      Idel     Icurv      Iadm
        90        91         0         0         0                   0         0         0         0
#          Fscalegap             Gap_max             Fpenmax
                   0                   0                   0
#              Stmin               Stmax          %mesh_size               dtmin  Irem_gap   Irem_i2
                   0                   0                   0                   0         0         0
#              Stfac                Fric              Gapmin              Tstart               Tstop
                   0{fric:>20}{gapmin:>20}                   0                   0
#      IBC                        Inacti                VisS                VisF              Bumult
       000                             0                   0{visf:>20}                   0
#    Ifric    Ifiltr               Xfreq     Iform   sens_ID   fct_IDf             AscaleF   fric_ID
         0         0                   0         0         0         0                   0         0
"""


def header(a):
    return "\n".join(["#RADIOSS STARTER", f"# Crumple shell probe: {a.kind} {' '.join(a.note)}", "/BEGIN", "PROBE",
                      "      2019         0",
                      "                  kg                  mm                  ms",
                      "                  kg                  mm                  ms", "/TITLE",
                      f"shell probe {a.kind}"]) + "\n"


def engine_deck(a):
    engine = f"""#RADIOSS ENGINE
/RUN/PROBE/1
{fmt_row([a.time])}
/PRINT/-{a.print_every}
/TFILE/4
{fmt_row([a.time / 50])}
"""
    if a.dtscale:
        engine += f"/DT\n{fmt_row([a.dtscale, 0])}\n"
    if a.noda:  # nodal mass scaling: scale and target step
        engine += f"/DT/NODA/CST/0\n{fmt_row(a.noda.split(','))}\n"
    return engine


def build_pair(a):
    """A free square plate of side --top at --depth above a free 5 x 5 plate (the main surface), both at rest, inside
    the TYPE7 gap --type7: the step of its first cycle is the contact's. --light scales the lower plate's density."""
    light = material(1).replace("/MAT/ELAST/1", "/MAT/ELAST/2").replace("7.85e-06", f"{7.85e-06 * a.light:.6g}")
    text = header(a) + material(a.law) + light + prop(a)
    text += "/PART/1\nmain plate\n         1         2         0\n/PART/2\ntop plate\n         1         1         0\n"
    lo, hi = a.centre - a.top / 2, a.centre + a.top / 2
    corners = [(0, 0, 0), (5, 0, 0), (5, 5, 0), (0, 5, 0), (lo, lo, a.depth), (hi, lo, a.depth), (hi, hi, a.depth),
               (lo, hi, a.depth)]
    text += "/NODE\n" + "".join(f"{k + 1:>10}{fmt_row([f'{x:.10g}', f'{y:.10g}', f'{z:.10g}'])}\n"
                                 for k, (x, y, z) in enumerate(corners))
    text += "/SHELL/1\n" + ints([1, 1, 2, 3, 4]) + "\n/SHELL/2\n" + ints([2, 5, 6, 7, 8]) + "\n"
    text += "/GRNOD/PART/90\ntop nodes\n         2\n/SURF/PART/91\nmain surface\n         1\n"
    return text + type7("pair", a.type7, a.fric, a.visf) + "/END\n", engine_deck(a)


def build(a):
    dx = a.length / a.nx
    dy = a.width / a.ny
    nodes, quads = mesh(a.nx, a.ny, dx, dy, a.skew)
    if a.imperfection:  # a half sine out of the plane along x, so that a strip pushed along x buckles one way
        for nid, (x, y, z) in nodes.items():
            nodes[nid] = (x, y, a.imperfection * math.sin(math.pi * x / a.length))
    if a.corners:  # one element of given corners "x,y,z;x,y,z;x,y,z;x,y,z" (nodes 1, 2, 4, 3 of the 1x1 mesh)
        xyz = [tuple(float(v) for v in c.split(",")) for c in a.corners.split(";")]
        for nid, c in zip(quads[0], xyz):
            nodes[nid] = c
    text = header(a) + material(a.law) + prop(a)
    text += "/PART/1\nsheet\n         1         1         0\n/NODE\n"
    for nid, (x, y, z) in nodes.items():
        text += f"{nid:>10}{fmt_row([f'{x:.10g}', f'{y:.10g}', f'{z:.10g}'])}\n"
    if a.tria:
        text += "/SH3N/1\n"
        eid = 0
        for q in quads:
            for tri in ((q[0], q[1], q[2]), (q[0], q[2], q[3])):
                eid += 1
                text += ints([eid, *tri]) + "\n"
    else:
        text += "/SHELL/1\n"
        for k, q in enumerate(quads):
            text += ints([k + 1, *q]) + "\n"
    if a.reverse:  # there and back: +1 for --reverse ms, -1 for as long, then at rest (what a mode dissipates)
        t = a.reverse
        text += "/FUNCT/1\nthere and back\n" + "".join(
            fmt_row(row) + "\n" for row in ([0, 1], [t, 1], [t * 1.0001, -1], [2 * t, -1], [2 * t * 1.0001, 0], [1e6, 0]))
    else:
        text += """/FUNCT/1
ramp to 1 over the rise time, then held
                   0                   0
""" + fmt_row([a.rise, 1]) + "\n" + fmt_row([1e6, 1]) + "\n"
    row = a.nx + 1
    root = [j * row + 1 for j in range(a.ny + 1)]
    tip = [j * row + row for j in range(a.ny + 1)]
    if a.kind == "edge":  # a velocity pulse: --speed until --rise, then 0
        text += "/FUNCT/2\npulse\n" + fmt_row([0, 1]) + "\n" + fmt_row([a.rise, 1]) + "\n"
        text += fmt_row([a.rise * 1.0001, 0]) + "\n" + fmt_row([1e6, 0]) + "\n"
        text += grnod(2, "tip", tip) + impvel(1, 2, a.drive.upper(), 2, a.speed)
    elif a.kind in ("strip", "fold"):
        text += grnod(1, "root", root) + "/BCS/1\nclamp\n   111 111         0         1\n"
        text += grnod(2, "tip", tip)
        if a.kind == "strip":
            text += impvel(1, 1, a.drive.upper(), 2, a.speed)
        else:
            text += impvel(1, 1, "X", 2, -a.speed)
            text += "/BCS/2\ntip guide\n   011 111         0         2\n"
    elif a.kind == "held":
        drives = [(int(t.split(":")[0]), t.split(":")[1].upper(), float(t.split(":")[2]) if t.count(":") > 1 else 1.0)
                  for t in a.held.split(",")]
        driven = sorted({n for n, _, _ in drives})
        held = [n for n in quads[0] if n not in driven]
        if held:
            text += grnod(1, "held", held) + "/BCS/1\nheld\n   111 111         0         1\n"
        k = 0
        for n in driven:  # the node's other degrees of freedom held (a blank /IMPVEL scale would mean 1)
            dofs = {d: sign for m, d, sign in drives if m == n}
            code = "".join("0" if d in dofs else "1" for d in ("X", "Y", "Z")) + " " + \
                "".join("0" if d in dofs else "1" for d in ("XX", "YY", "ZZ"))
            text += grnod(10 + n, f"node {n}", [n]) + f"/BCS/{10 + n}\nnode {n}\n   {code}{ints([0, 10 + n])}\n"
            for d, sign in dofs.items():
                k += 1
                text += impvel(k, 1, d, 10 + n, sign * a.speed)
    else:
        direction, signs = MODES[a.mode]
        for k, (nid, s) in enumerate(zip(quads[0], signs)):
            text += grnod(10 + k, f"node {nid}", [nid]) + impvel(10 + k, 1, direction, 10 + k, s * a.speed)
    if a.type7:  # a self contact of the sheet that never closes: what the interface alone does to the step
        text += "/GRNOD/PART/90\nsheet nodes\n         1\n/SURF/PART/91\nsheet surface\n         1\n"
        text += type7("self contact", a.type7)
    return text + "/END\n", engine_deck(a)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("kind", choices=["strip", "mode", "fold", "pair", "edge", "held"])
    p.add_argument("--out", required=True)
    p.add_argument("--nx", type=int, default=10)
    p.add_argument("--ny", type=int, default=2)
    p.add_argument("--length", type=float, default=50.0)
    p.add_argument("--width", type=float, default=10.0)
    p.add_argument("--thick", type=float, default=1.5)
    p.add_argument("--skew", type=float, default=0.0)
    p.add_argument("--tria", action="store_true")
    p.add_argument("--law", type=int, default=1, choices=[1, 2, 36])
    p.add_argument("--ishell", type=int, default=24)
    p.add_argument("--ismstr", type=int, default=0)
    p.add_argument("--ish3n", type=int, default=0)
    p.add_argument("--npt", type=int, default=5)
    p.add_argument("--hm", type=float, default=0)
    p.add_argument("--hf", type=float, default=0)
    p.add_argument("--hr", type=float, default=0)
    p.add_argument("--dm", type=float, default=0)
    p.add_argument("--dn", type=float, default=0)
    p.add_argument("--drive", default="z")
    p.add_argument("--mode", default="membrane", choices=sorted(MODES))
    p.add_argument("--speed", type=float, default=1.0, help="mm/ms")
    p.add_argument("--rise", type=float, default=0.1, help="ms")
    p.add_argument("--reverse", type=float, default=0.0,
                   help="ms: drive at +speed that long, then at -speed as long, then stop (kinds mode, held)")
    p.add_argument("--time", type=float, default=1.0, help="ms")
    p.add_argument("--print-every", type=int, default=100)
    p.add_argument("--dtscale", type=float, default=0)
    p.add_argument("--type7", type=float, default=0.0, help="a TYPE7 self contact of the sheet with this Gapmin [mm]")
    p.add_argument("--imperfection", type=float, default=0.0, help="mm: a half sine out of the plane along x")
    p.add_argument("--corners", default="", help="one element's corners, x,y,z;x,y,z;x,y,z;x,y,z (kinds mode, held)")
    p.add_argument("--top", type=float, default=2.0, help="mm: the upper plate's side (kind pair)")
    p.add_argument("--centre", type=float, default=2.5, help="mm: the upper plate's centre, x = y (kind pair)")
    p.add_argument("--depth", type=float, default=0.05, help="mm: the upper plate's height (kind pair)")
    p.add_argument("--light", type=float, default=1.0, help="the main plate's density factor (kind pair)")
    p.add_argument("--fric", type=float, default=0.0, help="the TYPE7's Coulomb friction (kind pair)")
    p.add_argument("--visf", type=float, default=0.0, help="the TYPE7's VisF, blank 1 (kind pair)")
    p.add_argument("--noda", default="", help="/DT/NODA/CST scale,dtmin in the engine deck")
    p.add_argument("--held", default="1:YY", help="the driven degrees of freedom, node:DOF[:sign],... (kind held)")
    p.add_argument("note", nargs="*")
    a = p.parse_args()
    if a.kind in ("mode", "held"):
        a.nx = a.ny = 1
        a.length = a.width = a.length if a.length != 50.0 else 5.0
    starter, engine = build_pair(a) if a.kind == "pair" else build(a)
    os.makedirs(a.out, exist_ok=True)
    open(os.path.join(a.out, "PROBE_0000.rad"), "w").write(starter)
    open(os.path.join(a.out, "PROBE_0001.rad"), "w").write(engine)


if __name__ == "__main__":
    main()
