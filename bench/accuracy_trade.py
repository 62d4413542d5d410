#!/usr/bin/python3
"""Speed-accuracy trade of the solver's knobs on the benchmark tube crush (issue 13): writes the tube decks of
decks/generate_bench.py (50 x 50 mm square tube, 1.5 mm wall, 200 mm long, Ishell 24, 5 points, Johnson-Cook steel,
a 50 kg sled on the rear ring's rigid body, 10 m/s onto a fixed rigid wall, TYPE7 self contact) at a few element
sizes, turns one knob at a time away from the default deck, runs each variant with `crumple run` and prints and
writes as Markdown what each knob costs in accuracy and buys in speed:

  - the crush response over the first WINDOW mm of sled travel (default 50): the energy absorbed, the integral of
    the rigid-wall normal force (/TH/RWALL, FNX FNY FNZ) over the sled's displacement increments (the rigid body's
    X in /history/rigid_body_values of NAME.h5), trapezoids on the history rows; the mean crush force, that energy
    over the travel (a displacement average); the peak crush force, the largest wall force over the window after
    an SAE J211 CFC filter (default CFC 1000, two-pass second-order Butterworth on the rows resampled at the
    history interval), since the unfiltered peak of an explicit run is sampling noise. The histories are written
    every 0.01 ms (the engine deck's /TFILE is changed from the generator's end time / 100). A run whose sled stops
    (its velocity turns) before WINDOW mm is measured up to where it stopped, and says so;
  - the energy absorbed over further windows (--windows, default 50 40: the 10 mm mesh stops its sled at 46.5 mm,
    so that over "50 mm" every 10 mm run absorbs the whole kinetic energy, whereas every run reaches 40 mm);
  - the energy error (NAME.summary.json energy.error_percent, at the end time), the time loop's wall time
    (summary wall_seconds), the crumple process's CPU time (user + system), the cycle count and the mass added by
    mass scaling;
  - each against the reference run, the finest mesh of --sizes with the finest settings (/DT scale 0.6, 5 points,
    Ishell 24, no mass scaling), as relative differences in percent; the speed-up against the default deck on
    the same mesh (same end time), on the process's CPU time by default (--clock: the solver runs on one thread,
    so on a quiet machine the two are the same, and CPU time is what other jobs on a shared machine disturb least).

Knobs, one at a time from the default deck (/DT 0.9, 5 points, Ishell 24, Stfac 0 = 1, no mass scaling):
  dt scale      the engine deck's /DT scale 0.6 (the reference's) against the default 0.9; the scale also
                multiplies the contact step;
  mass scaling  /DT/NODA/CST 0.9 DTMIN added to the engine deck with DTMIN 1.0, 1.2, 1.5 and 3 times dt0, the
                default run's first step on that mesh: the first row of /history/dt in its NAME.h5, the step of
                cycle 1, which `crumple check` prints as "scaled step" (the listing prints no step before cycle
                1000). The step falls to about 0.45 dt0 as the folds form, so 1.0 dt0 already adds mass there.
                These runs have /STOP Mmax 0 (no limit) instead of the deck's 0.1, so that they run to the end
                and show what the added mass does (the added mass column);
  /AMS         selective mass scaling (/AMS on the whole model, /DT/AMS 0.67 DTMIN) with DTMIN 1.5 and 3 times
                dt0: mass added to the deformation modes only, solved for every cycle (docs/theory/time-step.md,
                SM-0 to SM-7);
  points        3 integration points through the thickness against 5 (generator --points);
  Ishell        1 (Belytschko-Tsay, hourglass controlled) against 24 (generator --ishell);
  Stfac         the TYPE7 card's Stfac 0.1 and 1.0 against the default (0, which means 1.0: the 1.0 run repeats
                the default deck, a check of determinism and of the wall-time noise; it is not run on the
                reference mesh unless --all);
  --accuracy    the default deck run with `crumple run --accuracy draft` and `--accuracy fine`: the presets as a
                user meets them (src/app/accuracy.hpp; on this deck draft takes 3 points and /DT/NODA/CST at the
                first step, fine the /DT scale 0.6).
  precision     the default deck run by the mixed-precision build (--mixed-crumple, `cmake --preset mixed`:
                the integration points' state stored in single precision, docs/theory/precision.md) against
                the double build (--crumple). Build both from the same commit.
/PARITH/OFF is not a knob of Crumple: it is accepted with a warning and changes nothing (docs/deck-format.md).

End time: per mesh, long enough for WINDOW mm of travel of every variant, from first runs of the default deck (at
10 mm the sled stops at 46.5 mm at 9.6 ms; at 5 mm it reaches 50 mm at 7.45 ms, at 2.5 mm at 6.96 ms):
10.5, 8.5 and 7.6 ms (--end-time overrides, one value for every mesh; 10 ms for sizes not listed). A run whose sled
is still moving short of the window at its end time is run again with a longer end time (said in its notes; its
time is then for that longer run). The runs go one at a time.

Run (from the repository, after `cmake --build --preset release`):
    /usr/bin/python3 bench/accuracy_trade.py --table OUT.md --plot OUT.png       # 10, 5, 2.5 mm: about 20 min
    /usr/bin/python3 bench/accuracy_trade.py --sizes 10 5 --knobs default dt_scale  # a quick look
Decks and results go to --work (default /tmp/crumple-accuracy-trade), with results.json (every run's figures).
Generated decks are not kept in the repository.
"""
import argparse
import datetime
import json
import math
import os
import re
import resource
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "decks"))
import generate_bench  # noqa: E402

