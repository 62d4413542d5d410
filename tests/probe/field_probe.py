#!/usr/bin/env python3
"""The field probe (issue 27, item 5; docs/validation.md, "Field probe").

For each deck folder given, change each written physics value of its starter and engine decks, one at a time, run
Crumple on the changed deck, and sort the change by what Crumple did with it:

  effect   the run's energies (internal, kinetic, hourglass, external work, cycles) differ from the deck as written;
  error    the deck is refused with a message (exit code 2);
  warning  the run passes with a warning it did not give before (an output-only field, or one the reference
           itself ignores);
  silent   none of these: a value read and dropped. The probe fails on any.

A run past the time limit (--timeout) is an effect when a listing row it printed differs from the deck as
written's at the same cycle, and fails the probe as "timeout" otherwise.

A value is a non-blank token of a data line whose text parses as a number: a real (with a '.' or an exponent) is
multiplied by 1.37 (0 becomes 0.37 in the token's place), an integer flag below 100 gets 1 added. The token is
rewritten in its own columns, right-aligned, so the field keeps its place. Not probed: titles, node and element
cards (/NODE, /SHELL, /SH3N, /BRICK: geometry and connectivity), id lists (/GRNOD, /GRSHEL, /GRSH3N, /GRBRIC,
/SURF, /SUBSET), and integers of 100 or more (ids). Blank fields (defaults) are not probed: without the card's
layout their columns are unknown.

Usage: field_probe.py CRUMPLE DECK_FOLDER... [--jobs N] [--markdown] [--limit N]
It takes minutes per deck (one run per value); it is not part of .ci/run.
"""
import argparse
import concurrent.futures
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

SKIPPED = ("/NODE", "/SHELL", "/SH3N", "/BRICK", "/GRNOD", "/GRSHEL", "/GRSH3N", "/GRBRIC", "/SURF", "/SUBSET",
           "/BEGIN", "/TITLE", "/RUN", "/VERS", "/END", "/TH/", "/ANIM", "/PRINT", "/TFILE", "/MON", "/RFILE",
           "/SECT", "/ACCEL")  # the last: output definitions, whose values act on the histories, not the energies
NUMBER = re.compile(r"^[-+]?(\d+\.?\d*|\.\d+)([eEdD][-+]?\d+)?$")


def decks_of(folder):
    starters = sorted(f for f in os.listdir(folder) if f.endswith("_0000.rad"))
    if not starters:
        return None
    name = starters[0][: -len("_0000.rad")]
    files = [f for f in sorted(os.listdir(folder)) if f.startswith(name + "_") and f.endswith(".rad")]
    return name, files


def candidates(path):
    """(line index, start, end, token) of every probed value of one deck file."""
    out = []
    lines = open(path, errors="replace").read().split("\n")
    keyword = None
    keyword_line = -1
    first_data = False
    for n, text in enumerate(lines):
        if text.startswith("#") or text.startswith("$"):
            continue
        if text.startswith("/"):
            keyword = text.strip().upper()
            keyword_line = n
            first_data = True
            continue
        if keyword is None or keyword.startswith(SKIPPED):
            continue
        stripped = text.strip()
        if not stripped:
            continue
        tokens = [(m.start(), m.end(), m.group()) for m in re.finditer(r"\S+", text)]
        # A first data line with a word that is no number is a title (the cards that have one).
        if first_data and any(not NUMBER.match(t) for _, _, t in tokens):
            first_data = False
            continue
        first_data = False
        for start, end, token in tokens:
            if not NUMBER.match(token):
                continue
            is_real = any(c in token for c in ".eEdD")
            if not is_real and abs(int(float(token))) >= 100:
                continue
            out.append((n, start, end, token, keyword_line))
    return out


def mutations(token):
    """Non-default values to try in turn: the first that Crumple does something with settles the field (a flag's
    next value may mean its default, a threshold may not be reached with a small change)."""
    if any(c in token for c in ".eEdD"):
        value = float(token.replace("d", "e").replace("D", "e"))
        if value == 0.0:
            return ["0.37", "37.0"]
        return [repr(value * 1.37), repr(value * 0.1), repr(value * 10.0)]
    value = int(token)
    return [str(v) for v in (value + 1, value + 2, value + 3, value + 4, 37) if v != value]


