#!/usr/bin/python3
"""A `crumple run` watched while it goes, then stopped by a signal (README, "Watching and stopping a run").

    watch_run.py CRUMPLE DECK OUT_DIR NAME CASE

CASE is one of
  sigterm   stdout to a file; once the listing has 3 rows (it grows while the run goes: its first row is read
            before the later ones are written), SIGTERM
  sigint    the same with SIGINT, sent once the plain progress line (every 5 s, stdout not a terminal) is out
  terminal  stdout a pseudo-terminal 60 columns wide: the progress line is rewritten in place and cut to 59
            columns; SIGTERM once it is shown
  quiet     the same terminal with --quiet: after 3 listing rows and more than two progress intervals, nothing
            but the final message is on it
  restart   SIGTERM once the listing passes 40 % of the end time; the stopped run leaves NAME.rst; `crumple run
            --restart` from it into OUT_DIR/resumed ends with the uninterrupted run's (OUT_DIR/whole) energies,
            time and cycle count, digit for digit (the summary prints 17 significant digits)
  sigkill   SIGKILL once the listing passes 1.2 (frames at 0, 0.5 and 1.0 are out): NAME.h5 still opens and holds
            those frames and the histories up to its last flush

Each stopped run must exit with code 4, its summary say "stopped" and name the signal, its listing end with the
stop message after the stopped cycle's row (printed once), and NAME.h5 open with h5py and hold a last frame at
the stop's cycle and time. The run's speed does not matter (the Debug build with sanitizers is 15 times
slower): every wait is on what the files show, with a generous limit.
"""
import fcntl
import json
import os
import pty
import re
import signal
import struct
import subprocess
import sys
import termios
import time

import h5py

ROW = re.compile(r"^\s*(\d+)\s+([-+0-9.eE]+)\s+[-+0-9.eE]+\s", re.M)
LIMIT = 600.0  # seconds any one wait may take


def fail(message):
    print("FAIL:", message)
    sys.exit(1)


def read(path):
    try:
        with open(path, errors="replace") as f:
            return f.read()
    except FileNotFoundError:
        return ""


def wait_for(what, condition, process):
    start = time.monotonic()
    while not condition():
        if process.poll() is not None:
            fail(f"the run ended (code {process.returncode}) before {what}")
        if time.monotonic() - start > LIMIT:
            process.kill()
            fail(f"no {what} after {LIMIT:.0f} s")
        time.sleep(0.05)


class Console:
    """The run's stdout: a file, or a pseudo-terminal read as it goes."""

    def __init__(self, out_dir, terminal):
        self.terminal = terminal
        self.text = b""
        if terminal:
            self.master, self.slave = pty.openpty()
            fcntl.ioctl(self.slave, termios.TIOCSWINSZ, struct.pack("HHHH", 24, 60, 0, 0))
            os.set_blocking(self.master, False)
        else:
            self.path = os.path.join(out_dir, "stdout.txt")
            self.slave = open(self.path, "wb")

    def read(self):
        if not self.terminal:
            return read(self.path)
        try:
            while chunk := os.read(self.master, 65536):
                self.text += chunk
        except (BlockingIOError, OSError):
            pass
        return self.text.decode(errors="replace")


def start(crumple, deck, out_dir, console, quiet):
    command = [crumple, "run", deck, "-o", out_dir] + (["--quiet"] if quiet else [])
    stderr = open(os.path.join(out_dir, "stderr.txt"), "wb")
    # SIGINT as an interactive shell leaves it: a run started with it ignored keeps ignoring it.
    return subprocess.Popen(command, stdout=console.slave, stderr=stderr,
                            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))


def rows(listing):
    return [(int(c), float(t)) for c, t in ROW.findall(listing)]