DEFAULT_SIZES = [10.0, 5.0, 2.5]
END_TIMES = {10.0: 10.5, 5.0: 8.5, 2.5: 7.6}  # ms, from first runs of the default deck (docstring)
OTHER_END_TIME = 10.0
TH_INTERVAL = 0.01  # ms
REFERENCE_DT_SCALE = 0.6
AMS_SCALE = 0.67  # /DT/AMS DTsca, the value of the reference's examples


@dataclass
class Variant:
    knob: str           # key: default, dt_scale, mass_scaling, points, ishell, stfac
    value: str          # as printed
    dt_scale: float = 0.9
    points: int = 5
    ishell: int = 24
    stfac: float = None          # None: the generator's 0 (= 1.0)
    dtmin_factor: float = None   # /DT/NODA/CST DTMIN = factor x the default run's first step
    ams_factor: float = None     # /AMS and /DT/AMS 0.67 DTMIN, DTMIN = factor x the default run's first step
    preset: str = None           # crumple run --accuracy PRESET on the default deck
    build: str = None            # "mixed": the default deck run by the mixed-precision build (--mixed-crumple)
    default_only_off_reference: bool = False  # repeats the default deck: skipped on the reference mesh

    @property
    def tag(self):
        return re.sub(r"[^A-Za-z0-9.]+", "_", f"{self.knob}_{self.value}").strip("_")


KNOB_LABELS = {"default": "default deck", "dt_scale": "/DT scale", "mass_scaling": "/DT/NODA/CST", "ams": "/AMS",
               "points": "points", "ishell": "Ishell", "stfac": "TYPE7 Stfac", "preset": "--accuracy",
               "precision": "precision"}
KNOB_MARKERS = {"default": "o", "dt_scale": "s", "mass_scaling": "^", "ams": "<", "points": "D", "ishell": "v", "stfac": "P",
                "preset": "*", "precision": "X"}
VARIANTS = [
    Variant("default", "/DT 0.9, 5 points, Ishell 24, Stfac 1"),
    Variant("dt_scale", "0.6", dt_scale=0.6),
    Variant("mass_scaling", "1.0 dt0", dtmin_factor=1.0),
    Variant("mass_scaling", "1.2 dt0", dtmin_factor=1.2),
    Variant("mass_scaling", "1.5 dt0", dtmin_factor=1.5),
    Variant("mass_scaling", "3 dt0", dtmin_factor=3.0),
    Variant("ams", "1.5 dt0", ams_factor=1.5),
    Variant("ams", "3 dt0", ams_factor=3.0),
    Variant("points", "3", points=3),
    Variant("ishell", "1", ishell=1),
    Variant("stfac", "0.1", stfac=0.1),
    Variant("preset", "draft", preset="draft"),
    Variant("preset", "fine", preset="fine"),
    Variant("precision", "mixed", build="mixed"),
    Variant("stfac", "1.0", stfac=1.0, default_only_off_reference=True),
]


