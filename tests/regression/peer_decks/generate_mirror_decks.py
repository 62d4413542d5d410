# Generates the peer deck of a mirrored brick (docs/deck-format.md, "Transformations"): a 1 mm steel cube in kg mm ms,
# its bottom face held, its top pushed down at 0.01 mm/ms, written the right way out and then mirrored by
# /TRANSFORM/SYM, which turns it inside out. The reference reads it as the cube as written (the same listing to the
# last digit); ref.extract is its last row on MIRROR (run-or.sh, then or-extract.py).
# Run from this folder: python3 generate_mirror_decks.py
import os
I=lambda *v: "".join("%10d"%x for x in v)
R=lambda *v: "".join("%20.10g"%x for x in v)
def deck(name, mirror):
    s="/BEGIN\n%s\n%10d         0\n%20s%20s%20s\n%20s%20s%20s\n"%(name,2019,'kg','mm','ms','kg','mm','ms')
    s+="/NODE\n"
    c=[(0,0,0),(1,0,0),(1,1,0),(0,1,0),(0,0,1),(1,0,1),(1,1,1),(0,1,1)]
    for k,(x,y,z) in enumerate(c): s+=I(k+1)+R(x,y,z)+"\n"
    s+="/BRICK/1\n"+I(1,1,2,3,4,5,6,7,8)+"\n"
    s+="/PART/1\nblock\n"+I(1,1)+"\n/PROP/SOLID/1\nsolid\n"+I(1)+"\n"
    s+="/MAT/ELAST/1\nsteel\n"+R(7.85e-6)+"\n"+R(210.0,0.3)+"\n"
    s+="/GRNOD/NODE/1\nall\n"+I(*range(1,9))+"\n/GRNOD/NODE/2\nbottom\n"+I(1,2,3,4)+"\n/GRNOD/NODE/3\ntop\n"+I(5,6,7,8)+"\n"
    s+="/BCS/1\nfix\n   111 000"+I(0,2)+"\n"
    s+="/FUNCT/1\nc\n"+R(0,1)+"\n"+R(100,1)+"\n"
    s+="/IMPVEL/1\nv\n"+I(1)+"         Z"+I(0,0,3,0,0)+"\n"+R(1,-0.01,0,0)+"\n"
    if mirror: s+="/TRANSFORM/SYM/1\nmirror\n"+I(1)+R(2,0,0)+I(0,0)+"\n"+"%10s"%""+R(3,0,0)+"\n"
    s+="/END\n"
    os.makedirs(name,exist_ok=True)
    open(f"{name}/{name}_0000.rad","w").write(s)
    open(f"{name}/{name}_0001.rad","w").write(f"/RUN/{name}/1\n5.0\n/PRINT/-500\n/TFILE/4\n0.01\n/VERS/2019\n")
deck("MIRROR", True)
