#!/usr/bin/env python3
"""Writes decks/tube_impact: a thin-walled square steel tube driven into a rigid wall, and decks/tube_self_contact:
the same with a TYPE7 self contact of the tube (every tube node against the tube's surface, Fric 0.2), the
contact case of the time-profile benchmark (docs/performance.md).

Units: kg, mm, ms (so stresses in GPa, velocities in m/s, energies in J). The tube is 50 x 50 mm, 200 mm long,
1.2 mm thick, meshed with 5 mm shells; its rear end carries a 20 kg rigid body (a sled) and the whole tube moves
at 10 m/s towards the plane x = 0. Run: crumple run decks/tube_impact/TUBE_0000.rad
"""
from pathlib import Path

SIDE, LENGTH, SIZE = 50.0, 200.0, 5.0
N_SIDE, N_LENGTH = int(SIDE / SIZE), int(LENGTH / SIZE)
GAP = 1.0  # distance of the tube's front end from the wall [mm]


def i10(v):
    return f"{v:>10d}"


def r20(v):
    return f"{v:>20.10g}"


def ruler():
    return "#---1----|----2----|----3----|----4----|----5----|----6----|----7----|----8----|----9----|---10----|\n"


def perimeter_points():
    """Points around the square section (y, z), counter-clockwise, N_SIDE per side."""
    pts = []
    h = SIDE / 2
    for k in range(N_SIDE):
        pts.append((-h + k * SIZE, -h))
    for k in range(N_SIDE):
        pts.append((h, -h + k * SIZE))
    for k in range(N_SIDE):
        pts.append((h - k * SIZE, h))
    for k in range(N_SIDE):
        pts.append((-h, h - k * SIZE))
    return pts


def self_contact_cards():
    """/SURF/PART + /INTER/TYPE7: the whole tube's nodes (group 10) against its own surface, defaults otherwise."""
    blank = " " * 10
    return ["/SURF/PART/1\ntube surface\n", i10(1) + "\n",
            "/INTER/TYPE7/1\ntube self contact\n",
            "# grnd_IDs  surf_IDm      Istf      Ithe      Igap                Ibag      Idel     Icurv      Iadm\n",
            i10(10) + i10(1) + i10(0) + i10(0) + i10(0) + blank + i10(0) + i10(0) + i10(0) + i10(0) + "\n",
            r20(0.0) + r20(0.0) + r20(0.0) + "\n",
            r20(0.0) + r20(0.0) + r20(0.0) + r20(0.0) + i10(0) + i10(0) + "\n",
            "#              Stfac                Fric              Gapmin              Tstart               Tstop\n",
            r20(0.0) + r20(0.2) + r20(0.0) + r20(0.0) + r20(0.0) + "\n",
            "       000" + " " * 20 + i10(0) + r20(0.0) + r20(0.0) + r20(0.0) + "\n",
            i10(0) + i10(0) + r20(0.0) + i10(0) + i10(0) + i10(0) + r20(0.0) + i10(0) + "\n",
            "/TH/INTER/3\nself contact\n", f"{'DEF':<10}\n", i10(1) + "\n"]


