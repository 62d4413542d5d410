"""ctest driver of the ParaView check (tests/regression/CMakeLists.txt, cli.paraview_*):

    python3 run_paraview_check.py CRUMPLE DECK_0000.rad OUT_DIR RUN_NAME [check_paraview.py options]

Runs `crumple run DECK -o OUT_DIR`, then tests/support/check_paraview.py on OUT_DIR/RUN_NAME.xdmf under
`xvfb-run -a pvpython` (Debian's ParaView aborts without a display), saving OUT_DIR/RUN_NAME_paraview.png.
Exit code 77 (ctest: skipped) when pvpython is not installed, otherwise the first failing step's code.
"""
import os
import shutil
import subprocess
import sys
from pathlib import Path

SKIPPED = 77


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
    display = []
    if shutil.which("xvfb-run"):
        display = ["xvfb-run", "-a", "-s", "-screen 0 1280x1024x24"]
    elif not os.environ.get("DISPLAY"):
        print("pvpython needs a display: install xvfb (xvfb-run) or set DISPLAY")
        return 1
    shutil.rmtree(out, ignore_errors=True)
    run = subprocess.run([crumple, "run", deck, "-o", out])
    if run.returncode != 0:
        print(f"crumple run {deck}: exit code {run.returncode}")
        return run.returncode
    check = Path(__file__).with_name("check_paraview.py")
    xdmf = str(Path(out) / f"{name}.xdmf")
    picture = str(Path(out) / f"{name}_paraview.png")
    result = subprocess.run(display + [pvpython, str(check), xdmf, picture] + options)
    return result.returncode


if __name__ == "__main__":
    sys.exit(main())
