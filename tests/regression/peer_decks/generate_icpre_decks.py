# Generates the peer decks of Icpre 2 (docs/theory/brick8.md, eq. B-9c): a 100 x 20 x 20 mm Johnson-Cook cantilever
# of 2x2x2-point bricks, clamped at x = 0, its end pushed along Z at 5 mm/ms for 2 ms (bent well past yield).
# ICPRE18: Isolid 18 with Icpre blank, which the reference resolves to 2 with a plastic law; ICPRE14: Isolid 14,
# Icpre 2, twice as fine. Each folder's ref.extract is the reference solver's last row on its deck (run-or.sh, then
# or-extract.py). Run from this folder: python3 generate_icpre_decks.py
import os
I=lambda *v: "".join("%10d"%x for x in v)
R=lambda *v: "".join("%20.10g"%x for x in v)
def gen(name, isolid=18, icpre=0, nx=10, ny=2, nz=2, L=100.0, W=20.0, v=5.0, tend=2.0, law='jc', nu=0.3):
    nodes={}; nid=lambda i,j,k: 1+i+(nx+1)*(j+(ny+1)*k)
    for k in range(nz+1):
        for j in range(ny+1):
            for i in range(nx+1):
                nodes[nid(i,j,k)]=(L*i/nx, W*j/ny, W*k/nz)
    els=[]; e=1
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                els.append((e,nid(i,j,k),nid(i+1,j,k),nid(i+1,j+1,k),nid(i,j+1,k),nid(i,j,k+1),nid(i+1,j,k+1),nid(i+1,j+1,k+1),nid(i,j+1,k+1))); e+=1
    s="/BEGIN\n%s\n      2019         0\n%20s%20s%20s\n%20s%20s%20s\n"%(name,'kg','mm','ms','kg','mm','ms')
    s+="/NODE\n"+"".join(I(k)+R(*p)+"\n" for k,p in nodes.items())
    s+="/BRICK/1\n"+"".join(I(*x)+"\n" for x in els)
    s+="/PART/1\nbar\n"+I(1,1)+"\n"
    s+="/PROP/SOLID/1\nsolid\n"+I(isolid,0,0,icpre)+"\n"+R(0,0,0)+"\n"
    if law=='elast': s+="/MAT/ELAST/1\nsteel\n"+R(7.85e-6)+"\n"+R(210.0,nu)+"\n"
    else: s+="/MAT/PLAS_JOHNS/1\nsteel\n"+R(7.85e-6)+"\n"+R(210.0,nu)+"\n"+R(0.3,0.5,0.3)+"\n"
    left=[nid(0,j,k) for k in range(nz+1) for j in range(ny+1)]
    right=[nid(nx,j,k) for k in range(nz+1) for j in range(ny+1)]
    def grp(g,l,t):
        o="/GRNOD/NODE/%d\n%s\n"%(g,t)
        for i in range(0,len(l),10): o+=I(*l[i:i+10])+"\n"
        return o
    s+=grp(1,left,"left")+grp(2,right,"right")
    s+="/BCS/1\nclamp\n   111 000"+I(0,1)+"\n"
    s+="/FUNCT/1\nconst\n"+R(0,1)+"\n"+R(1000,1)+"\n"
    s+="/IMPVEL/1\npush\n"+I(1)+"         Z"+I(0,0,2,0,0)+"\n"+R(0,v,0,0)+"\n"
    s+="/END\n"
    os.makedirs(name,exist_ok=True)
    open(f"{name}/{name}_0000.rad","w").write(s)
    open(f"{name}/{name}_0001.rad","w").write(f"/RUN/{name}/1\n{tend}\n/PRINT/-100\n/TFILE/4\n{tend/100}\n/VERS/2019\n")
if __name__=="__main__":
    gen("ICPRE18", isolid=18, icpre=0)
    gen("ICPRE14", isolid=14, icpre=2, nx=20, ny=2, nz=4)
