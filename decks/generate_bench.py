#!/usr/bin/env python3
"""Writes the benchmark decks of issue 13 ("Speed, the measured speed-accuracy trade"), one family at a time, at
any model size from 10^3 to 10^6 elements (chosen by the element size or a target element count):

  tube         square-tube axial crush, the reference setup: a 50 x 50 mm tube, 1.5 mm wall, 200 mm long, of
               square 4-node shells (Ishell 24, 5 points through the thickness), Johnson-Cook mild steel, its rear
               ring a rigid body carrying a 50 kg sled, the whole at 10 m/s onto a fixed rigid wall, TYPE7 self
               contact of the tube with Fric 0.1;
  ball_plate   a hollow shell ball (a cube-sphere mesh) dropped at 10 m/s on a plate clamped at its edges, TYPE7
               contact of the ball's nodes on the plate;
  brick_block  a block of 8-node bricks (Isolid 24 or 1) at 10 m/s onto a fixed rigid wall.

Units: kg, mm, ms (stresses in GPa, velocities in m/s). Each deck is written as DIR/NAME_0000.rad (starter),
DIR/NAME_0001.rad (engine) and DIR/NAME.bench.json (its element counts by kind, nodes, contact secondary nodes and
the parameters, read by bench/run_bench.py). Generated decks are never committed: this script is.

Run:  python3 decks/generate_bench.py tube --elements 10000 --out /tmp/bench/tube_1e4
      python3 decks/generate_bench.py tube --size 2.5 --no-contact --ishell 1 --points 3 --out DIR
      python3 decks/generate_bench.py brick_block --elements 1e5 --isolid 1 --end-time 0.2 --out DIR
decks/generate_tube_impact.py writes the example decks decks/tube_impact and decks/tube_self_contact with the tube
writer of this file.
"""
import argparse
import json
import sys
import math
from dataclasses import dataclass, field, asdict
from pathlib import Path

# ----------------------------------------------------------------------------------------------- card writers


def i10(v):
    return f"{v:>10d}"


def r20(v):
    return f"{v:>20.10g}"


def ruler():
    return "#---1----|----2----|----3----|----4----|----5----|----6----|----7----|----8----|----9----|---10----|\n"


def id_list(ids):
    """Repeat lines of up to 10 ids (groups, surfaces)."""
    return ["".join(i10(v) for v in ids[s:s + 10]) + "\n" for s in range(0, len(ids), 10)]


def begin_cards(name, title, origin):
    return ["#RADIOSS STARTER\n", f"# Crumple {origin}\n", ruler(),
            f"/BEGIN\n{name}\n", i10(2019) + i10(0) + "\n"
            f"{'kg':>20}{'mm':>20}{'ms':>20}\n", f"{'kg':>20}{'mm':>20}{'ms':>20}\n", f"/TITLE\n{title}\n"]


@dataclass
class JohnsonCook:
    """Johnson-Cook steel without rate term, kg/mm/ms: stresses in GPa."""
    rho: float = 7.85e-6
    young: float = 210.0
    poisson: float = 0.3
    a: float = 0.25
    b: float = 0.35
    n: float = 0.52
    sig_max: float = 0.0  # 0: no cap


def johnson_cook_cards(mat_id, title, m):
    return [f"/MAT/PLAS_JOHNS/{mat_id}\n{title}\n", "#              RHO_I\n", r20(m.rho) + "\n",
            "#                  E                  Nu     Iflag\n", r20(m.young) + r20(m.poisson) + i10(0) + "\n",
            "#                  a                   b                   n           EPS_p_max            SIG_max0\n",
            r20(m.a) + r20(m.b) + r20(m.n) + r20(0.0) + r20(m.sig_max) + "\n",
            "#                  c           EPS_DOT_0       ICC   Fsmooth               F_cut               Chard\n",
            r20(0.0) + r20(0.0) + i10(0) + i10(0) + r20(0.0) + r20(0.0) + "\n"]


