#!/usr/bin/env bash
# Quick start, command 1: install the dependencies, build Release, run the example deck.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset release
cmake --build --preset release
./build/release/src/crumple run decks/tube_impact/TUBE_0000.rad -o build/tube_impact