# ------------------------------------------------------------------------------------------------- the decks


def edit_engine(text, v, dtmin, th_interval):
    """The generator's engine deck with the variant's /DT scale, /DT/NODA/CST and history interval."""
    text, n = re.subn(r"^/DT\n[^\n]*\n", f"/DT\n{v.dt_scale:g} 0.0\n", text, flags=re.M)
    if n != 1:
        raise RuntimeError("engine deck: expected one /DT card")
    text, n = re.subn(r"^/TFILE\n[^\n]*\n", f"/TFILE\n{th_interval:g}\n", text, flags=re.M)
    if n != 1:
        raise RuntimeError("engine deck: expected one /TFILE card")
    if dtmin is not None:
        card = f"/DT/AMS\n{AMS_SCALE:g} {dtmin:.6g}\n" if v.ams_factor else f"/DT/NODA/CST\n0.9 {dtmin:.6g}\n"
        text = text.replace(f"/DT\n{v.dt_scale:g} 0.0\n", f"/DT\n{v.dt_scale:g} 0.0\n" + card)
        # /STOP Emax Mmax ...: no added-mass limit, so that the run shows what the mass does
        text, n = re.subn(r"^/STOP\n(\S+) \S+ ", r"/STOP\n\1 0.0 ", text, flags=re.M)
        if n != 1:
            raise RuntimeError("engine deck: expected one /STOP card")
    return text


def edit_stfac(text, stfac):
    """The TYPE7 card's Stfac (columns 1-20 of the line under the '#   Stfac   Fric ...' comment)."""
    lines = text.split("\n")
    marks = [k for k, line in enumerate(lines) if line.startswith("#") and "Stfac" in line and "Fric" in line]
    if len(marks) != 1:
        raise RuntimeError(f"starter deck: expected one TYPE7 Stfac line, found {len(marks)}")
    k = marks[0] + 1
    lines[k] = generate_bench.r20(stfac) + lines[k][20:]
    return "\n".join(lines)


def write_variant(directory, size, end_time, v, dt0, th_interval):
    """The tube deck of mesh `size` [mm] with variant `v`; returns the starter's path."""
    starter = generate_bench.write_family("tube", directory, size=size, end_time=end_time, ishell=v.ishell,
                                          points=v.points)
    engine = starter.with_name(starter.name.replace("_0000.rad", "_0001.rad"))
    factor = v.dtmin_factor or v.ams_factor
    dtmin = factor * dt0 if factor else None
    engine.write_text(edit_engine(engine.read_text(), v, dtmin, th_interval))
    if v.ams_factor:  # /AMS on the whole model (grpart_ID 0), in the starter
        text = starter.read_text()
        starter.write_text(text[:text.rindex("/END")] + "/AMS\n0\n/END\n")
    if v.stfac is not None:
        starter.write_text(edit_stfac(starter.read_text(), v.stfac))
    return starter, dtmin


def scaled_step(crumple, deck):
    """The first step that `crumple check` prints ("scaled step"), None if absent."""
    done = subprocess.run([crumple, "check", str(deck)], capture_output=True, text=True)
    if done.returncode != 0:
        raise RuntimeError(f"crumple check {deck} exited with {done.returncode}:\n{done.stdout}{done.stderr}")
    found = re.search(r"^\s*scaled step\s+([0-9.eE+-]+)", done.stdout, re.M)
    return float(found.group(1)) if found else None


def run_crumple(crumple, deck, out_dir, timeout, preset=None):
    """`crumple run DECK -o OUT --quiet [--accuracy PRESET]`; its summary and the CPU time (user + system) of the
    process [s]."""
    out_dir.mkdir(parents=True, exist_ok=True)
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    with open(out_dir / "console.log", "w") as log:
        done = subprocess.run([crumple, "run", str(deck), "-o", str(out_dir), "--quiet"]
                              + (["--accuracy", preset] if preset else []), stdout=log,
                              stderr=subprocess.STDOUT, timeout=timeout)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    summaries = list(out_dir.glob("*.summary.json"))
    if done.returncode != 0 and not summaries:
        raise RuntimeError(f"crumple run {deck} exited with {done.returncode}: see {out_dir / 'console.log'}")
    return json.loads(summaries[0].read_text()), cpu


