# Generates the peer deck of //SUBMODEL (docs/deck-format.md, "Submodels"): a free 2 x 2 plate of 1 mm QEPH shells in
# kg mm ms, the same plate 10 mm higher and 2 mm thick in a block with off_def 1000, off_nod 100, off_ele 200,
# off_part 10, off_mat 20, off_type 30, and a third one 3 mm thick in a nested block with off_def 5000. Every block
# writes its cards with the same ids (1) and gives its own group 1 an /INIVEL of +1 mm/ms along Z; the main deck's
# /INIVEL/2 gives group 1 (the first plate) -1. Wrong offsets would move the wrong plate or none: the kinetic
# energy, 0.5 (m1 + m2 + m3) v^2, tells. ref.extract is the reference solver's last row (run-or.sh, or-extract.py).
# Run from this folder: python3 generate_submodel_decks.py
import os
I=lambda *v: "".join("%10d"%x for x in v)
R=lambda *v: "".join("%20.10g"%x for x in v)
def plate(z, t):
    s="/NODE\n"
    for j in range(3):
        for i in range(3):
            s+=I(1+i+3*j)+R(5.0*i,5.0*j,z)+"\n"
    s+="/SHELL/1\n"
    e=1
    for j in range(2):
        for i in range(2):
            n1=1+i+3*j; s+=I(e,n1,n1+1,n1+4,n1+3)+"\n"; e+=1
    s+="/PART/1\nplate\n"+I(1,1)+"\n"
    s+="/PROP/SHELL/1\nshell\n"+I(24,0)+"\n"+R(0,0,0,0,0)+"\n"+I(5,0)+R(t)+"\n"
    s+="/MAT/ELAST/1\nsteel\n"+R(7.85e-6)+"\n"+R(210.0,0.3)+"\n"
    s+="/GRNOD/NODE/1\nall\n"+I(*range(1,10))+"\n"
    return s
inivel=lambda k, vz: "/INIVEL/TRA/%d\nv\n"%k+R(0,0,vz)+I(1)+"\n"
name="SUBNEST"
s="/BEGIN\n%s\n%10d         0\n%20s%20s%20s\n%20s%20s%20s\n"%(name,2019,'kg','mm','ms','kg','mm','ms')
s+=plate(0.0, 1.0)
s+="//SUBMODEL/1\nblock\n"+I(1000,100,200,10,20,30,0)+"\n"+plate(10.0, 2.0)+inivel(1, 1.0)
s+="//SUBMODEL/2\ninner\n"+I(5000,0,0,0,0,0,0)+"\n"+plate(20.0, 3.0)+inivel(1, 1.0)+"//ENDSUB\n"
s+="//ENDSUB\n"+inivel(2, -1.0)+"/END\n"
os.makedirs(name,exist_ok=True)
open(f"{name}/{name}_0000.rad","w").write(s)
open(f"{name}/{name}_0001.rad","w").write(f"/RUN/{name}/1\n0.1\n/PRINT/-10\n/TFILE/4\n0.01\n/VERS/2019\n")
