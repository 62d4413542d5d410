"""crumple plot: PNGs of a results file's histories (docs/output-format.md, "Plots").

Embedded in the crumple binary and run with the system Python (matplotlib, h5py):

    crumple plot NAME.h5 [-o DIR] [--select PATTERN ...]

Writes into DIR (default: beside NAME.h5):
  NAME_energy.png          the energy balance: internal, kinetic (translational, rotational), hourglass, contact,
                           external work, total
  NAME_contact.png         each interface's normal and friction force magnitudes, when the model has interfaces
  NAME_rigid_walls.png     each rigid wall's force magnitude, when it has walls
  NAME_sections.png        the /TH/SECTIO histories, when there are any
  NAME_selected.png        with --select: every /history/th column whose label contains one of the patterns
Prints one line per file written. Exit code 0; 2 when the file is not a Crumple results file, a pattern selects
nothing or matplotlib is missing.

    crumple compare A.h5 B.h5 [...] [-o DIR] [--nodes ID ...]

Runs of one model side by side (README, "Trading speed for accuracy"): a table of what decides between them (the
cycles and wall time of each run from NAME.summary.json beside it, the internal energy at the end, the peak and
mean force of each rigid wall, the final displacement of the selected nodes, each against the first run) and,
into DIR (default: beside A.h5), NAME_compare_energy.png (internal and kinetic energy of every run),
NAME_compare_walls.png (every run's wall forces) and NAME_compare_contact.png (interface forces).
"""
import json
import os
import sys


COMMAND = "crumple plot"


def fail(message, code=2):
    print(f"{COMMAND}: {message}", file=sys.stderr)
    sys.exit(code)


try:
    import h5py
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
except ImportError as e:  # the set-up installs them (scripts/install-deps.sh)
    fail(f"needs h5py and matplotlib ({e}); install python3-h5py and python3-matplotlib")


def text(values):
    return [v.decode() if isinstance(v, bytes) else str(v) for v in values]


def labels_of(dataset, fallback):
    if "labels" in dataset.attrs:
        return text(dataset.attrs["labels"])
    return [f"{fallback} {k}" for k in range(dataset.shape[1])]


def unit_of(dataset, column=None):
    """The unit of a history column by its name in the run's working units ("ms", "kN", "J"), or for a file written
    before histories carried unit names its dimension letters ("T", "F", "E")."""
    for key in ("unit_names", "unit_name", "units", "unit"):
        if key in dataset.attrs:
            units = text(np.atleast_1d(dataset.attrs[key]))
            return units[column] if column is not None and column < len(units) else units[0]
    return ""


def axis_label(quantity, unit):
    return f"{quantity} [{unit}]" if unit else quantity


def save(fig, path):
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    labels = []  # the axes' quantities and units, each once, as a reader checks them
    for ax in fig.axes:
        for label in (ax.get_xlabel(), ax.get_ylabel()):
            if label and label not in labels:
                labels.append(label)
    plt.close(fig)
    print(f"wrote {path} ({', '.join(labels)})")


def energy_plot(h, name, out):
    t = h["time"][:]
    fig, ax = plt.subplots(figsize=(8, 5))
    kinetic = None
    for key, label in (("internal", "internal"), ("kinetic_translational", "kinetic, translational"),
                       ("kinetic_rotational", "kinetic, rotational"), ("hourglass", "hourglass"),
                       ("contact", "contact"), ("external_work", "external work"), ("total", "total")):
        if key in h and h[key].shape[0] == t.shape[0]:
            ax.plot(t, h[key][:], label=label, lw=2.0 if key == "total" else 1.2)
    ax.set_xlabel(axis_label("time", unit_of(h["time"])))
    ax.set_ylabel(axis_label("energy", unit_of(h["internal"]) if "internal" in h else ""))
    ax.set_title(f"{name}: energy balance")
    ax.grid(alpha=0.3)
    ax.legend()
    save(fig, os.path.join(out, f"{name}_energy.png"))


def object_ids(dataset, per_object):
    """The deck id of each object of a global 2-D history (its `object_ids` attribute), else 1, 2, ..."""
    count = dataset.shape[1] // per_object
    if "object_ids" in dataset.attrs:
        ids = list(dataset.attrs["object_ids"])[::per_object]
        if len(ids) == count:
            return ids
    return list(range(1, count + 1))


