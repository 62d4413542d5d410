"""ctest driver of the ParaView check (tests/regression/CMakeLists.txt, cli.paraview_*):

    python3 run_paraview_check.py CRUMPLE DECK_0000.rad OUT_DIR RUN_NAME [check_paraview.py options]

Runs `crumple run DECK -o OUT_DIR`, then tests/support/check_paraview.py on OUT_DIR/RUN_NAME.xdmf with pvpython,
saving OUT_DIR/RUN_NAME_paraview.png. Debian's ParaView aborts without a display: pvpython gets an Xvfb server of
its own (see start_xvfb), or the DISPLAY it was given when Xvfb is not installed.
Exit code 77 (ctest: skipped) when pvpython is not installed, otherwise the first failing step's code.

Every step's command, exit code (or the signal that ended it), time and whole output (stdout and stderr) are
printed (ctest shows them when the test fails) and kept in OUT_DIR/steps.log; the X server's messages are in
OUT_DIR/xvfb.log, printed too when the check fails.
"""
import os
import secrets
import shutil
import signal
import struct
import subprocess
import sys
import time
from pathlib import Path

SKIPPED = 77


def describe(code):
    if code < 0:
        try:
            return f"killed by signal {-code} ({signal.Signals(-code).name})"
        except ValueError:
            return f"killed by signal {-code}"
    return f"exit code {code}"


class Log:
    """What each step did, printed and written to OUT_DIR/steps.log as it goes."""

    def __init__(self, path):
        self.path = path
        self.file = open(path, "w")

    def write(self, text):
        sys.stdout.write(text)
        sys.stdout.flush()
        self.file.write(text)
        self.file.flush()

    def step(self, title, command, **kwargs):
        """Runs `command` with stdout and stderr captured together; returns its exit code."""
        self.write(f"--- {title}: {' '.join(command)}\n")
        start = time.monotonic()
        done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL,
                              **kwargs)
        output = done.stdout.decode(errors="replace")
        self.write(output if not output or output.endswith("\n") else output + "\n")
        self.write(f"--- {title}: {describe(done.returncode)} after {time.monotonic() - start:.1f} s\n")
        return done.returncode


def write_wild_cookie(path, cookie):
    """An X authority file of one MIT-MAGIC-COOKIE-1 entry that matches any display (FamilyWild, no display
    number): the server reads it at its start, before it has chosen its display number, and so does Xlib."""
    def counted(data):
        return struct.pack(">H", len(data)) + data

    entry = struct.pack(">H", 0xFFFF) + counted(b"") + counted(b"") + counted(b"MIT-MAGIC-COOKIE-1") + counted(cookie)
    fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o600)
    with os.fdopen(fd, "wb") as f:
        f.write(entry)


def start_xvfb(out, log):
    """Starts an X server of this test's own; returns (process, environment for its clients), or None.

    -noreset: by default Xvfb resets itself each time its last client disconnects, and drops a client that
    connects while it resets. pvpython opens and closes the display several times while it starts (its
    rendering-capability probes) before it opens the render window, so under CPU load the window's connection
    fell into a reset and ParaView aborted ("bad X server connection"). -displayfd: the server takes the first
    display number whose lock file it gets (no race with another X server starting at the same time, as
    `xvfb-run -a` has) and writes it to the pipe once it accepts connections. The cookie and the server's
    messages stay in OUT_DIR."""
    auth = Path(out) / "Xauthority"
    write_wild_cookie(auth, secrets.token_bytes(16))
    ready, ready_w = os.pipe()
    server_log = open(Path(out) / "xvfb.log", "wb")
    command = ["Xvfb", "-displayfd", str(ready_w), "-screen", "0", "1280x1024x24", "-nolisten", "tcp", "-noreset",
               "-auth", str(auth)]
    log.write(f"--- X server: {' '.join(command)}\n")
    server = subprocess.Popen(command, stdin=subprocess.DEVNULL, stdout=server_log, stderr=subprocess.STDOUT,
                              pass_fds=(ready_w,))
    os.close(ready_w)
    server_log.close()
    with os.fdopen(ready) as f:
        number = f.readline().strip()  # the display number once it is ready; nothing when it ended first
    if not number.isdigit():
        code = server.wait()
        log.write(f"--- X server: {describe(code)} before it was ready\n")
        return None
    log.write(f"--- X server: display :{number}, pid {server.pid}\n")
    return server, {"DISPLAY": f":{number}", "XAUTHORITY": str(auth)}


def stop_xvfb(server):
    server.terminate()
    try:
        server.wait(timeout=30)
    except subprocess.TimeoutExpired:
        server.kill()
        server.wait()


def main():
    if len(sys.argv) < 5:
        print(__doc__)
        return 2
    crumple, deck, out, name = sys.argv[1:5]
    options = sys.argv[5:]
    pvpython = shutil.which("pvpython")
    if pvpython is None:
        print("skipped: pvpython not found (Debian: apt-get install paraview python3-paraview xvfb)")
        return SKIPPED
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    log = Log(Path(out) / "steps.log")
    has_xvfb = shutil.which("Xvfb") is not None
    if not has_xvfb and not os.environ.get("DISPLAY"):
        log.write("pvpython needs a display: install xvfb (Xvfb) or set DISPLAY\n")
        return 1
    code = log.step("crumple run", [crumple, "run", deck, "-o", out])
    if code != 0:
        return code if code > 0 else 1
    check = Path(__file__).with_name("check_paraview.py")
    xdmf = str(Path(out) / f"{name}.xdmf")
    picture = str(Path(out) / f"{name}_paraview.png")
    env = dict(os.environ)
    server = None
    code = 0
    if has_xvfb:
        started = start_xvfb(out, log)
        if started is None:
            code = 1
        else:
            server, display = started
            env.update(display)
    if code == 0:
        try:
            code = log.step("ParaView check", [pvpython, str(check), xdmf, picture] + options, env=env)
        finally:
            if server is not None:
                stop_xvfb(server)
    xvfb_log = Path(out) / "xvfb.log"
    if code != 0 and xvfb_log.is_file():
        log.write(f"--- {xvfb_log}:\n{xvfb_log.read_text(errors='replace')}\n")
    return code if code >= 0 else 1


if __name__ == "__main__":
    sys.exit(main())
