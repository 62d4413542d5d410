"""ctest driver of the ParaView check (tests/regression/CMakeLists.txt, cli.paraview_*):

    python3 run_paraview_check.py CRUMPLE DECK_0000.rad OUT_DIR RUN_NAME [check_paraview.py options]

Runs `crumple run DECK -o OUT_DIR`, then tests/support/check_paraview.py on OUT_DIR/RUN_NAME.xdmf under
`xvfb-run -a pvpython` (Debian's ParaView aborts without a display), saving OUT_DIR/RUN_NAME_paraview.png.
Exit code 77 (ctest: skipped) when pvpython is not installed, otherwise the first failing step's code.

Every step's command, exit code (or the signal that ended it), time and whole output (stdout and stderr, the X
server's too) are printed (ctest shows them when the test fails) and kept in OUT_DIR/steps.log.
"""
import os
import shutil
import signal
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
    display = []
    if shutil.which("xvfb-run"):
        # -e: the X server's and xauth's messages into the log instead of /dev/null.
        display = ["xvfb-run", "-a", "-e", str(Path(out) / "xvfb.log"), "-s", "-screen 0 1280x1024x24"]
    elif not os.environ.get("DISPLAY"):
        log.write("pvpython needs a display: install xvfb (xvfb-run) or set DISPLAY\n")
        return 1
    code = log.step("crumple run", [crumple, "run", deck, "-o", out])
    if code != 0:
        return code if code > 0 else 1
    check = Path(__file__).with_name("check_paraview.py")
    xdmf = str(Path(out) / f"{name}.xdmf")
    picture = str(Path(out) / f"{name}_paraview.png")
    # The display the check got, then pvpython in its place.
    shown = ["sh", "-c", 'echo "DISPLAY=$DISPLAY XAUTHORITY=$XAUTHORITY"; exec "$@"', "sh"]
    code = log.step("ParaView check", display + shown + [pvpython, str(check), xdmf, picture] + options)
    xvfb_log = Path(out) / "xvfb.log"
    if code != 0 and xvfb_log.is_file():
        log.write(f"--- {xvfb_log}:\n{xvfb_log.read_text(errors='replace')}\n")
    return code if code >= 0 else 1


if __name__ == "__main__":
    sys.exit(main())
