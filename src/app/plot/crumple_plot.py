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
"""
import os
import sys


def fail(message, code=2):
    print(f"crumple plot: {message}", file=sys.stderr)
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
    if "units" not in dataset.attrs:
        return ""
    units = text(np.atleast_1d(dataset.attrs["units"]))
    return units[column] if column is not None and column < len(units) else units[0]


def save(fig, path):
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    print(f"wrote {path}")


def energy_plot(h, name, out):
    t = h["time"][:]
    fig, ax = plt.subplots(figsize=(8, 5))
    kinetic = None
    for key, label in (("internal", "internal"), ("kinetic_translational", "kinetic, translational"),
                       ("kinetic_rotational", "kinetic, rotational"), ("hourglass", "hourglass"),
                       ("contact", "contact"), ("external_work", "external work"), ("total", "total")):
        if key in h and h[key].shape[0] == t.shape[0]:
            ax.plot(t, h[key][:], label=label, lw=2.0 if key == "total" else 1.2)
    ax.set_xlabel(f"time [{unit_of(h['time']) or 'T'}]")
    ax.set_ylabel(f"energy [{unit_of(h['internal']) if 'internal' in h else 'E'}]")
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
    ax.set_xlabel(f"time [{unit_of(h['time']) or 'T'}]")
    ax.set_ylabel("force [F]")
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
    ax.set_xlabel("time")
    ax.set_title(title)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    save(fig, path)
    return True


def main(argv):
    args, out, select = [], None, []
    i = 0
    while i < len(argv):
        a = argv[i]
        if a in ("-o", "--output"):
            out = argv[i + 1]
            i += 2
        elif a == "--select":
            i += 1
            while i < len(argv) and not argv[i].startswith("-"):
                select.append(argv[i])
                i += 1
        else:
            args.append(a)
            i += 1
    if len(args) != 1:
        fail("usage: crumple plot NAME.h5 [-o DIR] [--select PATTERN ...]")
    path = args[0]
    name = os.path.splitext(os.path.basename(path))[0]
    out = out or os.path.dirname(os.path.abspath(path))
    os.makedirs(out, exist_ok=True)
    try:
        f = h5py.File(path, "r")
    except OSError as e:
        fail(f"cannot open {path}: {e}")
    with f:
        if "history" not in f or "time" not in f["history"]:
            fail(f"{path} has no /history/time: not a Crumple results file")
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
            columns_plot(h, sections, lambda label: True, f"{name}: section forces",
                         os.path.join(out, f"{name}_sections.png"))
        if select:
            if not columns_plot(h, th, lambda label: any(p.lower() in label.lower() for p in select),
                                f"{name}: {' '.join(select)}", os.path.join(out, f"{name}_selected.png")):
                fail(f"no /history/th column matches {' '.join(select)}")


if __name__ == "__main__":
    main(sys.argv[1:])
