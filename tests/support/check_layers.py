#!/usr/bin/env python3
"""Checks the layering of Crumple's sources (docs/architecture.md, "Layers"): a file of one layer includes
headers of its own layer and of the layers below it, never of a layer above or beside it.

    core -> model -> state -> materials -> elements -> solver -> output -> app
                          \\-> contact ------------/
                          \\-> parallel -----------/
    core -> model -> deck -> app

Usage: check_layers.py SOURCE_DIR. Prints every include that breaks the order (file, line, include) and exits 1
when there is one, 0 otherwise.
"""
import re
import sys
from pathlib import Path

# The layers each layer may include, besides itself.
BELOW = {
    "core": set(),
    "model": {"core"},
    "state": {"core", "model"},
    "materials": {"core", "model", "state"},
    "elements": {"core", "model", "state", "materials"},
    "contact": {"core", "model", "state"},
    "parallel": {"core", "model", "state"},
    "deck": {"core", "model"},
    "solver": {"core", "model", "state", "materials", "elements", "contact", "parallel"},
    "output": {"core", "model", "state", "materials", "elements", "contact", "parallel", "solver"},
    "app": {"core", "model", "state", "materials", "elements", "contact", "parallel", "solver", "output", "deck"},
}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')


def layer_of_file(path, root):
    """The layer of a project file: include/crumple/<layer>/... or src/<layer>/..."""
    parts = path.relative_to(root).parts
    if parts[0] == "include" and len(parts) > 2:
        return parts[2]
    if parts[0] == "src" and len(parts) > 1:
        return parts[1]
    return None


def layer_of_include(text):
    """The layer of an included header: "crumple/<layer>/x.hpp" or a private "<layer>/x.hpp"; None for a header
    of the file's own folder ("resolve.hpp")."""
    parts = text.split("/")
    if parts[0] == "crumple" and len(parts) > 2:
        return parts[1]
    if len(parts) > 1 and parts[0] in BELOW:
        return parts[0]
    return None


def main(root):
    root = Path(root)
    problems = []
    files = [p for d in ("include/crumple", "src") for p in (root / d).rglob("*") if p.suffix in (".hpp", ".cpp", ".h")]
    for path in sorted(files):
        layer = layer_of_file(path, root)
        if layer not in BELOW:
            problems.append(f"{path.relative_to(root)}: not in a known layer folder ({', '.join(BELOW)})")
            continue
        for number, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
            m = INCLUDE.match(line)
            if not m:
                continue
            target = layer_of_include(m.group(1))
            if target is None or target == layer:
                continue
            if target not in BELOW.get(layer, set()):
                problems.append(f"{path.relative_to(root)}:{number}: the {layer} layer includes \"{m.group(1)}\" "
                                f"of the {target} layer, which is not below it")
    for p in problems:
        print(p)
    print(f"{len(files)} files checked, {len(problems)} layering problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "."))
