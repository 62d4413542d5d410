#!/usr/bin/env bash
# Quick start, command 2: build and run the whole test suite through ctest.
#  1. Release build: every test.
#  2. Debug build with AddressSanitizer and UndefinedBehaviorSanitizer: unit, bad-input and fuzz tests.
#  3. The mixed-precision build (docs/theory/precision.md): the verification and stability tests, three MPI tests.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
jobs=$(nproc 2>/dev/null || echo 2)

cmake --preset release
cmake --build --preset release -j "$jobs"
ctest --preset release

if [ "${CRUMPLE_SKIP_SANITIZERS:-0}" != "1" ]; then
  cmake --preset debug
  cmake --build --preset debug -j "$jobs"
  # the longest command-line runs (the example tube and what reads its results: plots, units, its ParaView check;
  # four watch signals, the shared QA decks: 500 of the label's 1030 s of test time under the sanitizers,
  # 2026-12-05), the other ParaView check (12 s, most of it in ParaView, which has no sanitizers) and the two
  # longest brick runs (55 s of the 257 left; the brick kernels run in the other brick tests) are the release build's
  ctest --preset debug -L "unit|badinput|fuzz|cli" -E \
    "^(cli\.(run_example_tube(_files)?|plot_example_tube(_png)?|th_csv_example_tube_units|listing_example_tube_units|paraview_(tube|every_kind)|regress_shared_qa(_junit)?|watch_(sigterm|quiet|sigint|sigkill))|unit\.Brick8\.(NegativeVolumeStopsTheRun|WaveCrossesABarAtTheDilatationalSpeed))$"
fi

if [ "${CRUMPLE_SKIP_MIXED:-0}" != "1" ]; then
  cmake --preset mixed
  cmake --build --preset mixed -j "$jobs"
  # the two Hertz balls (80 and 35 s on CI's two cores) are left to the release build: the float state of bricks in
  # contact runs in the brick tests of both labels and in mpi.ranks_contact_idel below
  ctest --preset mixed -L "verification|stability" -E "^verification\.ContactHertz\."
  # the float state across ranks: shells with sections, contact with bricks and shells (the whole mpi label takes
  # 5 minutes on CI's two cores; these three take 20 s)
  ctest --preset mixed -R "^mpi\.ranks_(box_crush|contact_idel|section_strip)$"
fi