def shell_property_cards(prop_id, title, ishell, points, thickness):
    return [f"/PROP/SHELL/{prop_id}\n{title}\n",
            "#   Ishell    Ismstr     Ish3n    Idrill                            P_thick_fail\n",
            i10(ishell) + i10(0) + i10(0) + i10(0) + "\n",
            "#                 hm                  hf                  hr                  dm                  dn\n",
            "\n", "#        N   Istrain               Thick              Ashear              Ithick     Iplas\n",
            i10(points) + i10(0) + r20(thickness) + r20(0.0) + i10(1) + i10(1) + "\n"]


def solid_property_cards(prop_id, title, isolid):
    return [f"/PROP/SOLID/{prop_id}\n{title}\n", "#   Isolid\n", i10(isolid) + "\n",
            "#                 qa                  qb                   h\n", r20(0.0) + r20(0.0) + r20(0.0) + "\n"]


def part_cards(part_id, title, prop_id, mat_id):
    return [f"/PART/{part_id}\n{title}\n", i10(prop_id) + i10(mat_id) + "\n"]


def node_cards(points, first_id=1):
    """/NODE block of (x, y, z) points numbered from first_id."""
    return ["/NODE\n"] + [i10(first_id + k) + r20(x) + r20(y) + r20(z) + "\n" for k, (x, y, z) in enumerate(points)]


def element_cards(keyword, part_id, connectivity, first_id=1):
    """/SHELL or /BRICK block: one element per line, node ids as given."""
    return [f"/{keyword}/{part_id}\n"] + [i10(first_id + k) + "".join(i10(n) for n in nodes) + "\n"
                                          for k, nodes in enumerate(connectivity)]


def initial_velocity_cards(vel_id, title, velocity, group_id):
    return [f"/INIVEL/TRA/{vel_id}\n{title}\n",
            "#                 Vx                  Vy                  Vz   Gnod_id   Skew_id\n",
            r20(velocity[0]) + r20(velocity[1]) + r20(velocity[2]) + i10(group_id) + i10(0) + "\n"]


def rigid_body_cards(body_id, title, main_node, mass, group_id):
    return [f"/RBODY/{body_id}\n{title}\n",
            "#     RBID     ISENS     NSKEW    ISPHER                MASS   Gnod_id     IKREM      ICOG   Surf_id\n",
            i10(main_node) + i10(0) + i10(0) + i10(0) + r20(mass) + i10(group_id) + i10(0) + i10(0) + i10(0) + "\n",
            r20(0.0) + r20(0.0) + r20(0.0) + "\n", r20(0.0) + r20(0.0) + r20(0.0) + "\n", i10(0) + i10(0) + "\n"]


def fixed_wall_cards(wall_id, group_id):
    """/RWALL/PLANE fixed at x = 0, normal +x, its secondary nodes the group."""
    return [f"/RWALL/PLANE/{wall_id}\nrigid wall at x = 0\n", "#  node_ID     Slide grnod_ID1 grnod_ID2\n",
            i10(0) + i10(0) + i10(group_id) + i10(0) + "\n",
            "#           D_search                fric            Diameter                ffac       ifq\n",
            r20(0.0) + r20(0.0) + r20(0.0) + r20(0.0) + i10(0) + "\n",
            "#                 XM                  YM                  ZM\n", r20(0.0) + r20(0.0) + r20(0.0) + "\n",
            "#               X_M1                Y_M1                Z_M1\n", r20(1.0) + r20(0.0) + r20(0.0) + "\n"]


def type7_cards(inter_id, title, surf_title, surf_id, part_ids, secondary_group, fric, gapmin=0.0, inacti=0):
    """/SURF/PART of the parts + /INTER/TYPE7: the group's nodes against that surface, defaults otherwise."""
    blank = " " * 10
    return [f"/SURF/PART/{surf_id}\n{surf_title}\n"] + id_list(part_ids) + [
            f"/INTER/TYPE7/{inter_id}\n{title}\n",
            "# grnd_IDs  surf_IDm      Istf      Ithe      Igap                Ibag      Idel     Icurv      Iadm\n",
            i10(secondary_group) + i10(surf_id) + i10(0) + i10(0) + i10(0) + blank + i10(0) + i10(0) + i10(0)
            + i10(0) + "\n",
            r20(0.0) + r20(0.0) + r20(0.0) + "\n",
            r20(0.0) + r20(0.0) + r20(0.0) + r20(0.0) + i10(0) + i10(0) + "\n",
            "#              Stfac                Fric              Gapmin              Tstart               Tstop\n",
            r20(0.0) + r20(fric) + r20(gapmin) + r20(0.0) + r20(0.0) + "\n",
            "       000" + " " * 20 + i10(inacti) + r20(0.0) + r20(0.0) + r20(0.0) + "\n",
            i10(0) + i10(0) + r20(0.0) + i10(0) + i10(0) + i10(0) + r20(0.0) + i10(0) + "\n"]


