# Generates the peer decks of /PROP/TYPE45 (KJOINT2) spherical joints between two rigid bodies (docs/theory/spring.md,
# SP-25): each body one brick of steel carried by a /RBODY, the joint a /SPRING between a node of each body; the
# bodies hold no deformable element, so /DTIX sets the step the joint's automatic stiffness is taken at. Run from the
# folder that is to hold the decks; each folder's ref.extract is the reference solver's last printed row on its deck
# (run-or.sh, then or-extract.py).
#   joint_pendulum: body 1 held by /BCS, body 2 swung about the joint by its initial velocity and /GRAV; free
#     rotations with stiffness (and one with damping), Cr 0.02; the blocking stiffness set by the inertia term.
#   joint_free_bodies: two free bodies of different masses (a /RBODY mass on one, Ispher 1 and ICoG 3 on the other)
#     driven apart and about by their initial velocities, ScF 2, Cr left at its default 0.05; the joint node off
#     both bodies' centres.
#   joint_revolute: the pendulum's bodies on a revolute joint (Type 2) whose axis, set by the /SPRING card's third
#     node, is tilted out of the global axes; the swung body also spun across the axis, so that the blocked rotations
#     ring on their automatic stiffness and damping while the free one turns on its law.
#   joint_cylindrical, joint_planar, joint_translational, joint_oldham, joint_rigid: joint_revolute's bodies and
#     motion on the joints of Type 3, 4, 6, 7 and 8 (SP-25g), each free translation a linear law of its own
#     (stiffness 1e4 N/m and up, a damping on the second), each free rotation the revolute's.
#   joint_spherical_axis: the spherical joint given the third node, which turns its frame (SP-25f), its three free
#     rotations each of a different stiffness.
#   joint_universal, joint_free: the same bodies and motion on the joints of Type 5 and 9, whose frame the /SPRING
#     card's third and fourth nodes set (SP-25f).
#   joint_cylindrical_skew: the cylindrical joint whose frame a /SKEW/FIX sets (Skew_ID1, no third node; SP-25f).
#   joint_revolute_given_kn, joint_revolute_given_kn_scf: the revolute joint of joint_revolute's motion with a given
#     blocking stiffness Kn (5e4 N/m, ScF blank: 10; 1e5 N/m, ScF 2; SP-25i).
import os
I = lambda *v: "".join("%10d" % x for x in v)
R = lambda *v: "".join("%20.10g" % x for x in v)


def brick_nodes(first, x0, x1, h):
    out, k = "", first
    for x in (x0, x1):
        for y, z in ((-h, -h), (h, -h), (h, h), (-h, h)):
            out += I(k) + R(x, y, z) + "\n"
            k += 1
    return out


def rbody(rid, main, group, ispher=0, mass=0.0, icog=0):
    return ("/RBODY/%d\nbody %d\n" % (rid, rid) + I(main, 0, 0, ispher) + R(mass) + I(group, 0, icog, 0) + "\n"
            + R(0, 0, 0) + "\n" + R(0, 0, 0) + "\n" + I(0, 0) + "\n")


def free_dof(k, c=0.0):  # a free degree of freedom's three lines: K, fct_K, S-, S+, Icomb; C, fct_C; Kf, F, fct_F
    return R(k) + I(0) + R(0, 0) + I(0) + "\n" + R(c) + I(0) + "\n" + R(0, 0) + I(0) + "\n"


