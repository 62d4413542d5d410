# Generates the peer decks of functions (docs/deck-format.md, "Functions"; docs/theory/loads.md, L-9): a free 2 x 2
# plate of 1 mm QEPH shells, 10 x 10 mm, in kg mm ms. MOVEF: /IMPVEL along Z of every node with the function
# (-4, 1), (-3.8, 2) moved by /MOVE_FUNCT 2, 3, 8, -3 to (0, 0), (0.4, 3), run to 0.6 ms (past the moved function's
# last point). TAB36: /MAT/PLAS_TAB with the yield curve (0, 0.2), (0.01, 0.22) GPa, the plate stretched to 18 %
# (past the curve's last point). FGALL: /IMPDISP/FGEO driving every node to (1.01 x + 1, y, 0) along a ramp over
# 1 ms. Each folder's ref.extract is the reference solver's last row on its deck (run-or.sh, then or-extract.py).
# Run from this folder: python3 generate_function_decks.py
import os
I=lambda *v: "".join("%10d"%x for x in v)
R=lambda *v: "".join("%20.10g"%x for x in v)
def plate(name, material):
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
    s+=material
    s+="/GRNOD/NODE/1\nall\n"+I(*range(1,10))+"\n"
    return s
def write(name, starter, end, vers=2019):
    os.makedirs(name,exist_ok=True)
    open(f"{name}/{name}_0000.rad","w").write(starter+"/END\n")
    open(f"{name}/{name}_0001.rad","w").write(f"/RUN/{name}/1\n{end}\n/PRINT/-100\n/TFILE/4\n0.01\n/VERS/{vers}\n")
steel="/MAT/ELAST/1\nsteel\n"+R(7.85e-6)+"\n"+R(210.0,0.3)+"\n"
s=plate("MOVEF", steel)
s+="/FUNCT/2\nf\n"+R(-4,1)+"\n"+R(-3.8,2)+"\n/MOVE_FUNCT/2\nmove\n"+R(2,3,8,-3)+"\n"
s+="/IMPVEL/1\nv\n"+I(2)+"         Z"+I(0,0,1,0,0)+"\n"+R(1,1,0,0)+"\n"
write("MOVEF", s, 0.6)
tab="/MAT/PLAS_TAB/1\nsteel\n"+R(7.85e-6)+"\n"+R(210.0,0.3)+"\n"+I(1,0)+R(0,0)+"\n"+I(0)+R(0)+I(0)+"\n"+I(5)+"\n"+R(1.0)+"\n"+R(0.0)+"\n"
s=plate("TAB36", tab)
s+="/FUNCT/5\nhard\n"+R(0,0.2)+"\n"+R(0.01,0.22)+"\n"
s+="/GRNOD/NODE/2\nleft\n"+I(1,4,7)+"\n/GRNOD/NODE/3\nright\n"+I(3,6,9)+"\n"
s+="/BCS/1\nfix\n   100 000"+I(0,2)+"\n/BCS/2\nfixyz\n   011 000"+I(0,1)+"\n"
s+="/FUNCT/2\nconst\n"+R(0,1)+"\n"+R(100,1)+"\n"
s+="/IMPVEL/1\nv\n"+I(2)+"         X"+I(0,0,3,0,0)+"\n"+R(1,0.2,0,0)+"\n"
write("TAB36", s, 9.1)
s=plate("FGALL", steel)
s+="/FUNCT/1\nramp\n"+R(0,0)+"\n"+R(1,1)+"\n"
s+="/IMPDISP/FGEO/10\nfgeo\n"+I(1,0,0,0)+"\n"+R(1.0)+"%20s"%""+R(0,0)+"\n"
for j in range(3):
    for i in range(3):
        s+=I(1+i+3*j)+R(5.0*i*1.01+1.0, 5.0*j, 0.0)+"\n"
write("FGALL", s, 1.0)