def listing_rows(out_dir):
    """The energy rows of the run's listing (flushed row by row, so a run stopped at the time limit leaves the rows
    it printed): cycle -> the row's numbers (time, step, error, energies, masses)."""
    rows = {}
    listings = [f for f in os.listdir(out_dir) if f.endswith(".out")] if os.path.isdir(out_dir) else []
    for name in listings:
        for line in open(os.path.join(out_dir, name), errors="replace"):
            t = line.split()
            if len(t) < 10 or not t[0].isdigit():
                continue
            numbers = []
            for token in t[1:]:
                try:
                    numbers.append(float(token.rstrip("%")))
                except ValueError:
                    pass
            rows[(name, int(t[0]))] = numbers
    return rows


def run(crumple, folder, starter, out_dir, timeout):
    try:
        p = subprocess.run([crumple, "run", os.path.join(folder, starter), "-o", out_dir, "--quiet"],
                           capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return {"code": "timeout", "output": "", "rows": listing_rows(out_dir)}
    result = {"code": p.returncode, "output": p.stdout + p.stderr, "rows": listing_rows(out_dir)}
    summaries = [f for f in os.listdir(out_dir) if f.endswith(".summary.json")] if os.path.isdir(out_dir) else []
    if summaries:
        s = json.load(open(os.path.join(out_dir, summaries[0])))
        e = s.get("energy", {})
        result["values"] = [e.get(k, 0.0) for k in ("internal", "kinetic_translational", "kinetic_rotational",
                                                    "hourglass", "external_work")] + [s.get("cycles", 0)]
    return result


def warnings_of(output):
    # Without the folder a deck was read from: the changed deck runs from a copy.
    return {re.sub(r"\S*/([^/\s]+\.rad)", r"\1", line) for line in output.splitlines() if line.startswith("warning:")}


def differs(a, b):
    if len(a) != len(b):
        return True
    if not a:
        return False
    scale = max(max(abs(x) for x in a), max(abs(x) for x in b), 1e-300)
    return any(abs(x - y) > 1e-12 * scale for x, y in zip(a, b))


def probe_one(crumple, folder, files, file_name, item, base, timeout):
    for new in mutations(item[3]):
        r = probe_value(crumple, folder, files, file_name, item, new, base, timeout)
        if r["kind"] != "silent":
            break
    return r


def card_warned(base, file_name, keyword_line):
    """Whether the deck as written already has a warning about the whole card (an output-only or performance-hint
    card): its fields are then named by it."""
    marker = f"{file_name}:{keyword_line + 1}:"
    return any(marker in w and ("card" in w or "performance hint" in w) for w in warnings_of(base["output"]))


def field_name(folder, file_name, n, end):
    """The field's name in the comment line above its data line (the shared decks right-align each name over its
    columns): the name whose last column is nearest the value's last column, within one 20-column field."""
    lines = open(os.path.join(folder, file_name), errors="replace").read().split("\n")
    header = next((lines[i] for i in range(n - 1, -1, -1) if lines[i].startswith(("#", "$"))
                   or lines[i].startswith("/")), "")
    if not header.startswith(("#", "$")):
        return None
    names = [(abs(m.end() - end), m.group()) for m in re.finditer(r"[A-Za-z][\w%]*", header) if end - 20 < m.end() <= end + 1]
    return min(names)[1] if names else None


def field_warned(base, folder, file_name, item):
    """Whether the deck as written already has a warning on the value's card that names its field (hm, hf and hr
    with Ishell 12): a changed value then draws the same warning, not a new one, and is no silent drop."""
    n, start, end, token, keyword_line = item
    name = field_name(folder, file_name, n, end)
    if not name:
        return False
    for w in warnings_of(base["output"]):
        m = re.match(r"warning: " + re.escape(file_name) + r":(\d+):", w)
        if m and keyword_line < int(m.group(1)) <= n + 1 and re.search(r"\b" + re.escape(name) + r"\b", w):
            return True
    return False


def probe_value(crumple, folder, files, file_name, item, new, base, timeout):
    n, start, end, token = item[:4]
    work = tempfile.mkdtemp(prefix="probe_")
    try:
        for f in os.listdir(folder):
            src = os.path.join(folder, f)
            if os.path.isfile(src):
                shutil.copy(src, work)
        path = os.path.join(work, file_name)
        lines = open(path, errors="replace").read().split("\n")
        text = lines[n]
        width = end - start
        field_start = max(0, end - max(width, len(new)))
        lines[n] = (text[:field_start] + new.rjust(end - field_start) + text[end:])
        open(path, "w").write("\n".join(lines))
        r = run(crumple, work, files[0], os.path.join(work, "out"), timeout)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    where = f"{file_name}:{n + 1}:{start + 1}-{end}"
    if r["code"] == 2:
        kind = "error"
    elif r["code"] == "timeout":
        # Past the time limit: an effect if a row it printed differs from the deck as written's at the same cycle
        # (a step that collapsed, a contact that closed elsewhere), else unsettled.
        common = set(r["rows"]) & set(base.get("rows", {}))
        kind = "effect" if any(differs(r["rows"][c], base["rows"][c]) for c in common) else "timeout"
    elif "values" in r and "values" in base and differs(r["values"], base["values"]):
        kind = "effect"
    elif r["code"] != base["code"]:
        kind = "effect"
    elif (warnings_of(r["output"]) - warnings_of(base["output"]) or card_warned(base, file_name, item[4])
          or field_warned(base, folder, file_name, item)):
        kind = "warning"
    else:
        kind = "silent"
    new_warnings = sorted(warnings_of(r["output"]) - warnings_of(base["output"]))
    return {"where": where, "token": token, "new": new, "kind": kind, "said": new_warnings[:1]}


def expected_no_effect(path):
    """(deck, file:line:columns) -> reason, from the allowlist beside this script: values whose change can have no
    effect by their physics (a direction given by a vector whose length does not count), each with its reason."""
    out = {}
    if os.path.exists(path):
        for line in open(path):
            line = line.strip()
            if line and not line.startswith("#"):
                deck, where, reason = line.split(None, 2)
                out[(deck, where)] = reason
    return out


def main():
    a = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    a.add_argument("crumple")
    a.add_argument("folders", nargs="+")
    a.add_argument("--jobs", type=int, default=2)
    a.add_argument("--limit", type=int, default=0, help="at most this many values per deck (0: all)")
    a.add_argument("--timeout", type=float, default=120.0)
    a.add_argument("--markdown", action="store_true")
    a.add_argument("--show-warnings", action="store_true", help="list each value that only drew a warning")
    args = a.parse_args()
    totals = {}
    silent = []
    allowed = expected_no_effect(os.path.join(os.path.dirname(os.path.abspath(__file__)), "expected_no_effect.txt"))
    for folder in args.folders:
        found = decks_of(folder)
        if found is None:
            continue
        name, files = found
        with tempfile.TemporaryDirectory() as work:
            base = run(args.crumple, folder, files[0], os.path.join(work, "out"), args.timeout)
        if base["code"] != 0:
            print(f"{folder}: the deck as written does not run (exit {base['code']}); skipped", file=sys.stderr)
            continue
        items = [(f, c) for f in files for c in candidates(os.path.join(folder, f))]
        if args.limit:
            items = items[: args.limit]
        counts = {}
        with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
            futures = [pool.submit(probe_one, args.crumple, folder, files, f, c, base, args.timeout) for f, c in items]
            for fut in futures:
                r = fut.result()
                deck_name = os.path.basename(os.path.normpath(folder))
                if r["kind"] == "silent" and (deck_name, r["where"]) in allowed:
                    r["kind"] = "no effect by its physics"
                counts[r["kind"]] = counts.get(r["kind"], 0) + 1
                if r["kind"] in ("silent", "timeout"):
                    silent.append((os.path.basename(os.path.normpath(folder)), r))
                if r["kind"] == "warning" and args.show_warnings:
                    print(f"warning: {r['where']}: '{r['token']}' -> '{r['new']}': {r['said']}", file=sys.stderr)
        totals[os.path.basename(os.path.normpath(folder))] = counts
        print(f"{folder}: {len(items)} values: " + ", ".join(f"{k} {v}" for k, v in sorted(counts.items())),
              file=sys.stderr)
    if args.markdown:
        print("| deck | values | effect | error | warning | no effect by its physics | silent |")
        print("|---|---|---|---|---|---|---|")
        for deck, c in totals.items():
            print(f"| {deck} | {sum(c.values())} | {c.get('effect', 0)} | {c.get('error', 0)} | {c.get('warning', 0)} |"
                  f" {c.get('no effect by its physics', 0)} | {c.get('silent', 0) + c.get('timeout', 0)} |")
    for deck, r in silent:
        print(f"{r['kind']}: {deck} {r['where']}: '{r['token']}' -> '{r['new']}'")
    return 1 if silent else 0


if __name__ == "__main__":
    sys.exit(main())