# ------------------------------------------------------------------------------------------- the measurements


def columns(dataset, names):
    """Column indices of `dataset` whose 'variables' attribute is each of `names`."""
    variables = [v.decode() if isinstance(v, bytes) else str(v) for v in dataset.attrs["variables"]]
    return [variables.index(n) for n in names]


def cfc_filter(signal, interval_s, cfc):
    """SAE J211 channel frequency class filter: second-order Butterworth run forwards then backwards."""
    wd = 2.0 * math.pi * cfc * 2.0775
    wa = math.sin(wd * interval_s / 2.0) / math.cos(wd * interval_s / 2.0)
    den = 1.0 + math.sqrt(2.0) * wa + wa * wa
    a0 = wa * wa / den
    a1, a2 = 2.0 * a0, a0
    b1 = -2.0 * (wa * wa - 1.0) / den
    b2 = (-1.0 + math.sqrt(2.0) * wa - wa * wa) / den

    def one_pass(x):
        """At rest before the first sample: the two samples before it, in and out, equal it."""
        x = np.concatenate(([x[0], x[0]], x))
        y = x.copy()
        for i in range(2, len(x)):
            y[i] = a0 * x[i] + a1 * x[i - 1] + a2 * x[i - 2] + b1 * y[i - 1] + b2 * y[i - 2]
        return y[2:]
    return one_pass(one_pass(signal)[::-1])[::-1]


def crush_metrics(h5_path, window, cfc, th_interval):
    """Energy, mean and peak wall force over the first `window` mm of sled travel (or up to the sled's stop)."""
    import h5py  # only here: the deck writing runs without it
    with h5py.File(h5_path, "r") as f:
        t = f["history/time"][:]
        bodies = f["history/rigid_body_values"]
        ix, ivx = columns(bodies, ["X", "VX"])
        x, vx = bodies[:, ix], bodies[:, ivx]
        walls = [d for d in f["history/th"].values() if d.attrs.get("kind") == "RWALL"]
        if len(walls) != 1:
            raise RuntimeError(f"{h5_path}: expected one /TH/RWALL history, found {len(walls)}")
        normal = walls[0][:, columns(walls[0], ["FNX", "FNY", "FNZ"])]
    force = np.linalg.norm(normal, axis=1)
    # a row at t = 0 (the sled at its start, extrapolated at its first speed; no wall force before impact)
    x0 = x[0] - vx[0] * t[0]
    t, travel, force, vx = (np.concatenate(([0.0], t)), np.concatenate(([0.0], x0 - x)),
                            np.concatenate(([0.0], force)), np.concatenate(([vx[0]], vx)))
    moving = vx < 0.0  # towards the wall (-x)
    stop = len(t) if moving.all() else int(np.argmin(moving))  # first row where the sled has turned
    past = np.nonzero(travel[:stop] >= window)[0]
    if len(past):
        k = past[0]
        w = (window - travel[k - 1]) / (travel[k] - travel[k - 1])
        t_end = t[k - 1] + w * (t[k] - t[k - 1])
        f_end = force[k - 1] + w * (force[k] - force[k - 1])
        tw, dw, fw = np.append(t[:k], t_end), np.append(travel[:k], window), np.append(force[:k], f_end)
        status = "reached"
    else:
        k = stop - 1 if stop < len(t) else len(t) - 1
        k = int(np.argmax(travel[:k + 1]))  # the farthest point before the turn
        tw, dw, fw = t[:k + 1], travel[:k + 1], force[:k + 1]
        status = "stopped" if stop < len(t) else "short"
    energy = float(np.sum(0.5 * (fw[1:] + fw[:-1]) * np.diff(dw)))
    reached = float(dw[-1])
    grid = np.arange(0.0, tw[-1] + 0.5 * th_interval, th_interval)
    filtered = cfc_filter(np.interp(grid, tw, fw), th_interval * 1e-3, cfc)  # interval in s
    return {"status": status, "travel": reached, "time": float(tw[-1]), "energy": energy,
            "mean_force": energy / reached if reached > 0 else float("nan"),
            "peak_force": float(filtered.max()), "peak_force_raw": float(fw.max()),
            "end_travel": float(travel[-1]), "end_speed": float(-vx[-1]), "max_travel": float(travel.max())}


