# Generates the peer decks of conditions and loads in a skew (docs/theory/skews.md, SK-5, SK-6): a free 2 x 2 plate
# of 1 mm QEPH shells in kg mm ms, a /SKEW/FIX turned 30 degrees about Z, a ramp load on every node. SKEWBCS: /BCS
# holding the skew's Y' on every node, a /CLOAD along X' and a /GRAV along Y' in the skew (only the X' load may
# move the plate); SKEWBCSG: the same /BCS with a /CLOAD along the global X (its X' share moves the plate). Each
# folder's ref.extract is the reference solver's last row on its deck (run-or.sh, then or-extract.py).
# Run from this folder: python3 generate_skew_decks.py
import os, math
I=lambda *v: "".join("%10d"%x for x in v)
R=lambda *v: "".join("%20.10g"%x for x in v)
def deck(name, bcs="", load=""):
    s="/BEGIN\n%s\n%10d         0\n%20s%20s%20s\n%20s%20s%20s\n"%(name,2019,'kg','mm','ms','kg','mm','ms')
    s+="/NODE\n"
    for j in range(3):
        for i in range(3):
            s+=I(1+i+3*j)+R(5.0*i,5.0*j,0.0)+"\n"
    s+="/SHELL/1\n"
    e=1
    for j in range(2):
        for i in range(2):
            n1=1+i+3*j; s+=I(e,n1,n1+1,n1+4,n1+3)+"\n"; e+=1
    s+="/PART/1\nplate\n"+I(1,1)+"\n"
    s+="/PROP/SHELL/1\nshell\n"+I(24,0)+"\n"+R(0,0,0,0,0)+"\n"+I(5,0)+R(1.0)+"\n"
    s+="/MAT/ELAST/1\nsteel\n"+R(7.85e-6)+"\n"+R(210.0,0.3)+"\n"
    s+="/GRNOD/NODE/1\nall\n"+I(*range(1,10))+"\n"
    s+="/FUNCT/1\nramp\n"+R(0,0)+"\n"+R(100,100)+"\n"
    a=math.radians(30)
    # skew 5: Y' = (-sin a, cos a, 0) rotated 30 deg about z, Z' in the plane with (0,0,1)
    s+="/SKEW/FIX/5\nrot30\n"+R(0,0,0)+"\n"+R(-math.sin(a),math.cos(a),0)+"\n"+R(0,0,1)+"\n"
    s+=bcs+load
    s+="/END\n"
    os.makedirs(name,exist_ok=True)
    open(f"{name}/{name}_0000.rad","w").write(s)
    open(f"{name}/{name}_0001.rad","w").write(f"/RUN/{name}/1\n1.0\n/PRINT/-100\n/TFILE/4\n0.01\n/DT\n0.9 0\n/VERS/2019\n")
# loads: CLOAD along skew X (1 mN per node ramp), GRAV along skew Y, BCS fixing skew Y translation on all nodes
cload="/CLOAD/1\nload\n"+I(1)+"         X"+I(5,0,1,0)+R(1.0,1e-3)+"\n"
grav="/GRAV/1\ng\n"+I(1)+"         Y"+I(5,0,1,0)+R(1.0,1.0)+"\n"
bcs="/BCS/1\nfixY\n   010 000"+I(5,1)+"\n"
deck("SKEWBCS", bcs=bcs, load=cload+grav)
cload2="/CLOAD/1\nload\n"+I(1)+"         X"+I(0,0,1,0)+R(1.0,1e-3)+"\n"
deck("SKEWBCSG", bcs=bcs, load=cload2)