def vector_magnitudes_plot(h, dataset, per_object, vectors, title, name, out, suffix):
    """Per object (`per_object` columns each, docs/output-format.md): the magnitudes of the force vectors whose
    first column is at each offset of `vectors` (name, offset)."""
    d = h[dataset]
    if d.ndim != 2 or d.shape[1] < per_object or d.shape[0] == 0:
        return
    t, values = h["time"][:], d[:]
    fig, ax = plt.subplots(figsize=(8, 5))
    for k, oid in enumerate(object_ids(d, per_object)):
        for label, offset in vectors:
            first = k * per_object + offset
            ax.plot(t, np.linalg.norm(values[:, first:first + 3], axis=1), label=f"{title.split()[0]} {oid}: {label}")
    ax.set_xlabel(axis_label("time", unit_of(h["time"])))
    ax.set_ylabel(axis_label("force", unit_of(d, vectors[0][1])))
    ax.set_title(f"{name}: {title}")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    save(fig, os.path.join(out, f"{name}_{suffix}.png"))


def columns_plot(h, datasets, keep, title, path):
    fig, ax = plt.subplots(figsize=(8, 5))
    t = h["time"][:]
    for d in datasets:
        if d.shape[0] != t.shape[0]:
            continue
        for k, label in enumerate(labels_of(d, d.name)):
            if keep(label):
                unit = unit_of(d, k)
                ax.plot(t, d[:, k], label=f"{label} [{unit}]" if unit else label)
    if not ax.lines:
        plt.close(fig)
        return False
    ax.set_xlabel(axis_label("time", unit_of(h["time"])))
    ax.set_title(title)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    save(fig, path)
    return True


SECTIONS_PER_FIGURE = 6


def sections_plot(h, datasets, name, out):
    """One row of panels per cut section (its forces, its moments, each in its unit), at most SECTIONS_PER_FIGURE
    rows a figure: NAME_sections.png, then NAME_sections_2.png..., never dozens of curves in one axes."""
    t = h["time"][:]
    rows = []  # (section label, [(column label, values, unit)])
    for d in datasets:
        if d.shape[0] != t.shape[0]:
            continue
        labels = labels_of(d, d.name)
        by_object = {}
        for k, label in enumerate(labels):
            obj = "/".join(label.split("/")[:2])
            by_object.setdefault(obj, []).append((label.split("/")[-1], d[:, k], unit_of(d, k)))
        rows += list(by_object.items())
    time_label = axis_label("time", unit_of(h["time"]))
    for first in range(0, len(rows), SECTIONS_PER_FIGURE):
        chunk = rows[first:first + SECTIONS_PER_FIGURE]
        fig, axes = plt.subplots(len(chunk), 2, figsize=(11, 2.6 * len(chunk)), squeeze=False)
        for (section, columns), (force_ax, moment_ax) in zip(chunk, axes):
            units = [u for _, _, u in columns]
            force_unit = units[0] if units else ""
            for ax, wanted, quantity in ((force_ax, lambda u: u == force_unit, "force"),
                                         (moment_ax, lambda u: u != force_unit, "moment, work")):
                for variable, values, unit in columns:
                    if wanted(unit):
                        ax.plot(t, values, label=f"{variable} [{unit}]" if unit else variable, lw=1.0)
                ax.set_title(f"{section}: {quantity}", fontsize=9)
                ax.grid(alpha=0.3)
                if ax.lines:
                    ax.legend(fontsize=6, ncol=3)
            force_ax.set_ylabel(axis_label("force", force_unit))
        for ax in axes[-1]:
            ax.set_xlabel(time_label)
        suffix = "" if first == 0 else f"_{first // SECTIONS_PER_FIGURE + 1}"
        save(fig, os.path.join(out, f"{name}_sections{suffix}.png"))


def open_results(path):
    """A Crumple results file opened for reading; bad input (exit code 2) when it is not one."""
    try:
        f = h5py.File(path, "r")
    except OSError as e:
        fail(f"cannot open {path}: {e}")
    if "history" not in f or "time" not in f["history"]:
        f.close()
        fail(f"{path} has no /history/time: not a Crumple results file")
    return f


def parse_arguments(argv, list_options):
    """The positional arguments, -o/--output's folder, and the values after each option of `list_options` (the
    command line crumple has checked already)."""
    positional, out, lists = [], None, {option: [] for option in list_options}
    i = 0
    while i < len(argv):
        a = argv[i]
        if a in ("-o", "--output") and i + 1 < len(argv):
            out = argv[i + 1]
            i += 2
        elif a in lists:
            i += 1
            while i < len(argv) and not argv[i].startswith("-"):
                lists[a].append(argv[i])
                i += 1
        else:
            positional.append(a)
            i += 1
    return positional, out, lists