def history_cards(kind, th_id, title, object_id):
    return [f"/TH/{kind}/{th_id}\n{title}\n", f"{'DEF':<10}\n", i10(object_id) + "\n"]


def bench_engine_cards(name, end_time, noda_cst=0.0):
    """Engine deck of a benchmark run: 100 history rows, frames at t = 0, half-way and the end. With `noda_cst`
    [ms] > 0, /DT/NODA/CST mass scaling to that step, and /STOP without its added-mass limit (the energy limit
    stays)."""
    cards = [f"/RUN/{name}/1\n{end_time:g}\n", f"/TFILE\n{end_time / 100:g}\n", f"/ANIM/DT\n0.0 {end_time / 2:g}\n",
             "/ANIM/ELEM/VONM\n", "/ANIM/ELEM/EPSP\n", "/PRINT/-1000\n", "/DT\n0.9 0.0\n"]
    if noda_cst > 0.0:
        return cards + [f"/DT/NODA/CST\n0.9 {noda_cst:g}\n", "/STOP\n0.1 0.0 0.0 0 0 0\n"]
    return cards + ["/STOP\n0.1 0.1 0.0 0 0 0\n"]


# ------------------------------------------------------------------------------------------------------ the tube


@dataclass
class TubeSetup:
    """A square tube along x, its front end `gap` from the wall x = 0, its rear ring a rigid body with a sled."""
    name: str = "TUBE"
    title: str = "Square tube crushed against a rigid wall"
    origin: str = "benchmark deck, written by decks/generate_bench.py"
    side: float = 50.0
    length: float = 200.0
    elements_per_side: int = 10
    thickness: float = 1.5
    sled_mass: float = 50.0
    speed: float = 10.0
    gap: float = 0.05
    steel: JohnsonCook = field(default_factory=JohnsonCook)
    ishell: int = 24
    points: int = 5
    contact: bool = True
    fric: float = 0.1
    gapmin: float = 0.0  # the self contact's Gapmin [mm]; 0: the default (the mean thickness, bounded)
    noda_cst: float = 0.0  # > 0: /DT/NODA/CST mass scaling to this step [ms]
    end_time: float = 0.1
    engine: list = None  # engine cards; None: bench_engine_cards

    @property
    def element_size(self):
        return self.side / self.elements_per_side

    @property
    def elements_along(self):
        return int(round(self.length / self.element_size))


def tube_elements_per_side(elements):
    """Square elements: 4 n sides x 4 n along = 16 n^2 shells."""
    return max(1, int(round(math.sqrt(elements / 16.0))))


def perimeter_points(t):
    """Points around the square section (y, z), counter-clockwise, elements_per_side per side."""
    n, size, h = t.elements_per_side, t.element_size, t.side / 2
    return ([(-h + k * size, -h) for k in range(n)] + [(h, -h + k * size) for k in range(n)]
            + [(h - k * size, h) for k in range(n)] + [(-h, h - k * size) for k in range(n)])


def tube_mesh(t):
    """Nodes (x, y, z) ring after ring from the front end, the sled node last, and the shells' node ids."""
    ring = perimeter_points(t)
    n_ring, n_along = len(ring), t.elements_along
    points = [(t.gap + j * t.element_size, y, z) for j in range(n_along + 1) for (y, z) in ring]
    points.append((t.gap + t.length, 0.0, 0.0))
    node = lambda j, k: 1 + j * n_ring + k % n_ring
    shells = [(node(j, k), node(j + 1, k), node(j + 1, k + 1), node(j, k + 1))
              for j in range(n_along) for k in range(n_ring)]
    return points, shells, n_ring


