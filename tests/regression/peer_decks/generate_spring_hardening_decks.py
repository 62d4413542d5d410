# Generates the peer decks of /PROP/TYPE4 hardening springs (docs/theory/spring.md, SP-6, SP-7): one spring along y,
# node 1 fixed, node 2 driven by /IMPVEL at 0.1 m/s out to 0.05 m, back to -0.05 m and out again, on the curve
# f = 20 N at 0.01 m then 500 N/m (odd about 0), K = 2000 N/m for unloading. Run from the folder that is to hold the
# decks; each folder's ref.extract is the reference solver's last printed row (run-or.sh, then or-extract.py).
#   spring_hardening_isotropic (H 1), spring_hardening_uncoupled (H 2) and spring_hardening_kinematic (H 4, its
#   own two curves): the internal energy at every 100th row is the reference's to its 4 digits (6.915, 2.197 and
#   4.420 J at the end); the force the energy's slope gives, cycle by
#   cycle, follows the reference's through the reversals (tension, unloading, reverse yield, reloading).
#   spring_hardening_residual (H 5, the residual elongation half the largest), spring_hardening_unloading_curve (H 6),
#   spring_hardening_hysteresis (H 7) and spring_total_length (H 8): Crumple's row n + 1 carries the reference's row
#   n internal energy to its 4 digits (the listing's lag, docs/theory/spring.md).
import os
I=lambda *v: "".join("%10d"%x for x in v)
R=lambda *v: "".join("%20.10g"%x for x in v)
def deck(name, H=1, K=2000.0, pts=((-1,-30),(-0.01,-20),(0,0),(0.01,20),(1,30)), fct2=0, pts2=None, fct3=0, pts3=None,
         vel=((0,0.1),(0.5,0.1),(0.5001,-0.1),(1.5,-0.1),(1.5001,0.1),(2.5,0.1)), tend=2.5, scale=0.1):
    d="/BEGIN\n%s\n      2019         0\n%20s%20s%20s\n%20s%20s%20s\n"%("SPRH%d" % H,'kg','m','s','kg','m','s')
    d+="/NODE\n"+I(1)+R(0,0,0)+"\n"+I(2)+R(0,1,0)+"\n"
    d+="/BCS/1\nfix\n   111 111"+I(0,1)+"\n/GRNOD/NODE/1\nfix\n"+I(1)+"\n/BCS/2\nfree\n   101 111"+I(0,2)+"\n/GRNOD/NODE/2\nfree\n"+I(2)+"\n"
    d+="/PART/1\nspring\n"+I(4,0,0)+"\n/SPRING/1\n"+I(1,1,2)+"\n"
    d+="/PROP/SPRING/4\nspr\n"+R(2.0)+" "*30+I(0,0,0)+"\n"+R(K,0,1,0,0)+"\n"+I(1,H,fct2,fct3,0)+" "*10+R(0,0)+"\n"+R(0,0,0,0)+"\n"
    d+="/FUNCT/1\nf\n"+"".join(R(x,y)+"\n" for x,y in pts)
    if fct2: d+="/FUNCT/%d\ng\n"%fct2+"".join(R(x,y)+"\n" for x,y in pts2)
    if fct3: d+="/FUNCT/%d\nh\n"%fct3+"".join(R(x,y)+"\n" for x,y in pts3)
    d+="/FUNCT/9\nv\n"+"".join(R(x,y)+"\n" for x,y in vel)
    d+="/IMPVEL/1\nv\n"+I(9)+"         Y"+I(0,0,2)+"\n"+R(1,1,0,0)+"\n/END\n"
    os.makedirs(name, exist_ok=True)
    open(f"{name}/{name}_0000.rad","w").write(d)
    run = "SPRH%d" % H
    os.rename(f"{name}/{name}_0000.rad", f"{name}/{run}_0000.rad")
    open(f"{name}/{run}_0001.rad","w").write(f"/RUN/{run}/1\n{tend}\n/PRINT/-100\n/TFILE/4\n0.0\n/DT\n{scale} 0\n")
CURVE = ((-1, -515), (-0.01, -20), (0, 0), (0.01, 20), (1, 515))
deck("spring_hardening_isotropic", H=1, pts=CURVE)
deck("spring_hardening_uncoupled", H=2, pts=CURVE)
# kinematic (H 4): the force between a lower and an upper curve, 20 N either side of a 500 N/m line
# residual (H 5): unloading to the residual elongation fct_ID31(delta_max) = delta_max / 2 on each side (SP-11)
deck("spring_hardening_residual", H=5, pts=CURVE, fct3=3, pts3=((-1, -0.5), (0, 0), (1, 0.5)))
# unloading curve (H 6) and hysteresis (H 7): unloading along the curve fct_ID31, 5 N at 0.01 m then 197 N/m (SP-12,
# SP-13); total length (H 8): the force f(l0 + delta) of the length itself, 1 m at rest (SP-14)
UNLOADING = ((-1, -200), (-0.01, -5), (0, 0), (0.01, 5), (1, 200))
deck("spring_hardening_unloading_curve", H=6, pts=CURVE, fct3=3, pts3=UNLOADING)
deck("spring_hardening_hysteresis", H=7, pts=CURVE, fct3=3, pts3=UNLOADING)
deck("spring_total_length", H=8, pts=((0, 0), (0.9, 100), (1.1, 300), (2, 400)))
deck("spring_hardening_kinematic", H=4, pts=((-1, -480), (0, 20), (1, 520)), fct3=3, pts3=((-1, -520), (0, -20), (1, 480)))
