#!/usr/bin/env python3
"""The proof of a reason in expected_no_effect.txt (docs/validation.md, "Field probe").

Usage: prove.py CRUMPLE DECK_FOLDER "CONDITION EDITS" "PROBED EDIT"
An edit is FILE:LINE:START-END=VALUE (1-based line, columns as field_probe.py prints them), several joined by ';'.
Runs a copy of the deck with the condition edits (a deck changed to meet the condition: a load that reaches the
threshold, a function that is not constant), then with those and the probed edit, and prints both energy rows
(internal, translational and rotational kinetic, hourglass, external work, cycles) and EFFECT or NO EFFECT."""
import sys, os, shutil, tempfile, subprocess, json
crumple, folder, cond, probe = sys.argv[1:5]
def parse(s):
    out=[]
    for e in filter(None, s.split(";")):
        where, val = e.split("=",1)
        f, line, cols = where.split(":")
        a,b = map(int, cols.split("-"))
        out.append((f,int(line),a,b,val))
    return out
def run(edits):
    work = tempfile.mkdtemp(prefix="prove_")
    for f in os.listdir(folder):
        if os.path.isfile(os.path.join(folder,f)): shutil.copy(os.path.join(folder,f), work)
    for f,line,a,b,val in edits:
        p=os.path.join(work,f); L=open(p,errors="replace").read().split("\n"); t=L[line-1]
        start=a-1; end=b; fs=max(0,end-max(end-start,len(val)))
        L[line-1]=t[:fs]+val.rjust(end-fs)+t[end:]
        open(p,"w").write("\n".join(L))
    starter=sorted(x for x in os.listdir(work) if x.endswith("_0000.rad"))[0]
    r=subprocess.run([crumple,"run",os.path.join(work,starter),"-o",os.path.join(work,"out"),"--quiet"],capture_output=True,text=True)
    s=[x for x in os.listdir(os.path.join(work,"out")) if x.endswith(".summary.json")] if os.path.isdir(os.path.join(work,"out")) else []
    vals=None
    if s:
        j=json.load(open(os.path.join(work,"out",s[0]))); e=j.get("energy",{})
        vals=[e.get(k,0.0) for k in ("internal","kinetic_translational","kinetic_rotational","hourglass","external_work")]+[j.get("cycles",0)]
    shutil.rmtree(work, ignore_errors=True)
    return r.returncode, vals, [l for l in (r.stdout+r.stderr).splitlines() if l.startswith(("warning","error"))][:5]
c=parse(cond); p=parse(probe)
a=run(c); b=run(c+p)
print("cond      :",a); print("cond+probe:",b)
print("EFFECT" if a[1]!=b[1] or a[0]!=b[0] else "NO EFFECT")