def main(argv):
    args, out, lists = parse_arguments(argv, ("--select",))
    select = lists["--select"]
    if len(args) != 1:
        fail("usage: crumple plot NAME.h5 [-o DIR] [--select PATTERN ...]")
    path = args[0]
    name = os.path.splitext(os.path.basename(path))[0]
    out = out or os.path.dirname(os.path.abspath(path))
    os.makedirs(out, exist_ok=True)
    with open_results(path) as f:
        h = f["history"]
        energy_plot(h, name, out)
        if "interface_values" in h:  # FNX FNY FNZ FTX FTY FTZ and 4 energies per interface
            vector_magnitudes_plot(h, "interface_values", 10, (("|FN|", 0), ("|FT|", 3)), "interface forces", name,
                                   out, "contact")
        if "rigid_wall_force" in h:  # FX FY FZ per wall
            vector_magnitudes_plot(h, "rigid_wall_force", 3, (("|F|", 0),), "wall forces", name, out, "rigid_walls")
        th = [h["th"][k] for k in h["th"]] if "th" in h else []
        sections = [d for d in th if os.path.basename(d.name).upper().startswith("SECTIO")]
        if sections:
            sections_plot(h, sections, name, out)
        if select:
            if not columns_plot(h, th, lambda label: any(p.lower() in label.lower() for p in select),
                                f"{name}: {' '.join(select)}", os.path.join(out, f"{name}_selected.png")):
                fail(f"no /history/th column matches {' '.join(select)}")


# ---- crumple compare ----

class Run:
    """One run of a comparison: its histories, its last frame's displacements and its summary."""

    def __init__(self, path):
        self.path = path
        with open_results(path) as f:
            h = f["history"]
            self.time = h["time"][:]
            self.units = {key: unit_of(h[key]) for key in ("time", "internal") if key in h}
            self.series = {key: h[key][:] for key in ("internal", "kinetic_translational", "kinetic_rotational")
                           if key in h}
            self.walls = self.vectors(h, "rigid_wall_force", 3, 0)
            self.contacts = self.vectors(h, "interface_values", 10, 0)
            self.force_unit = unit_of(h["rigid_wall_force"], 0) if "rigid_wall_force" in h else ""
            self.node_ids = f["mesh/node_ids"][:] if "mesh/node_ids" in f else np.zeros(0, dtype=int)
            frames = sorted(f["frames"], key=int) if "frames" in f else []
            self.displacement = f[f"frames/{frames[-1]}/displacement"][:] if frames else None
            self.length_unit = unit_name_of(f, "L")
        summary = os.path.splitext(path)[0] + ".summary.json"
        self.summary = {}
        if os.path.exists(summary):
            with open(summary) as s:
                self.summary = json.load(s)

    @staticmethod
    def vectors(h, name, per_object, offset):
        """The magnitude of each object's vector (its first 3 columns from `offset`) over time."""
        if name not in h or h[name].ndim != 2 or h[name].shape[1] < per_object:
            return {}
        d = h[name]
        values = d[:]
        return {oid: np.linalg.norm(values[:, k * per_object + offset:k * per_object + offset + 3], axis=1)
                for k, oid in enumerate(object_ids(d, per_object))}

    def label(self, others):
        """The run's folder name (out_draft/TUBE.h5: out_draft), or its path when folders repeat."""
        folder = os.path.basename(os.path.dirname(os.path.abspath(self.path)))
        folders = [os.path.basename(os.path.dirname(os.path.abspath(o.path))) for o in others]
        return folder if folders.count(folder) == 1 else self.path

    def end(self, key):
        values = self.series.get(key)
        return float(values[-1]) if values is not None and len(values) else float("nan")

    def node_displacement(self, node):
        if self.displacement is None:
            return float("nan")
        rows = np.flatnonzero(self.node_ids == node)
        return float(np.linalg.norm(self.displacement[rows[0]])) if len(rows) else float("nan")


def unit_name_of(f, letters):
    """The name of a base or named unit (M, L, T, F, E, F/L^2) in a file's working units (its root attribute
    `working_unit_names`), or "" in a file written without it."""
    order = ("M", "L", "T", "F", "E", "F/L^2")
    if "working_unit_names" not in f.attrs or letters not in order:
        return ""
    names = text(np.atleast_1d(f.attrs["working_unit_names"]))
    return names[order.index(letters)] if len(names) == len(order) else ""