# --------------------------------------------------------------------------------------------------- running


def measure(a, work, size, end_time, v, dt0):
    """Writes, runs and measures one variant; runs again longer while the sled is short of the window."""
    notes, extensions = [], 0
    while True:
        deck_dir = work / f"tube_{size:g}mm" / v.tag
        deck, dtmin = write_variant(deck_dir, size, end_time, v, dt0, a.th_interval)
        load = os.getloadavg()[0]
        summary, cpu = run_crumple(a.mixed_crumple if v.build == "mixed" else a.crumple, deck, deck_dir / "out",
                                   a.timeout, v.preset)
        h5 = next((deck_dir / "out").glob("*.h5"))
        m = crush_metrics(h5, a.windows[0], a.cfc, a.th_interval)
        if m["status"] != "short" or summary["status"] != "normal" or extensions >= 2:
            break
        extensions += 1
        speed = max(m["end_speed"], 0.5)
        longer = end_time + 1.3 * (a.windows[0] - m["end_travel"]) / speed + 0.2
        notes.append(f"{end_time:g} ms short of {a.windows[0]:g} mm ({m['end_travel']:.1f} mm), run again to "
                     f"{longer:.2f} ms")
        end_time = longer
    if summary["status"] != "normal":
        notes.append(f"run ended at cycle {summary['cycles']}, {summary['time']:.3g} ms: {summary.get('message', '')}")
    elif m["status"] == "stopped":
        notes.append(f"sled stopped at {m['travel']:.1f} mm ({m['time']:.2f} ms)")
    elif m["status"] == "short":
        notes.append(f"short of the window: {m['travel']:.1f} mm")
    if dtmin is not None:
        notes.append(f"DTMIN {dtmin:.4g} ms")
    return {"size": size, "knob": v.knob, "value": v.value, "tag": v.tag, "end_time": end_time,
            "wall": summary["wall_seconds"], "cpu": cpu, "load": load, "commit": summary.get("commit"),
            "profile": summary.get("profile"), "cycles": summary["cycles"],
            "energy_error": summary["energy"]["error_percent"], "added_mass": summary["mass"]["added"],
            "total_mass": summary["mass"]["total"], "status": summary["status"], "dtmin": dtmin,
            "metrics": m, "windows": [crush_metrics(h5, w, a.cfc, a.th_interval) for w in a.windows[1:]],
            "notes": notes, "out": str(deck_dir / "out")}


def first_step(run):
    """The default run's first step: row 0 of /history/dt (the step of cycle 1)."""
    import h5py
    with h5py.File(next(Path(run["out"]).glob("*.h5")), "r") as f:
        return float(f["history/dt"][0])


# ---------------------------------------------------------------------------------------------------- report


def diff(value, reference):
    return 100.0 * (value - reference) / reference


def usable(r):
    """A run that reached its end time (a run stopped by /STOP or an error has no crush figures)."""
    return r["status"] == "normal"