def tube_starter(t):
    points, shells, n_ring = tube_mesh(t)
    n_along, sled = t.elements_along, len(points)
    out = begin_cards(t.name, t.title, t.origin)
    out += johnson_cook_cards(1, "mild steel", t.steel)
    out += shell_property_cards(1, "tube wall", t.ishell, t.points, t.thickness)
    out += part_cards(1, "tube", 1, 1)
    out += [ruler()] + node_cards(points) + element_cards("SHELL", 1, shells)
    rear = list(range(1 + n_along * n_ring, 1 + (n_along + 1) * n_ring))
    out += ["/GRNOD/PART/10\nwhole tube\n", i10(1) + "\n"]
    out += ["/GRNOD/NODE/11\nrear section\n"] + id_list(rear)
    out += ["/GRNOD/NODE/12\nsled and tube\n"] + id_list(list(range(1, sled + 1)))
    out += initial_velocity_cards(1, "impact speed", (-t.speed, 0.0, 0.0), 12)
    out += rigid_body_cards(1, "sled", sled, t.sled_mass, 11)
    out += fixed_wall_cards(1, 10)
    out += history_cards("RWALL", 1, "wall force", 1) + history_cards("RBODY", 2, "sled", 1)
    if t.contact:
        out += type7_cards(1, "tube self contact", "tube surface", 1, [1], 10, t.fric, t.gapmin)
        out += history_cards("INTER", 3, "self contact", 1)
    return out + ["/END\n"], {"shell4": len(shells), "nodes": len(points),
                              "contact_secondary_nodes": (len(points) - 1) if t.contact else 0}


# ------------------------------------------------------------------------------------------ the ball on a plate


@dataclass
class BallPlateSetup:
    """A shell ball of radius `radius` above a square plate in z = 0 clamped at its edges, falling at `speed`."""
    name: str = "BALL"
    title: str = "Shell ball dropped on a clamped plate"
    origin: str = "benchmark deck, written by decks/generate_bench.py"
    radius: float = 25.0
    ball_thickness: float = 2.0
    plate_side: float = 150.0
    plate_thickness: float = 2.0
    element_size: float = 5.0
    speed: float = 10.0
    clearance: float = 0.05  # between the contact gaps at t = 0 [mm]
    penetration: float = 0.0  # > 0: the ball's lowest node starts this share of the gap inside it instead
    inacti: int = 0  # the interface's Inacti (what it does with initial penetrations)
    plate_modulus_ratio: float = 1.0  # > 1: the plate is elastic, its Young's modulus the steel's over this
    stamp_side: float = 0.0  # > 0: a flat square stamp of this side [mm] instead of the ball (wide contact)
    press: float = 0.0  # > 0: a constant acceleration [mm/ms^2] on the ball or stamp towards the plate (/GRAV)
    drive: bool = False  # the ball or stamp driven at `speed` all through the run (/IMPVEL), not only launched
    die: bool = False  # every plate node held: the plate is a fixed die the ball or stamp lands on
    steel: JohnsonCook = field(default_factory=JohnsonCook)
    ishell: int = 24
    points: int = 5
    contact: bool = True
    fric: float = 0.1
    end_time: float = 0.1

    @property
    def ball_divisions(self):
        """Elements along an edge of each of the 6 cube faces (a quarter great circle)."""
        return max(1, int(round(0.5 * math.pi * self.radius / self.element_size)))

    @property
    def plate_divisions(self):
        return max(1, int(round(self.plate_side / self.element_size)))

    @property
    def gapmin(self):
        return 0.5 * (self.ball_thickness + self.plate_thickness)


def ball_plate_element_size(elements, radius=25.0, plate_side=150.0):
    """Element size h giving about `elements` shells: 6 (pi R / 2h)^2 on the ball and (L / h)^2 on the plate."""
    return math.sqrt((6 * (0.5 * math.pi * radius) ** 2 + plate_side ** 2) / elements)