def main(self_contact=False):
    ring = perimeter_points()
    n_ring = len(ring)
    out = ["#RADIOSS STARTER\n", "# Crumple example deck, written by decks/generate_tube_impact.py\n", ruler()]
    out += ["/BEGIN\nTUBE\n", i10(2019) + i10(0) + "\n"
            f"{'kg':>20}{'mm':>20}{'ms':>20}\n", f"{'kg':>20}{'mm':>20}{'ms':>20}\n"]
    out += ["/TITLE\nSquare tube crushed against a rigid wall\n"]
    out += ["/MAT/PLAS_JOHNS/1\nmild steel\n", "#              RHO_I\n", r20(7.85e-6) + "\n",
            "#                  E                  Nu     Iflag\n", r20(210.0) + r20(0.3) + i10(0) + "\n",
            "#                  a                   b                   n           EPS_p_max            SIG_max0\n",
            r20(0.25) + r20(0.45) + r20(0.4) + r20(0.0) + r20(0.6) + "\n",
            "#                  c           EPS_DOT_0       ICC   Fsmooth               F_cut               Chard\n",
            r20(0.0) + r20(0.0) + i10(0) + i10(0) + r20(0.0) + r20(0.0) + "\n"]
    out += ["/PROP/SHELL/1\ntube wall\n",
            "#   Ishell    Ismstr     Ish3n    Idrill                            P_thick_fail\n",
            i10(24) + i10(0) + i10(0) + i10(0) + "\n",
            "#                 hm                  hf                  hr                  dm                  dn\n",
            "\n", "#        N   Istrain               Thick              Ashear              Ithick     Iplas\n",
            i10(5) + i10(0) + r20(1.2) + r20(0.0) + i10(1) + i10(1) + "\n"]
    out += ["/PART/1\ntube\n", i10(1) + i10(1) + "\n"]
    out += [ruler(), "/NODE\n"]
    node_id = {}
    nid = 1
    for j in range(N_LENGTH + 1):
        x = GAP + j * SIZE
        for k, (y, z) in enumerate(ring):
            node_id[(j, k)] = nid
            out.append(i10(nid) + r20(x) + r20(y) + r20(z) + "\n")
            nid += 1
    sled = nid  # rigid-body main node at the centre of the rear section
    out.append(i10(sled) + r20(GAP + LENGTH) + r20(0.0) + r20(0.0) + "\n")
    out += ["/SHELL/1\n"]
    eid = 1
    for j in range(N_LENGTH):
        for k in range(n_ring):
            k1 = (k + 1) % n_ring
            out.append(i10(eid) + i10(node_id[(j, k)]) + i10(node_id[(j + 1, k)]) + i10(node_id[(j + 1, k1)])
                       + i10(node_id[(j, k1)]) + "\n")
            eid += 1

    def id_list(ids):
        lines = []
        for s in range(0, len(ids), 10):
            lines.append("".join(i10(v) for v in ids[s:s + 10]) + "\n")
        return lines

    rear = [node_id[(N_LENGTH, k)] for k in range(n_ring)]
    front = [node_id[(j, k)] for j in range(N_LENGTH + 1) for k in range(n_ring)]
    out += ["/GRNOD/PART/10\nwhole tube\n", i10(1) + "\n"]
    out += ["/GRNOD/NODE/11\nrear section\n"] + id_list(rear)
    out += ["/GRNOD/NODE/12\nsled and tube\n"] + id_list(front + [sled])
    out += ["/INIVEL/TRA/1\nimpact speed\n", "#                 Vx                  Vy                  Vz   Gnod_id   Skew_id\n",
            r20(-10.0) + r20(0.0) + r20(0.0) + i10(12) + i10(0) + "\n"]
    out += ["/RBODY/1\nsled\n",
            "#     RBID     ISENS     NSKEW    ISPHER                MASS   Gnod_id     IKREM      ICOG   Surf_id\n",
            i10(sled) + i10(0) + i10(0) + i10(0) + r20(20.0) + i10(11) + i10(0) + i10(0) + i10(0) + "\n",
            r20(0.0) + r20(0.0) + r20(0.0) + "\n", r20(0.0) + r20(0.0) + r20(0.0) + "\n", i10(0) + i10(0) + "\n"]
    out += ["/RWALL/PLANE/1\nrigid wall at x = 0\n", "#  node_ID     Slide grnod_ID1 grnod_ID2\n",
            i10(0) + i10(0) + i10(10) + i10(0) + "\n",
            "#           D_search                fric            Diameter                ffac       ifq\n",
            r20(0.0) + r20(0.0) + r20(0.0) + r20(0.0) + i10(0) + "\n",
            "#                 XM                  YM                  ZM\n", r20(0.0) + r20(0.0) + r20(0.0) + "\n",
            "#               X_M1                Y_M1                Z_M1\n", r20(1.0) + r20(0.0) + r20(0.0) + "\n"]
    out += ["/TH/RWALL/1\nwall force\n", f"{'DEF':<10}\n", i10(1) + "\n"]
    out += ["/TH/RBODY/2\nsled\n", f"{'DEF':<10}\n", i10(1) + "\n"]
    if self_contact:
        out += self_contact_cards()
    out += ["/END\n"]
    here = Path(__file__).parent / ("tube_self_contact" if self_contact else "tube_impact")
    here.mkdir(exist_ok=True)
    (here / "TUBE_0000.rad").write_text("".join(out))
    engine = ["/RUN/TUBE/1\n3.0\n", "/TFILE\n0.01\n", "/ANIM/DT\n0.0 0.5\n", "/ANIM/ELEM/VONM\n", "/ANIM/ELEM/ENER\n",
              "/PRINT/-1000\n", "/DT\n0.9 0.0\n", "/STOP\n0.1 0.1 0.0 0 0 0\n"]
    (here / "TUBE_0001.rad").write_text("".join(engine))


if __name__ == "__main__":
    main()
    main(self_contact=True)