def table(runs, reference, windows, clock):
    """One row per run: the figures over the first window, the energy over the others, the differences."""
    ref, main = reference["metrics"], windows[0]
    default_time = {r["size"]: r[clock] for r in runs if r["knob"] == "default"}
    extra = "".join(f"| energy {w:g} mm [J] | d energy {w:g} mm [%] " for w in windows[1:])
    head = (f"| mesh [mm] | knob | value | wall [s] | CPU [s] | speed-up ({clock}) | cycles | travel [mm] | mean force [kN] "
            f"| peak force [kN] | energy {main:g} mm [J] | energy error [%] | added mass [kg] | d mean [%] "
            f"| d peak [%] | d energy {main:g} mm [%] {extra}| notes |\n"
            + "|---" * (17 + 2 * (len(windows) - 1)) + "|\n")
    rows = []
    for r in runs:
        m, base = r["metrics"], default_time.get(r["size"])
        value = r["value"] + (" (reference)" if r is reference else "")
        cells = [f"{r['size']:g}", KNOB_LABELS[r["knob"]], value, f"{r['wall']:.1f}", f"{r['cpu']:.1f}"]
        if usable(r):
            cells += [f"{base / r[clock]:.2f}" if base else "n/a", f"{r['cycles']}", f"{m['travel']:.1f}",
                      f"{m['mean_force']:.2f}", f"{m['peak_force']:.1f}", f"{m['energy']:.0f}",
                      f"{r['energy_error']:.3f}", f"{r['added_mass']:.3g}",
                      f"{diff(m['mean_force'], ref['mean_force']):+.1f}",
                      f"{diff(m['peak_force'], ref['peak_force']):+.1f}", f"{diff(m['energy'], ref['energy']):+.1f}"]
            for w, rw in zip(reference["windows"], r["windows"]):
                cells += [f"{rw['energy']:.0f}", f"{diff(rw['energy'], w['energy']):+.1f}"]
        else:  # unstable: no speed-up or crush figures to give
            cells += ["-", f"{r['cycles']}", "-", "-", "-", "-", f"{r['energy_error']:.3g}", f"{r['added_mass']:.3g}",
                      "-", "-", "-"] + ["-", "-"] * (len(windows) - 1)
        busy = [f"load average {r['load']:.1f} at its start"] if r["load"] > (os.cpu_count() or 1) else []
        cells.append("; ".join(r["notes"] + busy))
        rows.append("| " + " | ".join(cells) + " |")
    return head + "\n".join(rows) + "\n"