def cube_face_nodes(n, axis, sign):
    """Lattice points (i, j, k) in 0..n of one cube face and its quads, counter-clockwise about the outward normal."""
    b, c = (axis + 1) % 3, (axis + 2) % 3
    first, second = (b, c) if sign > 0 else (c, b)

    def lattice(i, j):
        p = [0, 0, 0]
        p[axis], p[first], p[second] = (n if sign > 0 else 0), i, j
        return tuple(p)
    quads = [(lattice(i, j), lattice(i + 1, j), lattice(i + 1, j + 1), lattice(i, j + 1))
             for i in range(n) for j in range(n)]
    return quads


def sphere_point(lattice, n, radius, centre):
    """Equiangular projection of a cube-lattice point on the sphere."""
    q = [math.tan(0.25 * math.pi * (2.0 * v / n - 1.0)) for v in lattice]
    norm = math.sqrt(sum(v * v for v in q))
    return tuple(centre[d] + radius * q[d] / norm for d in range(3))


def ball_mesh(s, first_id):
    """Nodes and quads of the cube-sphere ball whose lowest point is the contact gap plus clearance above z = 0."""
    n = s.ball_divisions
    clearance = -s.penetration * s.gapmin if s.penetration > 0.0 else s.clearance
    centre = (0.0, 0.0, s.radius + s.gapmin + clearance)
    ids, points, quads = {}, [], []
    for axis in range(3):
        for sign in (1, -1):
            for quad in cube_face_nodes(n, axis, sign):
                for lat in quad:
                    if lat not in ids:
                        ids[lat] = first_id + len(points)
                        points.append(sphere_point(lat, n, s.radius, centre))
                quads.append(tuple(ids[lat] for lat in quad))
    if s.penetration > 0.0:  # the lowest node, not the sphere, starts that share of the gap inside it
        drop = min(p[2] for p in points) - (s.gapmin + clearance)
        points = [(x, y, z - drop) for (x, y, z) in points]
    return points, quads


def stamp_mesh(s, first_id):
    """Nodes and quads of a flat square stamp of side stamp_side centred above the plate, the contact gap plus
    clearance above it: every node of it meets the plate at once (a contact as wide as the stamp)."""
    m = max(1, int(round(s.stamp_side / s.element_size)))
    clearance = -s.penetration * s.gapmin if s.penetration > 0.0 else s.clearance
    h, x0, z = s.stamp_side / m, -0.5 * s.stamp_side, s.gapmin + clearance
    points = [(x0 + i * h, x0 + j * h, z) for j in range(m + 1) for i in range(m + 1)]
    node = lambda i, j: first_id + j * (m + 1) + i
    quads = [(node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)) for j in range(m) for i in range(m)]
    return points, quads


def plate_mesh(s):
    """Nodes of the plate row by row, its quads, and the ids of its edge nodes."""
    m, h = s.plate_divisions, s.plate_side / s.plate_divisions
    x0 = -0.5 * s.plate_side
    points = [(x0 + i * h, x0 + j * h, 0.0) for j in range(m + 1) for i in range(m + 1)]
    node = lambda i, j: 1 + j * (m + 1) + i
    quads = [(node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)) for j in range(m) for i in range(m)]
    edge = [node(i, j) for j in range(m + 1) for i in range(m + 1) if i in (0, m) or j in (0, m)]
    return points, quads, edge


