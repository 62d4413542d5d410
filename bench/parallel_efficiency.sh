#!/usr/bin/env bash
# Parallel efficiency on one machine (docs/performance.md, "Parallel runs"): the benchmark tube with self contact
# (decks/generate_bench.py, at least 200 000 shells) run as one process and under mpirun with 2 ranks, alternately,
# `rounds` times each; prints each run's loop wall time (the summary's wall_seconds), its phase profile, the best
# of each rank count and the efficiency T1 / (2 T2) of the best runs. Also checks that the two runs end with the
# same energies and cycles (the answer does not depend on the rank count).
#   bench/parallel_efficiency.sh [CRUMPLE] [ELEMENTS] [END_TIME_MS] [ROUNDS]
#   defaults: build/release/src/crumple 200000 0.02 3
set -euo pipefail
cd "$(dirname "$0")/.."
crumple=$(realpath "${1:-build/release/src/crumple}")
elements=${2:-200000}
end_time=${3:-0.02}
rounds=${4:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 decks/generate_bench.py tube --elements "$elements" --end-time "$end_time" --out "$work/deck" > /dev/null
for round in $(seq "$rounds"); do
  for ranks in 1 2; do
    mpirun --allow-run-as-root --oversubscribe -np "$ranks" "$crumple" run "$work/deck/TUBE_0000.rad" \
      -o "$work/out$ranks.$round" --quiet > /dev/null 2>&1
  done
done
/usr/bin/python3 - "$work" "$rounds" <<'PY'
import json, sys
work, rounds = sys.argv[1], int(sys.argv[2])
best = {}
for ranks in (1, 2):
    for r in range(1, rounds + 1):
        s = json.load(open(f"{work}/out{ranks}.{r}/TUBE.summary.json"))
        p = s["profile"]
        print(f"{ranks} rank(s), round {r}: wall {s['wall_seconds']:.2f} s  elements {p['elements']:.2f}  "
              f"contact {p['contact']:.2f}  loads {p['loads']:.2f}  update {p['update']:.2f}  output {p['output']:.2f}  "
              f"cycles {s['cycles']}")
        best[ranks] = min(best.get(ranks, 1e300), s["wall_seconds"])
one = json.load(open(f"{work}/out1.1/TUBE.summary.json"))
two = json.load(open(f"{work}/out2.1/TUBE.summary.json"))
same = one["energy"] == two["energy"] and one["cycles"] == two["cycles"]
print(f"best: 1 rank {best[1]:.2f} s, 2 ranks {best[2]:.2f} s, efficiency {best[1] / (2 * best[2]) * 100:.1f} %")
print("energies and cycles of 1 and 2 ranks:", "identical" if same else "DIFFERENT")
PY
