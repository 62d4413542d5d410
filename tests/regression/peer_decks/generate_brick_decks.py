# Generates the peer decks of degenerate bricks (docs/theory/brick8.md, "Degenerate bricks", eqs. B-2b and B-12a):
# a 100 x 20 x 20 mm elastic bar, clamped at x = 0 and pulled at 5 m/s at x = 100 for 0.2 ms, meshed in hexahedra cut
# into prisms (Isolid 14), tetrahedra (Isolid 1) or pyramids around each cell's centre (Isolid 1), each written as
# 8-node bricks with repeated nodes. Each folder's ref.extract is the reference solver's last row on its deck.
# Run from the folder that is to hold the decks: python3 generate_brick_decks.py
def vol(a,b,c,d):
    u=[b[i]-a[i] for i in range(3)]; v=[c[i]-a[i] for i in range(3)]; w=[d[i]-a[i] for i in range(3)]
    return u[0]*(v[1]*w[2]-v[2]*w[1])-u[1]*(v[0]*w[2]-v[2]*w[0])+u[2]*(v[0]*w[1]-v[1]*w[0])
import os, sys
I=lambda *v: "".join("%10d"%x for x in v)
R=lambda *v: "".join("%20.10g"%x for x in v)
def gen(name, kind, nx=10, ny=2, nz=2, L=100.0, W=20.0, isolid=0, law='elast', v=5.0, tend=0.2, icpre=0, push='X',
        print_every=20):
    nodes={}; nid=lambda i,j,k: 1+i+(nx+1)*(j+(ny+1)*k)
    for k in range(nz+1):
        for j in range(ny+1):
            for i in range(nx+1):
                nodes[nid(i,j,k)]=(L*i/nx, W*j/ny, W*k/nz)
    els=[]; e=1
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                n=[nid(i,j,k),nid(i+1,j,k),nid(i+1,j+1,k),nid(i,j+1,k),nid(i,j,k+1),nid(i+1,j,k+1),nid(i+1,j+1,k+1),nid(i,j+1,k+1)]
                if kind=='hex': els.append((e,*n)); e+=1
                elif kind=='prism':
                    # split the hex along the diagonal of its x-y faces: two prisms with triangular bases in x-y, extruded in z
                    a,b,c,d,A,B,C,D=n
                    els.append((e,a,b,c,c,A,B,C,C)); e+=1
                    els.append((e,a,c,d,d,A,C,D,D)); e+=1
                elif kind=='pyr':
                    a,b,c,d,A,B,C,D=n
                    ctr=len(nodes)+100000+e
                    nodes[ctr]=tuple(sum(nodes[k][c] for k in n)/8.0 for c in range(3))
                    for f in [(a,d,c,b),(A,B,C,D),(a,b,B,A),(b,c,C,B),(c,d,D,C),(d,a,A,D)]:
                        P=[nodes[k] for k in f]; apex=nodes[ctr]
                        d1=[P[2][i]-P[0][i] for i in range(3)]; d2=[P[3][i]-P[1][i] for i in range(3)]
                        nrm=[d1[1]*d2[2]-d1[2]*d2[1], d1[2]*d2[0]-d1[0]*d2[2], d1[0]*d2[1]-d1[1]*d2[0]]
                        cen=[sum(P[j][i] for j in range(4))/4 for i in range(3)]
                        if sum(nrm[i]*(apex[i]-cen[i]) for i in range(3))<0: f=(f[0],f[3],f[2],f[1])
                        els.append((e,*f,ctr,ctr,ctr,ctr)); e+=1
                elif kind=='tet':
                    a,b,c,d,A,B,C,D=n
                    for t in [(a,b,c,A),(b,c,A,B),(c,A,B,C),(a,c,d,A),(c,d,A,D),(c,A,D,C)]:
                        p,q,r,s=t
                        P=[nodes[k] for k in (p,q,r,s)]
                        if vol(*P)<0: p,q=q,p
                        els.append((e,p,q,r,r,s,s,s,s)); e+=1
    s="/BEGIN\n%s\n      2019         0\n%20s%20s%20s\n%20s%20s%20s\n"%(name,'kg','mm','ms','kg','mm','ms')
    s+="/NODE\n"+"".join(I(k)+R(*p)+"\n" for k,p in nodes.items())
    s+="/BRICK/1\n"+"".join(I(*x)+"\n" for x in els)
    s+="/PART/1\nbar\n"+I(1,1)+"\n"
    s+="/PROP/SOLID/1\nsolid\n"+(I(isolid,0,0,icpre) if icpre else I(isolid,0))+"\n"+R(0,0,0)+"\n"
    if law=='elast':
        s+="/MAT/ELAST/1\nsteel\n"+R(7.85e-6)+"\n"+R(210.0,0.3)+"\n"
    else:
        s+="/MAT/PLAS_JOHNS/1\nsteel\n"+R(7.85e-6)+"\n"+R(210.0,0.3)+"\n"+R(0.3,0.5,0.3)+"\n"
    left=[nid(0,j,k) for k in range(nz+1) for j in range(ny+1)]
    right=[nid(nx,j,k) for k in range(nz+1) for j in range(ny+1)]
    def grp(g,l,t):
        o="/GRNOD/NODE/%d\n%s\n"%(g,t)
        for i in range(0,len(l),10): o+=I(*l[i:i+10])+"\n"
        return o
    s+=grp(1,left,"left")+grp(2,right,"right")
    s+="/BCS/1\nclamp\n   111 000"+I(0,1)+"\n"
    s+="/FUNCT/1\nconst\n"+R(0,1)+"\n"+R(1000,1)+"\n"
    s+="/IMPVEL/1\npull\n"+I(1)+"         "+push+I(0,0,2,0,0)+"\n"+R(0,v,0,0)+"\n"
    s+="/END\n"
    os.makedirs(name,exist_ok=True)
    open(f"{name}/{name}_0000.rad","w").write(s)
    open(f"{name}/{name}_0001.rad","w").write(f"/RUN/{name}/1\n{tend}\n/PRINT/-{print_every}\n/TFILE/4\n{tend/100}\n/VERS/2019\n")
if __name__ == "__main__":
    gen("PRI14", "prism", isolid=14)
    gen("TET", "tet")
    gen("PYR", "pyr")