def ball_plate_starter(s):
    plate_points, plate_quads, edge = plate_mesh(s)
    ball_points, ball_quads = (stamp_mesh if s.stamp_side > 0.0 else ball_mesh)(s, 1 + len(plate_points))
    out = begin_cards(s.name, s.title, s.origin)
    out += johnson_cook_cards(1, "mild steel", s.steel)
    plate_material = 1
    if s.plate_modulus_ratio != 1.0:  # a soft elastic plate: the stiffness ratio of the bodies in contact
        plate_material = 2
        out += ["/MAT/LAW1/2\nsoft plate\n", r20(s.steel.rho) + "\n",
                r20(s.steel.young / s.plate_modulus_ratio) + r20(s.steel.poisson) + "\n"]
    out += shell_property_cards(1, "plate", s.ishell, s.points, s.plate_thickness)
    out += shell_property_cards(2, "ball", s.ishell, s.points, s.ball_thickness)
    out += part_cards(1, "plate", 1, plate_material) + part_cards(2, "ball", 2, 1)
    out += [ruler()] + node_cards(plate_points + ball_points)
    out += element_cards("SHELL", 1, plate_quads) + element_cards("SHELL", 2, ball_quads, 1 + len(plate_quads))
    out += ["/GRNOD/NODE/10\nplate edge\n"] + id_list(edge)
    out += ["/BCS/1\nclamped edge\n", "   111 111         0        10\n"]
    if s.die:
        out += ["/GRNOD/PART/12\nplate\n", i10(1) + "\n", "/BCS/2\nfixed die\n", "   111 111         0        12\n"]
    out += ["/GRNOD/PART/11\nball\n", i10(2) + "\n"]
    out += initial_velocity_cards(1, "drop speed", (0.0, 0.0, -s.speed), 11)
    if s.drive:  # keeps the contact closed quasi-statically: the ball or stamp pushed into the plate at its speed
        out += ["/FUNCT/1\nconstant\n", r20(0.0) + r20(1.0) + "\n", r20(1e3 * max(s.end_time, 1.0)) + r20(1.0) + "\n"]
        out += ["/IMPVEL/1\ndriven at the drop speed\n", i10(1) + "{:>10}".format("Z") + i10(0) + i10(0) + i10(11) + "\n",
                r20(0.0) + r20(-s.speed) + r20(0.0) + r20(0.0) + "\n"]
    if s.press > 0.0:  # keeps the contact closed: the ball or stamp pressed onto the plate
        out += ["/GRAV/1\npressed onto the plate\n",
                i10(0) + "{:>10}".format("Z") + i10(0) + i10(0) + i10(11) + " " * 10 + r20(1.0) + r20(-s.press) + "\n"]
    if s.contact:
        out += type7_cards(1, "ball on plate", "plate surface", 1, [1], 11, s.fric, s.gapmin, s.inacti)
        out += history_cards("INTER", 1, "ball on plate", 1)
    counts = {"shell4": len(plate_quads) + len(ball_quads), "nodes": len(plate_points) + len(ball_points),
              "contact_secondary_nodes": len(ball_points) if s.contact else 0}
    return out + ["/END\n"], counts


# --------------------------------------------------------------------------------------------- the brick block


@dataclass
class BrickBlockSetup:
    """A block of bricks, 2 L long in x and L x L across, its front face `gap` from the wall x = 0."""
    name: str = "BLOCK"
    title: str = "Brick block against a rigid wall"
    origin: str = "benchmark deck, written by decks/generate_bench.py"
    width: float = 50.0
    divisions: int = 8  # across; 2 x divisions along
    speed: float = 10.0
    gap: float = 0.05
    steel: JohnsonCook = field(default_factory=JohnsonCook)
    isolid: int = 24
    end_time: float = 0.1

    @property
    def element_size(self):
        return self.width / self.divisions


def brick_block_divisions(elements):
    """2 n x n x n bricks."""
    return max(1, int(round((elements / 2.0) ** (1.0 / 3.0))))


def block_mesh(b):
    n, h = b.divisions, b.element_size
    nx = 2 * n
    points = [(b.gap + i * h, -0.5 * b.width + j * h, -0.5 * b.width + k * h)
              for k in range(n + 1) for j in range(n + 1) for i in range(nx + 1)]
    node = lambda i, j, k: 1 + (k * (n + 1) + j) * (nx + 1) + i
    bricks = []
    for k in range(n):
        for j in range(n):
            for i in range(nx):
                bottom = [node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k), node(i, j + 1, k)]
                top = [node(i, j, k + 1), node(i + 1, j, k + 1), node(i + 1, j + 1, k + 1), node(i, j + 1, k + 1)]
                bricks.append(tuple(bottom + top))
    return points, bricks


