# Generates the peer decks of /PROP/TYPE4 springs and /DAMP (docs/theory/spring.md, damping.md): a chain of five
# springs along x, node 1 fixed, a mass at its end. Run from the folder that is to hold the decks; each folder's
# ref.extract is the reference solver's last printed row on its deck (run-or.sh, then or-extract.py).
#   spring_chain_damped: released at 2 m/s, dashpots C = 5 and /DAMP alpha = 3 from 0.1 to 0.6 s.
#     Measured: internal energy +4.1 %, kinetic -1.6 % of the scale, 50 cycles against 50.
#   spring_chain_engine_damp: a constant pull of 100 N, C = 2, the engine's /DAMP alpha = 8 (starter 0).
#     Measured: internal energy +0.2 %, kinetic 0.0 %, 100 cycles against 100.
#   spring_chain_stiffness_damp: the constant pull, no dashpot, /DAMP beta = 0.002 (stiffness damping).
#     Measured: see the end of this file's run notes in docs/theory/damping.md.
#   spring_chain_function: the constant pull on springs of a stiffening force function (fct_ID11, A = 1.5,
#     Ascale = 0.02 m, SP-2b), C = 1, no /DAMP. Measured: internal energy -8.1 %, kinetic +1.2 % of the scale, 550
#     cycles against 550; every row's internal energy is the reference's to 4 digits one row later (the -8.1 % is
#     that row's change, as in spring_chain_stiffness_damp).
#   spring_chain_breaks: a pull ramped to 100 N at 1 s, C = 2, every spring breaking at delta_max = 0.06 m
#     (the reference breaks them all within two cycles of each other, at 1.35 s). Measured: internal energy -0.1 %
#     (the work of each spring's last force, SP-5a), kinetic -4.1 % of the scale (the reference's own energy
#     error at that row is -4.2 %, Crumple's 0.0 %), 376 cycles against 375.
import os
I=lambda *v: "".join("%10d"%x for x in v)
R=lambda *v: "".join("%20.10g"%x for x in v)
def spring_prop(pid, mass, k, c, dmax=0.0, fct=0, a=0.0, ascale=0.0):
    return ("/PROP/SPRING/%d\nspring\n"%pid + R(mass)+" "*30+I(0,0,0)+"\n" + R(k,c,a,0,0)+"\n"
            + I(fct,0,0,0,0)+" "*10+R(0,dmax)+"\n" + R(0,0,ascale,0)+"\n")
def chain(name, run, n=5, mass=0.5, k=2000.0, c=5.0, alpha=3.0, tstart=0.1, tstop=0.6, engine_alpha=None, end=1.0, load=0.0, v0=2.0, dmax=0.0, every=50, ramp=0.0, end_mass=1.0, beta=0.0, stiffening=False):
    s="/BEGIN\n%s\n      2019         0\n%20s%20s%20s\n%20s%20s%20s\n"%(run,'kg','m','s','kg','m','s')
    s+="/NODE\n"+"".join(I(i+1)+R(0.1*i,0.0,0.0)+"\n" for i in range(n+1))
    s+="/SPRING/1\n"+"".join(I(i+1,i+1,i+2)+"\n" for i in range(n))
    s+="/PART/1\nsprings\n"+I(1,0)+"\n"+spring_prop(1,mass,k,c,dmax, 2 if stiffening else 0, 1.5 if stiffening else 0.0, 0.02 if stiffening else 0.0)
    if stiffening:  # a stiffening force-elongation curve, f(delta / Ascale) scaled by A
        s+="/FUNCT/2\nstiffening\n"+R(-1,-3000)+"\n"+R(0,0)+"\n"+R(1,500)+"\n"+R(2,1500)+"\n"+R(5,6000)+"\n"
    s+="/GRNOD/NODE/1\nfixed\n"+I(1)+"\n/GRNOD/NODE/2\nfree\n"+I(*range(2,n+2))+"\n"
    s+="/GRNOD/NODE/3\nend\n"+I(n+1)+"\n/GRNOD/NODE/4\nall\n"+I(*range(1,n+2))+"\n"
    s+="/BCS/1\nfixed\n   111 111"+I(0,1)+"\n/BCS/2\nfree\n   011 111"+I(0,2)+"\n"
    s+="/ADMAS/0/1\nend mass\n"+R(end_mass)+I(3)+"\n"
    if v0: s+="/INIVEL/TRA/1\nv\n"+R(v0,0.0,0.0)+I(3)+"\n"
    if load: s+="/FUNCT/1\nload\n"+R(0,0 if ramp else 1)+"\n"+R(ramp if ramp else 100,1)+"\n"+(R(100,1)+"\n" if ramp else "")+"/CLOAD/1\npull\n"+I(1)+"         X"+I(0,0,3)+" "*10+R(1.0,load)+"\n"
    if alpha or beta or engine_alpha is not None: s+="/DAMP/1\nrayleigh\n"+R(alpha,beta)+I(4,0)+R(tstart,tstop)+"\n"
    s+="/TH/SPRING/1\nsprings\nDEF       \n"+"".join(I(i+1)+"\n" for i in range(n))
    s+="/END\n"
    os.makedirs(name, exist_ok=True)
    open(os.path.join(name, run+"_0000.rad"),"w").write(s)
    e="/RUN/%s/1\n%g\n/TFILE\n0.01\n/PRINT/-%d\n"%(run, end, every)
    if engine_alpha is not None: e+="/DAMP/1\n%g 0\n"%engine_alpha
    open(os.path.join(name, run+"_0001.rad"),"w").write(e)
chain("spring_chain_damped", "SPRDAMP")
chain("spring_chain_engine_damp", "SPRENG", alpha=0.0, engine_alpha=8.0, tstart=0.0, tstop=0.0, c=2.0, load=100.0,
      v0=0.0, end=1.5)
chain("spring_chain_breaks", "SPRBRK", alpha=0.0, c=2.0, mass=0.05, load=200.0, v0=0.0, end=1.5, dmax=0.06, every=25, ramp=2.0,
      end_mass=10.0)
chain("spring_chain_stiffness_damp", "SPRBETA", alpha=0.0, beta=0.002, c=0.0, load=100.0, v0=0.0, end=1.0,
      tstart=0.0, tstop=0.0)
chain("spring_chain_function", "SPRFUN", alpha=0.0, c=1.0, v0=0.0, load=100.0, end=0.8, stiffening=True)
