# Generates the peer decks of the end of a run (docs/theory/time-loop.md, T-0): one linear /PROP/SPRING between a
# fixed node and a free one, released at 1 m/s, ringing with a period of about five cycles, so that the state a run
# ends on shows in both energies. Run from the folder that is to hold the decks; each folder's ref.extract is the
# reference solver's last printed row on its deck (run-or.sh, then or-extract.py). Every cycle is listed.
#   spring_end_time_no_frames: no /ANIM/DT, the end time 0.3 of a step past cycle 314: the run ends at cycle 314.
#   spring_end_time_after_frame: frames every 0.1 s, the end 50.5 steps past the frame at 0.1 s: the run ends at
#     the last cycle before the end time.
#   spring_end_time_frame_due: frames every 0.1 s, the end 120.4 steps past that frame: the run goes one cycle
#     past the end time, for its end frame.
# Measured: Crumple's last cycle is the reference's on the three, its energies the reference's to 4 digits
# (tests/regression/check_end_state.py, ctest regression.end_state).
import math, os
I=lambda *v: "".join("%10d"%x for x in v)
R=lambda *v: "".join("%20.10g"%x for x in v)
MASS, K = 0.05, 1.0e5
DT = 0.9 * math.sqrt(MASS / K)  # the spring's step (SP-4) at the default scale
def deck(name, run, end, frames=0.0):
    s="/BEGIN\n%s\n      2019         0\n%20s%20s%20s\n%20s%20s%20s\n"%(run,'kg','m','s','kg','m','s')
    s+="/NODE\n"+I(1)+R(0.0,0.0,0.0)+"\n"+I(2)+R(0.1,0.0,0.0)+"\n"
    s+="/SPRING/1\n"+I(1,1,2)+"\n"
    s+="/PART/1\nspring\n"+I(1,0)+"\n"
    s+="/PROP/SPRING/1\nspring\n"+R(MASS)+" "*30+I(0,0,0)+"\n"+R(K,0,0,0,0)+"\n"+I(0,0,0,0,0)+" "*10+R(0,0)+"\n"+R(0,0,0,0)+"\n"
    s+="/GRNOD/NODE/1\nfixed\n"+I(1)+"\n/GRNOD/NODE/2\nfree\n"+I(2)+"\n"
    s+="/BCS/1\nfixed\n   111 111"+I(0,1)+"\n/BCS/2\nfree\n   011 111"+I(0,2)+"\n"
    s+="/INIVEL/TRA/1\nv\n"+R(1.0,0.0,0.0)+I(2)+"\n"
    s+="/TH/SPRING/1\nspring\nDEF       \n"+I(1)+"\n/END\n"
    os.makedirs(name, exist_ok=True)
    open(os.path.join(name, run+"_0000.rad"),"w").write(s)
    e="/RUN/%s/1\n%.9f\n/TFILE\n0.01\n/PRINT/-1\n"%(run, end)
    if frames: e+="/ANIM/DT\n0 %g\n"%frames
    open(os.path.join(name, run+"_0001.rad"),"w").write(e)
frame_cycle = math.ceil(0.1 / DT)  # the frame at 0.1 s is written at the first cycle at or past it
deck("spring_end_time_no_frames", "ENDNOF", (314 + 0.3) * DT)
deck("spring_end_time_after_frame", "ENDAFT", (frame_cycle + 50.5) * DT, frames=0.1)
deck("spring_end_time_frame_due", "ENDDUE", (frame_cycle + 120.4) * DT, frames=0.1)