def brick_block_starter(b):
    points, bricks = block_mesh(b)
    out = begin_cards(b.name, b.title, b.origin)
    out += johnson_cook_cards(1, "mild steel", b.steel)
    out += solid_property_cards(1, "block", b.isolid)
    out += part_cards(1, "block", 1, 1)
    out += [ruler()] + node_cards(points) + element_cards("BRICK", 1, bricks)
    out += ["/GRNOD/PART/10\nwhole block\n", i10(1) + "\n"]
    out += initial_velocity_cards(1, "impact speed", (-b.speed, 0.0, 0.0), 10)
    out += fixed_wall_cards(1, 10) + history_cards("RWALL", 1, "wall force", 1)
    return out + ["/END\n"], {"brick8": len(bricks), "nodes": len(points), "contact_secondary_nodes": 0}


# ------------------------------------------------------------------------------------------------- writing


def write_deck(directory, name, starter, engine, counts, setup):
    """NAME_0000.rad, NAME_0001.rad and NAME.bench.json in `directory`; returns the starter's path."""
    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    (directory / f"{name}_0000.rad").write_text("".join(starter))
    (directory / f"{name}_0001.rad").write_text("".join(engine))
    if counts is not None:
        meta = {"family": type(setup).__name__, "counts": counts, "setup": asdict(setup)}
        meta["setup"].pop("engine", None)
        (directory / f"{name}.bench.json").write_text(json.dumps(meta, indent=1) + "\n")
    return directory / f"{name}_0000.rad"


def write_tube(directory, t, with_meta=True):
    starter, counts = tube_starter(t)
    engine = t.engine if t.engine is not None else bench_engine_cards(t.name, t.end_time, t.noda_cst)
    return write_deck(directory, t.name, starter, engine, counts if with_meta else None, t)


def setup_for(family, elements=None, size=None, end_time=0.1, contact=True, ishell=24, points=5, isolid=24,
              speed=10.0, gap=0.0, penetration=0.0, inacti=0, plate_modulus_ratio=1.0, noda_cst=0.0, stamp=0.0,
              press=0.0, drive=False, die=False):
    """The setup of one family at a target element count or an element size [mm]."""
    if family == "tube":
        n = tube_elements_per_side(elements) if elements else max(1, int(round(50.0 / size)))
        return TubeSetup(elements_per_side=n, end_time=end_time, contact=contact, ishell=ishell, points=points,
                         speed=speed, gapmin=gap, noda_cst=noda_cst)
    if family == "ball_plate":
        h = size if size else ball_plate_element_size(elements)
        return BallPlateSetup(element_size=h, end_time=end_time, contact=contact, ishell=ishell, points=points,
                              speed=speed, penetration=penetration, inacti=inacti,
                              plate_modulus_ratio=plate_modulus_ratio, stamp_side=stamp, press=press, drive=drive, die=die)
    if family == "brick_block":
        n = brick_block_divisions(elements) if elements else max(1, int(round(50.0 / size)))
        return BrickBlockSetup(divisions=n, end_time=end_time, isolid=isolid, speed=speed)
    raise ValueError(f"unknown family {family}")


def write_family(family, directory, **options):
    """Writes one deck of the family into `directory`; returns the starter's path."""
    setup = setup_for(family, **options)
    if family == "tube":
        return write_tube(directory, setup)
    starter, counts = (ball_plate_starter if family == "ball_plate" else brick_block_starter)(setup)
    return write_deck(directory, setup.name, starter, bench_engine_cards(setup.name, setup.end_time), counts, setup)


FAMILIES = ("tube", "ball_plate", "brick_block")


