#!/usr/bin/python3
"""Whole-run benchmark of issue 13: writes the benchmark decks of decks/generate_bench.py for a list of sizes, runs
`crumple run` on each, and prints and writes as Markdown what a run costs:

  - ns per element-cycle (the time loop's wall time / (elements x cycles)), by element kind, the element
    phase's part of it, and the whole process's CPU time (deck reading included) per element-cycle, which a
    loaded machine disturbs less than wall time;
  - contact ns per secondary node-cycle (contact phase / (secondary nodes x contact passes)), the nodes in
    contact (ACTIVE_NODES of the interface histories in NAME.h5, read with h5py) and the contact's,
    the output's share of the cycle (the phases of NAME.summary.json), and the share of the contact's searches
    (`contact_sort`: the bucket sorts);
  - peak memory (the run's peak RSS, from /usr/bin/time) per element, and its slope against the element count;
  - the exponent of the cost per cycle against the element count, fitted by least squares on log-log;
  - each time figure also against a memory-bandwidth probe run in the same invocation (a numpy copy of a
    200 MB array, best of 5): ns x GB/s, the bytes the machine copies in that time.

Run (from the repository, after `cmake --build --preset release`):
    /usr/bin/python3 bench/run_bench.py                 # 1e3, 1e4, 3e4 elements, 0.1 ms: a few minutes
    /usr/bin/python3 bench/run_bench.py --large         # adds 1e5 and 1e6 elements (long, and 1e6 needs GBs)
    /usr/bin/python3 bench/run_bench.py --sizes 1000 --families tube --output OUT.md
Decks and results go to --work (default build/bench-work), the Markdown table to --output (default
WORK/bench.md). Generated decks are not kept in the repository.
"""
import argparse
import datetime
import json
import math
import re
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "decks"))
import generate_bench  # noqa: E402

DEFAULT_SIZES = [1000, 10000, 30000]
LARGE_SIZES = [100000, 1000000]
KIND_OF_FAMILY = {"tube": "4-node shell, Ishell 24, 5 points, JC", "ball_plate": "4-node shell, Ishell 24, 5 points, JC",
                  "brick_block": "8-node brick, Isolid 24, JC"}
CHECK_COUNTS = {"nodes": "nodes", "shell4": "4-node shells", "shell3": "3-node shells", "brick8": "8-node bricks"}


# ---------------------------------------------------------------------------------------------- measurements


