# Generates the peer deck wall_pushes_rigid_body (docs/theory/rigid-walls.md, RW-0 and RW-3): a 40 x 40 x 100 mm
# Johnson-Cook tube of 640 QEPH shells whose top ring is a rigid body, crushed 30 mm by a moving /RWALL/PARAL of
# 50 kg at 10 m/s whose only secondary node is the body's main node; the bottom ring stands on a fixed
# /RWALL/PLANE that selects its nodes by D_search alone (grnod_ID1 = 0). Run from the folder that is to hold WRB/.
import os
I=lambda *v: "".join("%10d"%x for x in v)
R=lambda *v: "".join("%20.10g"%x for x in v)
def gen(name, dsearch_bottom=True):
    a=40.0; h=100.0; n=8; nz=20
    nodes={}; nid=1
    ring=[]
    for side in range(4):
        for k in range(n):
            t=k/n
            if side==0: p=(-a/2+a*t, -a/2)
            elif side==1: p=(a/2, -a/2+a*t)
            elif side==2: p=(a/2-a*t, a/2)
            else: p=(-a/2, a/2-a*t)
            ring.append(p)
    ids=[]
    for j in range(nz+1):
        row=[]
        for (x,y) in ring:
            nodes[nid]=(x,y,h*j/nz); row.append(nid); nid+=1
        ids.append(row)
    shells=[]; eid=1
    m=len(ring)
    for j in range(nz):
        for i in range(m):
            shells.append((eid, ids[j][i], ids[j][(i+1)%m], ids[j+1][(i+1)%m], ids[j+1][i])); eid+=1
    main=9000; nodes[main]=(0.0,0.0,h)
    s="/BEGIN\n%s\n      2019         0\n%20s%20s%20s\n%20s%20s%20s\n"%(name,'kg','mm','ms','kg','mm','ms')
    s+="/NODE\n"+"".join(I(k)+R(*v)+"\n" for k,v in nodes.items())
    s+="/SHELL/1\n"+"".join(I(*e)+"\n" for e in shells)
    s+="/PART/1\ntube\n"+I(1,1)+"\n"
    s+="/PROP/SHELL/1\nshell\n"+I(24,0)+"\n"+R(0,0,0,0,0)+"\n"+I(5,0)+R(1.5)+"\n"
    s+="/MAT/PLAS_JOHNS/1\nsteel\n"+R(7.85e-6)+"\n"+R(210.0,0.3)+"\n"+R(0.3,0.5,0.3)+"\n"
    def grp(gid, lst, title):
        out="/GRNOD/NODE/%d\n%s\n"%(gid,title)
        for i in range(0,len(lst),10): out+=I(*lst[i:i+10])+"\n"
        return out
    s+=grp(1, ids[-1], "top")+grp(2,[main],"main")+grp(3, ids[0], "bottom")
    s+="/RBODY/1\ntop\n"+I(main,0,0,0)+R(0)+I(1,0,0,0)+"\n"+R(0,0,0)+"\n"+R(0,0,0)+"\n"+I(0,0)+"\n"
    s+="/RWALL/PARAL/1\nmoving\n"+I(9001,0,2,0)+"\n"+R(0,0,0)+"\n"+R(50.0,0,0,-10)+"\n"+R(-100,100,105)+"\n"+R(100,-100,105)+"\n"
    if dsearch_bottom:
        s+="/RWALL/PLANE/2\nfloor\n"+I(0,1,0,0)+"\n"+R(1.0,0,0)+"\n"+R(0,0,0)+"\n"+R(0,0,1)+"\n"
    else:
        s+="/BCS/1\nbottom\n   111 111"+I(0,3)+"\n"
    s=s.replace("/RWALL/PARAL/1","/NODE\n"+I(9001)+R(-100,-100,105)+"\n/RWALL/PARAL/1")
    s+="/END\n"
    os.makedirs(name,exist_ok=True)
    open(f"{name}/{name}_0000.rad","w").write(s)
    open(f"{name}/{name}_0001.rad","w").write(f"/RUN/{name}/1\n3.0\n/PRINT/-200\n/TFILE/4\n0.01\n/DT\n0.9 0\n/VERS/2019\n")
if __name__ == "__main__":
    # The deck of wall_pushes_rigid_body (its ref.extract: the reference solver on it, run-or.sh then or-extract.py).
    gen("WRB")