def plot(runs, reference, windows, path, clock):
    """Run time (log) against the energy difference to the reference, a panel per window; unstable runs left out."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import matplotlib.ticker  # noqa: F401 (matplotlib.ticker below)
    sizes = sorted({r["size"] for r in runs}, reverse=True)
    colours = dict(zip(sizes, plt.rcParams["axes.prop_cycle"].by_key()["color"]))
    fig, axes = plt.subplots(1, len(windows), figsize=(7.5 * len(windows), 6.5), squeeze=False, sharex=True)
    shown = [r for r in runs if usable(r)]
    for k, (ax, window) in enumerate(zip(axes[0], windows)):
        pick = (lambda r: r["metrics"]) if k == 0 else (lambda r, k=k: r["windows"][k - 1])
        ax.axhline(0.0, color="0.6", lw=0.8)
        for r in shown:
            y = diff(pick(r)["energy"], pick(reference)["energy"])
            ax.scatter(r[clock], y, marker=KNOB_MARKERS[r["knob"]], color=colours[r["size"]], s=60,
                       edgecolors="k" if r is reference else "none", linewidths=1.2, zorder=3)
            label = "reference" if r is reference else ("" if r["knob"] == "default" else r["value"])
            if label:
                ax.annotate(label, (r[clock], y), textcoords="offset points", xytext=(5, 3), fontsize=7)
        ax.set_xscale("log")
        ax.xaxis.set_major_formatter(matplotlib.ticker.FuncFormatter(lambda v, _: f"{v:g}"))
        ax.xaxis.set_minor_formatter(matplotlib.ticker.FuncFormatter(
            lambda v, _: f"{v:g}" if round(v / 10 ** math.floor(math.log10(v))) in (2, 5) else ""))
        ax.tick_params(axis="x", which="minor", labelsize=7)
        ax.set_xlabel(("CPU time of the run (user + system)" if clock == "cpu" else "wall time of the run")
                      + " [s] (log)")
        ax.set_ylabel(f"energy absorbed over the first {window:g} mm of travel: difference to the reference [%]")
        ax.grid(True, which="both", alpha=0.3)
        ax.set_title(f"first {window:g} mm of sled travel" + (" (or up to the sled's stop)" if k == 0 else ""),
                     fontsize=10)
    knobs = list(dict.fromkeys(r["knob"] for r in shown))
    handles = [plt.Line2D([], [], ls="", marker=KNOB_MARKERS[k], color="0.3", label=KNOB_LABELS[k]) for k in knobs]
    handles += [plt.Line2D([], [], ls="", marker="o", color=colours[s], label=f"{s:g} mm mesh") for s in sizes]
    axes[0][0].legend(handles=handles, fontsize=8, loc="best")
    left_out = {}
    for r in runs:
        if not usable(r):
            left_out.setdefault(f"{KNOB_LABELS[r['knob']]} {r['value']}", []).append(f"{r['size']:g}")
    left_out = [f"{k} ({', '.join(v)} mm)" for k, v in left_out.items()]
    fig.suptitle("Benchmark tube crush, one knob at a time from the default deck: speed against accuracy"
                 + (f"\nnot shown (unstable, stopped by /STOP): {', '.join(left_out)}" if left_out else ""),
                 fontsize=10)
    fig.tight_layout()
    Path(path).parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=110)


def parse_arguments():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--sizes", type=float, nargs="+", default=DEFAULT_SIZES,
                   help="element sizes [mm] (default 10 5 2.5); the smallest is the reference mesh")
    p.add_argument("--knobs", nargs="+", default=list(KNOB_LABELS), choices=list(KNOB_LABELS),
                   help="knobs to run (default all; default and dt_scale are always run on the reference mesh)")
    p.add_argument("--all", action="store_true", help="also repeat the default deck as Stfac 1.0 on the reference mesh")
    p.add_argument("--end-time", type=float, help="end time of every deck [ms] (default per mesh, see above)")
    p.add_argument("--windows", type=float, nargs="+", default=[50.0, 40.0],
                   help="sled travel of the measurements [mm]: the first for every figure, the others for the "
                        "energy only (default 50 40)")
    p.add_argument("--clock", choices=["cpu", "wall"], default="cpu",
                   help="time of the speed-ups and the plot: the crumple process's CPU time (user + system, the "
                        "default: the solver runs on one thread, and CPU time is what another job on the machine "
                        "disturbs least) or the time loop's wall time (summary wall_seconds)")
    p.add_argument("--cfc", type=float, default=1000.0, help="filter class of the peak force (default CFC 1000)")
    p.add_argument("--th-interval", type=float, default=TH_INTERVAL, help="history interval [ms] (default 0.01)")
    p.add_argument("--crumple", default=str(ROOT / "build/release/src/crumple"))
    p.add_argument("--mixed-crumple", default=str(ROOT / "build/mixed/src/crumple"),
                   help="the mixed-precision build (cmake --preset mixed) for the precision knob")
    p.add_argument("--work", default="/tmp/crumple-accuracy-trade", help="decks and results")
    p.add_argument("--table", help="Markdown file (default WORK/accuracy_trade.md)")
    p.add_argument("--plot", help="PNG file (default WORK/speed_accuracy.png)")
    p.add_argument("--timeout", type=float, default=3600, help="per run [s]")
    p.add_argument("--from-results", action="store_true",
                   help="run nothing: write the table and the plot again from WORK/results.json")
    p.add_argument("--resume", action="store_true",
                   help="take the runs recorded in WORK/results.json (same mesh, knob value and crumple) as they "
                        "are and run only the others: an interrupted study goes on, and a run whose timing a busy "
                        "machine spoilt is run again after deleting its entry")
    return p.parse_args()


def write_report(a, work, runs, reference, skipped, command):
    """The Markdown table (printed and written), the plot and WORK/results.json."""
    cpu = sum(r["cpu"] for r in runs)
    finest = reference["size"]
    commits = sorted({str(r.get("commit")) for r in runs})
    lines = [f"Command: `{command}`  ",
             f"Solver: crumple {', '.join(commits)} (summary \"commit\")"
             + ("  **(the runs were made by more than one build)**" if len(commits) > 1 else "") + "  ",
             f"Date: {datetime.date.today().isoformat()}; CPU time of the runs {cpu / 60:.1f} min; reference: the "
             f"{finest:g} mm mesh with /DT 0.6, 5 points, Ishell 24, no mass scaling. Figures over the first "
             f"{a.windows[0]:g} mm of sled travel, or up to where the sled stops (travel column); peak force after "
             f"CFC {a.cfc:g}; energy error from the summary at the end time; d: difference to the reference; "
             f"wall: the time loop's (summary wall_seconds); CPU: the process's user + system time; speed-up: the "
             f"default deck's {a.clock} time on the same mesh over the run's. Load average (1 min) before the runs "
             f"{min(r['load'] for r in runs):.2f} to {max(r['load'] for r in runs):.2f}.", ""]
    if skipped:
        lines += ["Not run: " + "; ".join(skipped) + ".", ""]
    markdown = "\n".join(lines) + table(runs, reference, a.windows, a.clock)
    table_path = Path(a.table) if a.table else work / "accuracy_trade.md"
    plot_path = Path(a.plot) if a.plot else work / "speed_accuracy.png"
    table_path.parent.mkdir(parents=True, exist_ok=True)
    table_path.write_text(markdown)
    plot(runs, reference, a.windows, plot_path, a.clock)
    (work / "results.json").write_text(json.dumps({"command": command, "runs": runs,
                                                   "reference": [reference["size"], reference["tag"]],
                                                   "skipped": skipped, "windows": a.windows, "cfc": a.cfc,
                                                   "cpu_seconds": cpu}, indent=1) + "\n")
    print("\n" + markdown + f"\nwrote {table_path}, {plot_path} and {work / 'results.json'}")


def main():
    a = parse_arguments()
    work = Path(a.work).resolve()
    if a.from_results:
        saved = json.loads((work / "results.json").read_text())
        a.windows, a.cfc = saved["windows"], saved["cfc"]
        runs = saved["runs"]
        reference = next(r for r in runs if [r["size"], r["tag"]] == saved["reference"])
        write_report(a, work, runs, reference, saved.get("skipped", []), saved["command"])
        return
    sizes = sorted(set(a.sizes), reverse=True)
    finest = sizes[-1]
    runs, skipped = [], []
    done = {}
    partial = work / "results.partial.json"  # every run so far, written after each one
    for saved in [work / "results.json", partial] if a.resume else []:
        for r in json.loads(saved.read_text())["runs"] if saved.exists() else []:
            if r.get("crumple") == a.crumple:
                done[(r["size"], r["tag"])] = r
    for size in sizes:
        end_time = a.end_time or END_TIMES.get(size, OTHER_END_TIME)
        dt0 = None
        for v in VARIANTS:
            wanted = v.knob in a.knobs or (size == finest and v.knob in ("default", "dt_scale"))
            if v.knob != "default" and not wanted:
                continue
            if v.build == "mixed" and not Path(a.mixed_crumple).is_file():
                skipped.append(f"{size:g} mm precision mixed (no {a.mixed_crumple}: cmake --preset mixed)")
                continue
            if v.default_only_off_reference and size == finest and not a.all:
                skipped.append(f"{size:g} mm {KNOB_LABELS[v.knob]} {v.value} (the default deck again)")
                continue
            r = done.get((size, v.tag))
            if r is not None:
                print(f"{size:g} mm {v.knob} {v.value}: taken from {work / 'results.json'}", flush=True)
                runs.append(r)
                dt0 = first_step(r) if v.knob == "default" else dt0
                continue
            r = measure(a, work, size, end_time, v, dt0)
            r["crumple"] = a.crumple
            if v.knob == "default":
                dt0 = first_step(r)
                check = scaled_step(a.crumple, next(Path(r["out"]).parent.glob("*_0000.rad")))
                r["notes"].append(f"first step dt0 {dt0:.4g} ms (crumple check: {check:.4g})")
            runs.append(r)
            m = r["metrics"]
            print(f"{size:g} mm {v.knob} {v.value}: {r['status']}, {r['wall']:.1f} s, {r['cycles']} cycles, energy "
                  f"{m['energy']:.0f} J over {m['travel']:.1f} mm, mean {m['mean_force']:.2f} kN, peak "
                  f"{m['peak_force']:.1f} kN, error {r['energy_error']:.3f} %", flush=True)
            partial.write_text(json.dumps({"runs": runs}, indent=1) + "\n")
    reference = next(r for r in runs if r["size"] == finest and r["knob"] == "dt_scale"
                     and abs(float(r["value"]) - REFERENCE_DT_SCALE) < 1e-9)
    command = ("/usr/bin/python3 bench/accuracy_trade.py " + " ".join(sys.argv[1:])).strip()
    write_report(a, work, runs, reference, skipped, command)


if __name__ == "__main__":
    main()