def bandwidth_probe(megabytes=200, repeats=5):
    """Copies a `megabytes` array into another, best of `repeats`; GB/s counting the read and the write."""
    source = np.ones(int(megabytes * 1e6) // 8)
    target = np.empty_like(source)
    np.copyto(target, source)  # touch both once
    best = math.inf
    for _ in range(repeats):
        start = time.perf_counter()
        np.copyto(target, source)
        best = min(best, time.perf_counter() - start)
    return {"megabytes": megabytes, "seconds": best, "gb_per_s": 2 * source.nbytes / best / 1e9}


def check_counts(crumple, deck):
    """Element and node counts printed by `crumple check`; its exit code must be 0."""
    done = subprocess.run([crumple, "check", str(deck)], capture_output=True, text=True)
    if done.returncode != 0:
        raise RuntimeError(f"crumple check {deck} exited with {done.returncode}:\n{done.stdout}{done.stderr}")
    counts = {}
    for key, label in CHECK_COUNTS.items():
        found = re.search(rf"^  {re.escape(label)} +(\d+)$", done.stdout, re.M)
        counts[key] = int(found.group(1)) if found else 0
    return counts


def run_crumple(crumple, deck, out_dir, timeout):
    """`crumple run` under /usr/bin/time: its process wall time [s], peak RSS [bytes] and CPU time (user + system)
    [s].

    The peak RSS is GNU time's %M, not this script's own wait4: a child forked from this process would count
    this process's memory (the bandwidth probe's arrays) in its peak, since Linux keeps the high-water mark of the
    memory replaced by exec; a child of the small `time` process counts only a few hundred kB of it.
    """
    out_dir.mkdir(parents=True, exist_ok=True)
    rss_file = out_dir / "time_rss_kb_user_system"
    command = ["/usr/bin/time", "-f", "%M %U %S", "-o", str(rss_file), crumple, "run", str(deck), "-o", str(out_dir)]
    with open(out_dir / "console.log", "w") as log:
        start = time.perf_counter()
        done = subprocess.run(command, stdout=log, stderr=subprocess.STDOUT, timeout=timeout)
        wall = time.perf_counter() - start
    if done.returncode != 0:
        raise RuntimeError(f"crumple run {deck} exited with {done.returncode}: see {out_dir / 'console.log'}")
    rss_kb, user, system = rss_file.read_text().split()[-3:]
    return wall, int(rss_kb) * 1024, float(user) + float(system)


def nodes_in_contact(out_dir):
    """Mean and largest number of active secondary nodes over the history rows (every interface summed), from
    the ACTIVE_NODES columns of /history/interface_values in NAME.h5; None without interfaces."""
    import h5py  # only here: the rest of the driver runs without it
    with h5py.File(next(out_dir.glob("*.h5")), "r") as f:
        values = f["history/interface_values"]
        names = [v.decode() if isinstance(v, bytes) else str(v) for v in values.attrs.get("variables", [])]
        columns = [k for k, v in enumerate(names) if v == "ACTIVE_NODES"]
        if not columns or values.shape[0] == 0:
            return None
        active = values[:, columns].sum(axis=1)
    return float(active.mean()), float(active.max())


def largest_penetration(out_dir):
    """The largest penetration over gap of the run's interfaces, from the listing's INTER lines (None: none)."""
    listing = next(out_dir.glob("*.out")).read_text()
    values = [float(v) for v in re.findall(r"^INTER \d+: largest p/g ([0-9.eE+-]+)", listing, re.M)]
    return max(values) if values else None


def measure(crumple, family, size, work, end_time, timeout, repeats):
    """Writes one deck, checks it, runs it `repeats` times; returns the raw figures of the fastest run (by the
    time loop's wall time: on a shared machine the least disturbed) and every run's loop wall time."""
    deck_dir = work / f"{family}_{size}"
    deck = generate_bench.write_family(family, deck_dir, elements=size, end_time=end_time)
    meta = json.loads((deck_dir / deck.name.replace("_0000.rad", ".bench.json")).read_text())
    counts = check_counts(crumple, deck)
    elements = counts["shell4"] + counts["shell3"] + counts["brick8"]
    written = sum(meta["counts"].get(k, 0) for k in ("shell4", "shell3", "brick8"))
    if elements != written:
        raise RuntimeError(f"{deck}: crumple check counts {elements} elements, the generator wrote {written}")
    runs = []
    for k in range(repeats):
        out_dir = deck_dir / f"out{k + 1}"
        process_wall, peak_rss, cpu = run_crumple(crumple, deck, out_dir, timeout)
        summary = json.loads(next(out_dir.glob("*.summary.json")).read_text())
        runs.append((summary["wall_seconds"], process_wall, peak_rss, cpu, summary, out_dir))
    walls = [r[0] for r in runs]
    _, process_wall, peak_rss, cpu, summary, out_dir = min(runs, key=lambda r: r[0])
    return {"family": family, "target": size, "elements": elements, "nodes": counts["nodes"],
            "secondary_nodes": meta["counts"]["contact_secondary_nodes"], "cycles": summary["cycles"],
            "wall": summary["wall_seconds"], "process_wall": process_wall, "process_cpu": cpu, "peak_rss": peak_rss,
            "profile": summary["profile"], "status": summary["status"], "walls": walls,
            "largest_p_over_g": largest_penetration(out_dir), "in_contact": nodes_in_contact(out_dir)}


# ------------------------------------------------------------------------------------------------ the figures


def figures(r):
    """The per-run figures of issue 13 from one run's raw numbers."""
    p, element_cycles = r["profile"], r["elements"] * r["cycles"]
    cycle = p["elements"] + p["contact"] + p["loads"] + p["update"] + p["output"]
    passes, secondary = p["contact_passes"], r["secondary_nodes"]
    return {"ns_per_element_cycle": 1e9 * r["wall"] / element_cycles,
            "cpu_ns_per_element_cycle": 1e9 * r["process_cpu"] / element_cycles,
            "element_phase_ns": 1e9 * p["elements"] / element_cycles,
            "contact_ns_per_node_cycle": 1e9 * p["contact"] / (secondary * passes) if secondary and passes else None,
            "contact_share": p["contact"] / cycle if passes else None,
            "sort_share": p.get("contact_sort", 0.0) / cycle if passes else None,
            "output_share": p["output"] / cycle,
            "bytes_per_element": r["peak_rss"] / r["elements"],
            "seconds_per_cycle": r["wall"] / r["cycles"]}


def fit_slope(xs, ys, log=True):
    """Least-squares slope of y against x (of log y against log x when `log`); None below two sizes."""
    if len(set(xs)) < 2:
        return None
    if log:
        xs, ys = [math.log(x) for x in xs], [math.log(y) for y in ys]
    return float(np.polyfit(xs, ys, 1)[0])


def family_fits(runs):
    """Per family: the cost exponent (time per cycle against elements) and peak RSS bytes per added element."""
    fits = {}
    for family in dict.fromkeys(r["family"] for r in runs):
        mine = [r for r in runs if r["family"] == family]
        elements = [r["elements"] for r in mine]
        fits[family] = {"exponent": fit_slope(elements, [r["wall"] / r["cycles"] for r in mine]),
                        "element_phase_exponent": fit_slope(elements, [r["profile"]["elements"] / r["cycles"]
                                                                       for r in mine]),
                        "marginal_bytes": fit_slope(elements, [r["peak_rss"] for r in mine], log=False),
                        "sizes": len(mine)}
    return fits


# ---------------------------------------------------------------------------------------------------- report


def text(v, fmt="{:.0f}"):
    return "n/a" if v is None else fmt.format(v)


def machine():
    """CPU model and count from lscpu (it gives no cache sizes on this machine)."""
    try:
        out = subprocess.run(["lscpu"], capture_output=True, text=True).stdout
    except OSError:
        return "lscpu not available"
    field = lambda name: (re.search(rf"^{name}:\s*(.+)$", out, re.M) or [None, "?"])[1].strip()
    cpus, threads = field(r"CPU\(s\)"), field(r"Thread\(s\) per core")
    guest = ", a virtual machine" if re.search(r"^Flags:.*\bhypervisor\b", out, re.M) else ""
    return (f"{field('Model name')} (CPU family {field('CPU family')}, model {field('Model')}), {cpus} CPUs, "
            f"{threads} thread(s) per core{guest}")


def cost_table(runs, probe):
    gbps = probe["gb_per_s"]
    head = ("| deck | element kind | elements | cycles | loop wall [s], fastest (all runs) | process wall, CPU [s] "
            "| ns / element-cycle | x GB/s [B] | element phase ns / element-cycle | process CPU ns / element-cycle "
            "| peak RSS [MB] | B / element |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n")
    rows = []
    for r in runs:
        f = figures(r)
        walls = ", ".join(f"{w:.2f}" for w in r["walls"])
        rows.append(f"| {r['family']} {r['target']:.0e} | {KIND_OF_FAMILY[r['family']]} | {r['elements']} "
                    f"| {r['cycles']} | {r['wall']:.2f} ({walls}) | {r['process_wall']:.2f}, {r['process_cpu']:.2f} "
                    f"| {f['ns_per_element_cycle']:.0f} | {f['ns_per_element_cycle'] * gbps:.0f} "
                    f"| {f['element_phase_ns']:.0f} | {f['cpu_ns_per_element_cycle']:.0f} | {r['peak_rss'] / 1e6:.0f} | {f['bytes_per_element']:.0f} |")
    return head + "\n".join(rows) + "\n"


def in_contact(r):
    """Mean / most secondary nodes in contact over the run, with the most as a share of the secondary nodes."""
    if not r["in_contact"] or not r["secondary_nodes"]:
        return "-"
    mean, most = r["in_contact"]
    return f"{mean:.0f} / {most:.0f} ({100 * most / r['secondary_nodes']:.1f} %)"


def contact_table(runs, probe):
    gbps = probe["gb_per_s"]
    head = ("| deck | secondary nodes | in contact, mean / most | contact passes | largest p/g "
            "| contact ns / secondary node-cycle | x GB/s [B] | contact share | sort share | output share |\n"
            "|---|---|---|---|---|---|---|---|---|---|\n")
    rows = []
    for r in runs:
        f = figures(r)
        contact, share, sort = f["contact_ns_per_node_cycle"], f["contact_share"], f["sort_share"]
        rows.append(f"| {r['family']} {r['target']:.0e} | {r['secondary_nodes'] or '-'} | {in_contact(r)} "
                    f"| {r['profile']['contact_passes']} | {text(r['largest_p_over_g'], '{:.4f}')} "
                    f"| {text(contact, '{:.1f}')} | {text(contact and contact * gbps)} "
                    f"| {text(share and 100 * share, '{:.1f} %')} | {text(sort and 100 * sort, '{:.1f} %')} "
                    f"| {100 * f['output_share']:.1f} % |")
    return head + "\n".join(rows) + "\n"


def fit_table(runs):
    head = ("| deck family | element kind | sizes | cost exponent (loop time per cycle) | element phase exponent "
            "| peak RSS per added element [B] |\n|---|---|---|---|---|---|\n")
    rows = [f"| {family} | {KIND_OF_FAMILY[family]} | {fit['sizes']} | {text(fit['exponent'], '{:.3f}')} "
            f"| {text(fit['element_phase_exponent'], '{:.3f}')} | {text(fit['marginal_bytes'])} |"
            for family, fit in family_fits(runs).items()]
    return head + "\n".join(rows) + "\n"


def report(runs, probes, command, end_time):
    gbps = probes[0]["gb_per_s"]
    lines = [f"Command: `{command}`  ", f"Date: {datetime.date.today().isoformat()}; machine: {machine()}  ",
             f"End time {end_time:g} ms for every deck. Memory-bandwidth probe (numpy copy of a "
             f"{probes[0]['megabytes']} MB array, best of 5, read + write counted): "
             + ", ".join(f"{p['gb_per_s']:.2f} GB/s" for p in probes) + " (before, after the runs); the"
             f" x GB/s columns use the first, {gbps:.2f} GB/s.", "", cost_table(runs, probes[0]), contact_table(runs, probes[0]), fit_table(runs)]
    return "\n".join(lines)


def parse_arguments():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--sizes", type=float, nargs="+", default=DEFAULT_SIZES, help="target element counts")
    p.add_argument("--large", action="store_true", help="add 1e5 and 1e6 elements")
    p.add_argument("--families", nargs="+", default=list(generate_bench.FAMILIES), choices=generate_bench.FAMILIES)
    p.add_argument("--end-time", type=float, default=0.1, help="end time of every deck [ms] (default 0.1)")
    p.add_argument("--crumple", default=str(ROOT / "build/release/src/crumple"))
    p.add_argument("--work", default=str(ROOT / "build/bench-work"), help="decks and results (default build/bench-work)")
    p.add_argument("--output", help="Markdown file (default WORK/bench.md)")
    p.add_argument("--probe-mb", type=float, default=200, help="size of the bandwidth probe's array [MB]")
    p.add_argument("--timeout", type=float, default=3600, help="per run [s]")
    p.add_argument("--repeats", type=int, default=3, help="runs of each deck, the fastest reported (default 3)")
    return p.parse_args()


def main():
    a = parse_arguments()
    sizes = sorted({int(s) for s in a.sizes} | (set(LARGE_SIZES) if a.large else set()))
    work = Path(a.work).resolve()
    probes = [bandwidth_probe(a.probe_mb)]
    print(f"bandwidth probe: {probes[0]['gb_per_s']:.2f} GB/s", flush=True)
    runs = []
    for family in a.families:
        for size in sizes:
            r = measure(a.crumple, family, size, work, a.end_time, a.timeout, a.repeats)
            runs.append(r)
            f = figures(r)
            print(f"{family} {size}: {r['elements']} elements, {r['cycles']} cycles, {r['wall']:.2f} s, "
                  f"{f['ns_per_element_cycle']:.0f} ns per element-cycle, peak RSS {r['peak_rss'] / 1e6:.0f} MB",
                  flush=True)
    probes.append(bandwidth_probe(a.probe_mb))
    command = "/usr/bin/python3 bench/run_bench.py " + " ".join(sys.argv[1:])
    markdown = report(runs, probes, command.strip(), a.end_time)
    output = Path(a.output) if a.output else work / "bench.md"
    output.parent.mkdir(parents=True, exist_ok=True)
    output.write_text(markdown)
    (output.with_suffix(".json")).write_text(json.dumps({"runs": runs, "probes": probes}, indent=1) + "\n")
    print("\n" + markdown + f"\nwrote {output} and {output.with_suffix('.json')}")


if __name__ == "__main__":
    main()