def relative(value, first):
    if not np.isfinite(value) or not np.isfinite(first) or first == 0:
        return "-"
    return f"{100.0 * (value - first) / abs(first):+.1f} %"


def mean_over_time(t, values):
    if len(t) < 2 or t[-1] <= t[0]:
        return float("nan")
    return float(np.trapz(values, t) / (t[-1] - t[0]))


def compare_table(runs, nodes):
    """Rows of the comparison: each run's numbers, each against the first run's."""
    labels = [r.label(runs) for r in runs]
    energy = runs[0].units.get("internal", "")
    columns = [("cycles", lambda r: r.summary.get("cycles_total", float("nan")), "{:.0f}"),
               ("wall time [s]", lambda r: r.summary.get("wall_seconds", float("nan")), "{:.2f}"),
               (f"IE at the end [{energy}]", lambda r: r.end("internal"), "{:.5g}")]
    for wall in runs[0].walls:
        columns.append((f"wall {wall} peak [{runs[0].force_unit}]",
                        lambda r, w=wall: float(np.max(r.walls[w])) if w in r.walls else float("nan"), "{:.5g}"))
        columns.append((f"wall {wall} mean [{runs[0].force_unit}]",
                        lambda r, w=wall: mean_over_time(r.time, r.walls[w]) if w in r.walls else float("nan"),
                        "{:.5g}"))
    for node in nodes:
        columns.append((f"node {node} |u| [{runs[0].length_unit}]", lambda r, n=node: r.node_displacement(n),
                        "{:.5g}"))
    print(f"{'run':<24} " + " ".join(f"{name:>22}" for name, _, _ in columns))
    for k, run in enumerate(runs):
        cells = []
        for name, value, form in columns:
            v = float(value(run))
            shown = form.format(v) if np.isfinite(v) else "-"
            if k > 0:
                shown += f" ({relative(v, float(value(runs[0])))})"
            cells.append(f"{shown:>22}")
        print(f"{labels[k]:<24} " + " ".join(cells))
    print("(each run against the first; cycles and wall time from NAME.summary.json beside each file)")


def compare_plots(runs, name, out):
    labels = [r.label(runs) for r in runs]
    time_label = axis_label("time", runs[0].units.get("time", ""))
    fig, ax = plt.subplots(figsize=(8, 5))
    for run, label in zip(runs, labels):
        if "internal" in run.series:
            ax.plot(run.time, run.series["internal"], label=f"{label}: internal")
        if "kinetic_translational" in run.series:
            ax.plot(run.time, run.series["kinetic_translational"], ls="--", label=f"{label}: kinetic")
    ax.set_xlabel(time_label)
    ax.set_ylabel(axis_label("energy", runs[0].units.get("internal", "")))
    ax.set_title(f"{name}: runs compared")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    save(fig, os.path.join(out, f"{name}_compare_energy.png"))
    for attribute, suffix, title in (("walls", "walls", "wall force"), ("contacts", "contact", "interface normal force")):
        if not any(getattr(r, attribute) for r in runs):
            continue
        fig, ax = plt.subplots(figsize=(8, 5))
        for run, label in zip(runs, labels):
            for oid, values in getattr(run, attribute).items():
                ax.plot(run.time, values, label=f"{label}: {oid}", lw=1.0)
        ax.set_xlabel(time_label)
        ax.set_ylabel(axis_label("force", runs[0].force_unit))
        ax.set_title(f"{name}: {title}, runs compared")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
        save(fig, os.path.join(out, f"{name}_compare_{suffix}.png"))


def compare_main(argv):
    files, out, lists = parse_arguments(argv, ("--nodes",))
    nodes = []
    for node in lists["--nodes"]:
        try:
            nodes.append(int(node))
        except ValueError:
            fail(f"--nodes takes node ids, not {node}")
    if len(files) < 2:
        fail("usage: crumple compare A.h5 B.h5 [...] [-o DIR] [--nodes ID ...]")
    runs = [Run(p) for p in files]
    for node in nodes:
        if node not in runs[0].node_ids:
            fail(f"node {node} is not in {runs[0].path}")
    name = os.path.splitext(os.path.basename(files[0]))[0]
    out = out or os.path.dirname(os.path.abspath(files[0]))
    os.makedirs(out, exist_ok=True)
    compare_table(runs, nodes)
    compare_plots(runs, name, out)


if __name__ == "__main__":
    if sys.argv[1:2] == ["compare"]:
        COMMAND = "crumple compare"
        compare_main(sys.argv[2:])
    else:
        main(sys.argv[1:])