def deck(name, run, joint_at, second, scale, critical, rotations, bodies, loads, end, dt, joint_type=1, axis_node=None,
         translations=(), plane_node=None, skew=None, kn=0.0):
    s = "/BEGIN\n%s\n      2019         0\n%20s%20s%20s\n%20s%20s%20s\n" % (run, 'kg', 'm', 's', 'kg', 'm', 's')
    s += "/MAT/ELAST/1\nsteel\n" + R(7800) + "\n" + R(2.1e11, 0.3) + "\n"
    s += "/NODE\n" + I(1) + R(*joint_at) + "\n" + I(2) + R(*joint_at) + "\n" + I(5) + R(-0.15, 0, 0) + "\n"
    if axis_node:
        s += I(3) + R(*axis_node) + "\n"
    if plane_node:
        s += I(4) + R(*plane_node) + "\n"
    s += I(6) + R(*second) + "\n" + brick_nodes(11, -0.2, -0.1, 0.05) + brick_nodes(21, 0.1, 0.3, 0.05)
    s += "/PART/1\njoint\n" + I(1, 0) + "\n/SPRING/1\n" + I(30, 1, 2, *((3,) if axis_node else ()), *((4,) if plane_node else ())) + "\n"
    s += "/PART/2\nbodies\n" + I(2, 1) + "\n/BRICK/2\n" + I(10, *range(11, 19)) + "\n" + I(20, *range(21, 29)) + "\n"
    s += "/PROP/SOLID/2\nbricks\n" + I(0) + "\n" + R(0) + "\n" + R(0) + "\n"
    s += "/PROP/TYPE45/1\njoint\n" + I(joint_type) + R(kn, scale, critical) + I(0, 7 if skew else 0, 0) + "\n"
    for k, c in tuple(translations) + tuple(rotations):  # the free translations' lines first, then the rotations'
        s += free_dof(k, c)
    s += "/GRNOD/NODE/8\nbody 1\n" + I(1, *range(11, 19)) + "\n/GRNOD/NODE/9\nbody 2\n" + I(2, *range(21, 29)) + "\n"
    s += bodies + loads
    if skew:  # /SKEW/FIX/7: the origin, the direction of Y', a direction in the Y'Z' plane
        s += "/SKEW/FIX/7\njoint frame\n" + R(0, 0, 0) + "\n" + R(*skew[0]) + "\n" + R(*skew[1]) + "\n"
    s += "/TH/SPRING/1\njoint\nDEF       \n" + I(30) + "\n/TH/RBODY/2\nbodies\nDEF       \n" + I(1, 2) + "\n/END\n"
    os.makedirs(name, exist_ok=True)
    open(os.path.join(name, run + "_0000.rad"), "w").write(s)
    open(os.path.join(name, run + "_0001.rad"), "w").write(
        "/RUN/%s/1\n%g\n/TFILE\n%g\n/PRINT/-200\n/DTIX\n%g %g\n" % (run, end, end / 200, dt, dt))