def check_stopped(process, out_dir, name, signal_name):
    try:
        process.wait(timeout=LIMIT)
    except subprocess.TimeoutExpired:
        process.kill()
        fail(f"the run did not stop within {LIMIT:.0f} s of {signal_name}")
    stderr = read(os.path.join(out_dir, "stderr.txt"))
    if process.returncode != 4:
        fail(f"exit code {process.returncode}, expected 4 (stopped)\n{stderr}")
    if f"stopped by {signal_name}" not in stderr:
        fail(f"stderr does not name {signal_name}:\n{stderr}")
    summary = json.loads(read(os.path.join(out_dir, name + ".summary.json")))
    if summary["status"] != "stopped":
        fail(f"summary status {summary['status']!r}, expected 'stopped'")
    if f"stopped by {signal_name} at the end of cycle {summary['cycles']}" not in summary["message"]:
        fail(f"summary message {summary['message']!r}")
    listing = read(os.path.join(out_dir, name + ".out"))
    table = rows(listing)
    cycles = [c for c, _ in table]
    if len(cycles) != len(set(cycles)):
        fail(f"a row is printed twice: {cycles}")
    if cycles[0] != 0 or cycles[-1] != summary["cycles"]:
        fail(f"the rows run from cycle {cycles[0]} to {cycles[-1]}, expected 0 to {summary['cycles']}")
    stop_line = f"RUN STOPPED ON REQUEST: stopped by {signal_name} at the end of cycle {summary['cycles']}"
    after = listing[listing.rfind("\n" + str(summary["cycles"]).rjust(9)):]
    if stop_line not in after:
        fail(f"no '{stop_line}' after the last row:\n{listing[-2000:]}")
    with h5py.File(os.path.join(out_dir, name + ".h5"), "r") as f:
        frames = sorted(f["frames"], key=int)
        last = f["frames"][frames[-1]]
        if last.attrs["cycle"] != summary["cycles"] or last.attrs["time"] != summary["time"]:
            fail(f"last frame at cycle {last.attrs['cycle']} time {last.attrs['time']!r}, the run stopped at "
                 f"cycle {summary['cycles']} time {summary['time']!r}")
        if len(frames) > 1 and f["frames"][frames[-2]].attrs["cycle"] == last.attrs["cycle"]:
            fail("the stop's frame is written twice")
        if f["history/time"].shape[0] == 0:
            fail("no history rows")
    print(f"stopped by {signal_name} at cycle {summary['cycles']}, time {summary['time']:.6g}: exit code 4, "
          f"{len(cycles)} listing rows, {len(frames)} frames")
    return summary


def listing_time(path):
    table = rows(read(path))
    return table[-1][1] if table else 0.0


def restart_case(crumple, deck, out_dir, name, console):
    """Stopped at 40 %, resumed from its snapshot: the end is the uninterrupted run's, bit for bit."""
    listing = os.path.join(out_dir, name + ".out")
    process = start(crumple, deck, out_dir, console, quiet=True)
    wait_for("40 % of the run", lambda: listing_time(listing) > 1.2, process)
    process.send_signal(signal.SIGTERM)
    stopped = check_stopped(process, out_dir, name, "SIGTERM")
    snapshot = os.path.join(out_dir, name + ".rst")
    if not os.path.isfile(snapshot):
        fail("the stopped run left no restart file " + snapshot)
    ends = {}
    for case, extra in (("resumed", ["--restart", snapshot]), ("whole", [])):
        folder = os.path.join(out_dir, case)
        os.makedirs(folder, exist_ok=True)
        done = subprocess.run([crumple, "run", deck, "-o", folder, "--quiet"] + extra, capture_output=True,
                              text=True, timeout=LIMIT)
        if done.returncode != 0:
            fail(f"{case} run: exit code {done.returncode}\n{done.stderr}")
        ends[case] = json.loads(read(os.path.join(folder, name + ".summary.json")))
    a, b = ends["whole"], ends["resumed"]
    for key in ("time", "cycles_total"):
        if a[key] != b[key]:
            fail(f"{key}: resumed {b[key]!r}, uninterrupted {a[key]!r}")
    for key, value in a["energy"].items():
        if b["energy"][key] != value:
            fail(f"energy {key}: resumed {b['energy'][key]!r}, uninterrupted {value!r}")
    print(f"stopped at cycle {stopped['cycles']}, resumed to cycle {b['cycles_total']}: time, cycles and every "
          "energy equal to the uninterrupted run's")
    print("PASS")


