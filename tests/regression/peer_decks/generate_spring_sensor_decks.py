# Generates the peer deck of springs switched by a sensor (docs/theory/spring.md, SP-24): five springs, each from a
# clamped node to a free 1 kg node launched at (1, 0.5, 0.2) m/s, and a clamped control spring that bounds the step
# while the others idle. Run from the folder that is to hold the deck; ref.extract is the reference solver's last
# printed row on it (run-or.sh, then or-extract.py).
#   spring_sensor_switches: /PROP/TYPE4 with Isflag 0 (on at 0.3 s, for good, its rest the length at t = 0), 1 (gone
#   at 0.3 s) and 2 (on from 0.2 s to 0.6 s, its rest the length it had when it came on); /PROP/TYPE8 with Isflag 0
#   and /PROP/TYPE13 with Isflag 1, all dofs acting.
#   spring_sensor_rest_anew: /PROP/TYPE8 and /PROP/TYPE13 with Isflag 2 (on from 0.2 s to 0.6 s, each of their six
#   laws' rest the deformation it had when it came on, SP-24b), beside the TYPE4 of Isflag 2 and 0.
import os
I = lambda *v: "".join("%10d" % x for x in v)
R = lambda *v: "".join("%20.10g" % x for x in v)


def law(k, c=0.0):
    return R(k, c) + "\n" + I(0) + "\n" + R(0) + "\n"


def prop4(pid, sensor, flag, mass=0.01):
    return "/PROP/TYPE4/%d\nspring\n" % pid + R(mass) + " " * 30 + I(sensor, flag, 0) + "\n" + law(1000.0, 2.0)


def prop6(pid, card, sensor, flag):
    s = "/PROP/%s/%d\nsix laws\n" % (card, pid) + R(0.01, 0.001) + I(0, sensor, flag, 0, 0, 0) + "\n"
    s += "".join(law(k) for k in (1000.0, 800.0, 600.0, 10.0, 8.0, 6.0))
    return s + (I(0) + R(0) + "\n" if card == "TYPE8" else R(0, 0, 0) + I(0) + "\n")


def deck(name, run, props):
    s = "/BEGIN\n%s\n      2023         0\n%20s%20s%20s\n%20s%20s%20s\n" % (run, 'kg', 'm', 's', 'kg', 'm', 's')
    s += "/NODE\n" + "".join(I(2 * i + 1) + R(0, i, 0) + "\n" + I(2 * i + 2) + R(0.5, i, 0) + "\n" for i in range(6))
    for i, p in enumerate(props):
        s += "/SPRING/%d\n" % (i + 1) + I(i + 1, 2 * i + 1, 2 * i + 2) + "\n/PART/%d\npart\n" % (i + 1) + I(i + 1, 0) + "\n" + p
    s += "/SENSOR/TIME/1\non at 0.3\n" + R(0.3) + "\n" + R(0.0) + "\n"
    s += "/SENSOR/TIME/2\non from 0.2 to 0.6\n" + R(0.2) + "\n" + R(0.6) + "\n"
    s += "/GRNOD/NODE/1\nclamped\n" + I(1, 3, 5, 7, 9, 11, 12) + "\n/GRNOD/NODE/2\nfree\n" + I(2, 4, 6, 8, 10) + "\n"
    s += "/BCS/1\nclamped\n   111 111" + I(0, 1) + "\n"
    s += "/ADMAS/0/1\nfree\n" + R(1.0) + I(2) + "\n"
    s += "/INIVEL/TRA/1\nlaunched\n" + R(1.0, 0.5, 0.2) + I(2) + "\n"
    s += "/TH/SPRING/1\nsprings\nDEF       \n" + "".join(I(i) + "\n" for i in range(1, 6)) + "/END\n"
    os.makedirs(name, exist_ok=True)
    open(os.path.join(name, run + "_0000.rad"), "w").write(s)
    open(os.path.join(name, run + "_0001.rad"), "w").write("/RUN/%s/1\n0.9\n/TFILE\n0.01\n/PRINT/-1\n/DT\n0.9 0\n" % run)  # every cycle: the last row at the end


deck("spring_sensor_switches", "SPRSENS", [prop4(1, 1, 0), prop4(2, 1, 1), prop4(3, 2, 2), prop6(4, "TYPE8", 1, 0),
                                          prop6(5, "TYPE13", 1, 1), prop4(6, 0, 0, mass=0.001)])
deck("spring_sensor_rest_anew", "SPRANEW", [prop4(1, 1, 0), prop6(2, "TYPE8", 2, 2), prop4(3, 2, 2),
                                            prop6(4, "TYPE8", 1, 0), prop6(5, "TYPE13", 2, 2), prop4(6, 0, 0, mass=0.001)])