if __name__ == "__main__":
    deck("joint_pendulum", "JPEND", (0, 0, 0), (0.2, 0, 0), 0, 0.02, ((10, 0), (20, 0.5), (30, 0)),
         rbody(1, 5, 8) + rbody(2, 6, 9) + "/GRNOD/NODE/3\nheld\n" + I(5) + "\n/BCS/1\nheld\n   111 111" + I(0, 3) + "\n",
         "/GRNOD/NODE/4\nswung\n" + I(6) + "\n/INIVEL/TRA/1\nswing\n" + R(0, 1.0, 2.0) + I(4, 0) + "\n"
         + "/FUNCT/7\none\n" + R(0, 1) + "\n" + R(100, 1) + "\n/GRAV/1\ngravity\n" + I(7) + "%10s" % "Z" + I(0, 0, 0)
         + " " * 10 + R(0, -9.81) + "\n", 0.5, 1e-4)
    deck("joint_free_bodies", "JFREE", (0.02, 0.01, 0), (0.0, 0, 0), 2, 0, ((0, 0), (0, 0), (50, 0)),
         rbody(1, 5, 8, mass=200.0) + rbody(2, 6, 9, ispher=1, icog=3),
         "/GRNOD/NODE/3\nfirst\n" + I(5) + "\n/GRNOD/NODE/4\nsecond\n" + I(6) + "\n"
         + "/INIVEL/TRA/1\nfirst\n" + R(-1.0, 0.5, 0) + I(3, 0) + "\n/INIVEL/TRA/2\nsecond\n" + R(1.5, 0, -1.0) + I(4, 0) + "\n"
         + "/INIVEL/ROT/3\nsecond spins\n" + R(0, 0, 2.0) + I(4, 0) + "\n", 0.3, 5e-5)
    deck("joint_revolute", "JREV", (0, 0, 0), (0.2, 0, 0), 0, 0.03, ((15, 0.2),),
         rbody(1, 5, 8) + rbody(2, 6, 9) + "/GRNOD/NODE/3\nheld\n" + I(5) + "\n/BCS/1\nheld\n   111 111" + I(0, 3) + "\n",
         "/GRNOD/NODE/4\nswung\n" + I(6) + "\n/INIVEL/TRA/1\nswing\n" + R(0, 1.0, 2.0) + I(4, 0) + "\n"
         + "/INIVEL/ROT/2\nacross\n" + R(0, 3.0, 0) + I(4, 0) + "\n"
         + "/FUNCT/7\none\n" + R(0, 1) + "\n" + R(100, 1) + "\n/GRAV/1\ngravity\n" + I(7) + "%10s" % "Z" + I(0, 0, 0)
         + " " * 10 + R(0, -9.81) + "\n", 0.3, 1e-4, joint_type=2, axis_node=(0.3, 0.1, 1.0))
    swung = ("/GRNOD/NODE/4\nswung\n" + I(6) + "\n/INIVEL/TRA/1\nswing\n" + R(0, 1.0, 2.0) + I(4, 0) + "\n"
             + "/INIVEL/ROT/2\nacross\n" + R(0, 3.0, 0) + I(4, 0) + "\n"
             + "/FUNCT/7\none\n" + R(0, 1) + "\n" + R(100, 1) + "\n/GRAV/1\ngravity\n" + I(7) + "%10s" % "Z"
             + I(0, 0, 0) + " " * 10 + R(0, -9.81) + "\n")
    held = rbody(1, 5, 8) + rbody(2, 6, 9) + "/GRNOD/NODE/3\nheld\n" + I(5) + "\n/BCS/1\nheld\n   111 111" + I(0, 3) + "\n"
    # name, run, Type, free translations, free rotations (as many groups as the type frees)
    for name, run, joint_type, free_t, free_r in (("joint_cylindrical", "JCYL", 3, 1, 1), ("joint_planar", "JPLA", 4, 2, 1),
                                                  ("joint_translational", "JTRA", 6, 1, 0), ("joint_oldham", "JOLD", 7, 2, 0),
                                                  ("joint_rigid", "JRIG", 8, 0, 0), ("joint_spherical_axis", "JSPA", 1, 0, 3),
                                                  ("joint_universal", "JUNI", 5, 0, 2), ("joint_free", "JFRE", 9, 3, 3),
                                                  ("joint_cylindrical_skew", "JCSK", 3, 1, 1)):
        translations = [(1e4 * (1 + i), 10.0 * i) for i in range(free_t)]
        rotations = [(15.0 * (1 + i), 0.2) for i in range(free_r)]
        deck(name, run, (0, 0, 0), (0.2, 0, 0), 0, 0.03, rotations, held, swung, 0.3, 1e-4, joint_type=joint_type,
             axis_node=None if name.endswith("_skew") else (0.3, 0.1, 1.0), translations=translations,
             plane_node=(0.2, 1.0, 0.3) if joint_type in (5, 9) else None,
             skew=((1, 1, 0), (-1, 1, 0.2)) if name.endswith("_skew") else None)
    # SP-25i: a given Kn, the rotations' stiffness ScF Kn (ScF blank: 10); joint_revolute's bodies and motion.
    for name, run, kn, scale in (("joint_revolute_given_kn", "JRKN", 5e4, 0), ("joint_revolute_given_kn_scf", "JRKS", 1e5, 2)):
        deck(name, run, (0, 0, 0), (0.2, 0, 0), scale, 0.03, ((15, 0.2),), held, swung, 0.3, 1e-4, joint_type=2,
             axis_node=(0.3, 0.1, 1.0), kn=kn)