def sigkill_case(crumple, deck, out_dir, name, console):
    """Killed without warning: the results file is readable up to its last flushed frame."""
    listing = os.path.join(out_dir, name + ".out")
    process = start(crumple, deck, out_dir, console, quiet=True)
    wait_for("t = 1.2", lambda: listing_time(listing) > 1.2, process)
    killed_at = listing_time(listing)
    process.send_signal(signal.SIGKILL)
    process.wait(timeout=LIMIT)
    if process.returncode != -signal.SIGKILL:
        fail(f"exit {process.returncode}, expected death by SIGKILL")
    with h5py.File(os.path.join(out_dir, name + ".h5"), "r") as f:
        times = sorted(float(f["frames"][k].attrs["time"]) for k in f["frames"])
        # each frame goes out at the first cycle at or past its time on the /ANIM/DT grid
        if len(times) < 3 or any(abs(t - g) > 0.01 for t, g in zip(times, (0.0, 0.5, 1.0))):
            fail(f"frames at {times}, expected at least the ones near 0, 0.5 and 1.0")
        history = f["history/time"][:]
        # the rows are flushed with each frame (the frame goes out before its cycle's history row)
        if history.shape[0] == 0 or history[-1] < times[-1] - 0.02 or history[-1] > killed_at + 0.5:
            fail(f"histories end at {history[-1] if history.shape[0] else None}, killed near {killed_at}")
    print(f"killed near t = {killed_at:.3g}: {len(times)} frames readable, histories to t = {history[-1]:.4g}")
    print("PASS")


def main():
    crumple, deck, out_dir, name, case = sys.argv[1:6]
    os.makedirs(out_dir, exist_ok=True)
    for old in os.listdir(out_dir):
        path = os.path.join(out_dir, old)
        if os.path.isdir(path):
            for inner in os.listdir(path):
                os.remove(os.path.join(path, inner))
        else:
            os.remove(path)
    listing_path = os.path.join(out_dir, name + ".out")
    console = Console(out_dir, terminal=case in ("terminal", "quiet"))
    if case == "restart":
        return restart_case(crumple, deck, out_dir, name, console)
    if case == "sigkill":
        return sigkill_case(crumple, deck, out_dir, name, console)
    process = start(crumple, deck, out_dir, console, quiet=case == "quiet")
    started = time.monotonic()
    if case in ("sigterm", "sigint"):
        wait_for("listing row", lambda: len(rows(read(listing_path))) >= 1, process)
        first = rows(read(listing_path))
        if process.poll() is not None:
            fail("the run ended before its first row could be read")
        wait_for("3 listing rows", lambda: len(rows(read(listing_path))) >= 3, process)
        later = rows(read(listing_path))
        if later[: len(first)] != first or len(later) <= len(first):
            fail(f"the listing did not grow while the run went: {first} then {later}")
        print(f"the listing grew while the run went: {len(first)} rows, then {len(later)}")
    if case == "sigint":
        wait_for("plain progress line", lambda: re.search(r"^cycle \d+  t .* left .*\n", console.read(), re.M),
                 process)
        line = re.search(r"^cycle \d+  t .*$", console.read(), re.M).group(0)
        if "\r" in console.read():
            fail("a carriage return on a console that is no terminal")
        print(f"progress line: {line!r}")
    if case == "terminal":
        wait_for("progress line", lambda: "\x1b[K" in console.read(), process)
        shown = re.search(r"\r([^\r\x1b]*)\x1b\[K", console.read()).group(1)
        if not shown.startswith("cycle ") or len(shown) != 59:
            fail(f"progress line {shown!r}: expected 'cycle ...' cut to 59 columns")
        print(f"progress line on the terminal: {shown!r}")
    if case == "quiet":
        wait_for("3 listing rows", lambda: len(rows(read(listing_path))) >= 3, process)
        wait_for("2.5 s of running", lambda: time.monotonic() - started > 2.5, process)
    process.send_signal(signal.SIGINT if case == "sigint" else signal.SIGTERM)
    check_stopped(process, out_dir, name, "SIGINT" if case == "sigint" else "SIGTERM")
    text = console.read()
    if case == "quiet":
        if re.search(r"cycle \d+  t ", text) or "\x1b" in text or "\r" in text.replace("\r\n", "\n"):
            fail(f"--quiet printed progress: {text!r}")
        print("--quiet: no progress on the terminal")
    if case == "terminal" and f"\r\x1b[Kcrumple run {name}: stopped after" not in text:
        fail(f"the progress line is not cleared before the final message: {text[-300:]!r}")
    if f"crumple run {name}: stopped after" not in text:
        fail(f"no final message on stdout: {text[-500:]!r}")
    print("PASS")


if __name__ == "__main__":
    main()