def parse_arguments():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("family", choices=FAMILIES)
    size = p.add_mutually_exclusive_group(required=True)
    size.add_argument("--elements", type=float, help="target element count (1e3 to 1e6)")
    size.add_argument("--size", type=float, help="element size [mm]")
    p.add_argument("--out", required=True, help="directory of the deck (created)")
    p.add_argument("--end-time", type=float, default=0.1, help="end time [ms] (default 0.1)")
    p.add_argument("--no-contact", action="store_true", help="tube, ball_plate: no TYPE7 interface")
    p.add_argument("--ishell", type=int, default=24, help="shell formulation (default 24)")
    p.add_argument("--points", type=int, default=5, help="shell points through the thickness (default 5)")
    p.add_argument("--isolid", type=int, default=24, help="brick formulation of brick_block (default 24)")
    p.add_argument("--speed", type=float, default=10.0, help="impact speed [m/s] (default 10)")
    p.add_argument("--noda-cst", type=float, default=0.0,
                   help="tube: /DT/NODA/CST mass scaling to this step [ms] (default 0: none)")
    p.add_argument("--gap", type=float, default=0.0,
                   help="tube: the self contact's Gapmin [mm] (default 0: the thickness-based default)")
    p.add_argument("--penetration", type=float, default=0.0,
                   help="ball_plate: the ball starts this share of the contact gap inside it (0 to 0.99)")
    p.add_argument("--inacti", type=int, default=0, help="ball_plate: the interface's Inacti (default 0)")
    p.add_argument("--plate-modulus-ratio", type=float, default=1.0,
                   help="ball_plate: an elastic plate whose Young's modulus is the steel's over this (default 1: "
                        "the ball's steel)")
    p.add_argument("--stamp", type=float, default=0.0,
                   help="ball_plate: a flat square stamp of this side [mm] instead of the ball, so that a wide contact "
                        "(about a quarter of the nodes at 87 mm) closes at once (default 0: the ball)")
    p.add_argument("--press", type=float, default=0.0,
                   help="ball_plate: a constant acceleration [mm/ms^2] pressing the ball or stamp onto the plate (/GRAV), "
                        "so that the contact stays closed (default 0: none)")
    p.add_argument("--drive", action="store_true",
                   help="ball_plate: the ball or stamp driven at --speed all through the run (/IMPVEL), so that the "
                        "contact stays closed without a press (default: launched at --speed, then free)")
    p.add_argument("--die", action="store_true",
                   help="ball_plate: every plate node held, so that the plate is a fixed die (default: clamped edges)")
    return p.parse_args()


def main():
    a = parse_arguments()
    if a.gap and a.family != "tube":
        sys.exit(f"generate_bench.py: --gap is the tube's self-contact gap; {a.family} has none to set")
    if a.noda_cst and a.family != "tube":
        sys.exit(f"generate_bench.py: --noda-cst is the tube's; {a.family} has none to set")
    ball_only = {"--penetration": a.penetration != 0.0, "--inacti": a.inacti != 0,
                 "--plate-modulus-ratio": a.plate_modulus_ratio != 1.0, "--stamp": a.stamp != 0.0,
                 "--press": a.press != 0.0, "--drive": a.drive, "--die": a.die}
    for option, given in ball_only.items():
        if given and a.family != "ball_plate":
            sys.exit(f"generate_bench.py: {option} is the ball_plate's; {a.family} has none to set")
    if not 0.0 <= a.penetration < 1.0 or a.plate_modulus_ratio <= 0.0 or not 0.0 <= a.stamp < 150.0 or a.press < 0.0:
        sys.exit("generate_bench.py: --penetration takes 0 to below 1, --plate-modulus-ratio a positive number, "
                 "--stamp a side from 0 to below the plate's 150 mm, --press a positive acceleration")
    starter = write_family(a.family, a.out, elements=int(a.elements) if a.elements else None, size=a.size,
                           end_time=a.end_time, contact=not a.no_contact, ishell=a.ishell, points=a.points,
                           isolid=a.isolid, speed=a.speed, gap=a.gap, penetration=a.penetration, inacti=a.inacti,
                           plate_modulus_ratio=a.plate_modulus_ratio, noda_cst=a.noda_cst, stamp=a.stamp,
                           press=a.press, drive=a.drive, die=a.die)
    counts = json.loads(starter.with_name(starter.name.replace("_0000.rad", ".bench.json")).read_text())["counts"]
    print(f"wrote {starter}: " + ", ".join(f"{k} {v}" for k, v in counts.items()))


if __name__ == "__main__":
    main()
