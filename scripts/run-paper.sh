#!/usr/bin/env bash
# The main job: build, generate the paper's gear set (gear table, checks, tolerances, meshes)
# into out/paper/, print the planet's tolerance table, and run the paper's dynamics scenario
# (1 s, sun at 104.7 rad/s, 43 µm flank error on planet 0) into out/paper_dynamics/.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
build/bin/gearsim gears assets/specs/paper_gearset.yaml --out out/paper
echo
build/bin/gearsim tolerance --module 1 --teeth 36 --diameter 36 --quality 8
echo
build/bin/gearsim run assets/scenarios/paper_dynamics.yaml --out out/paper_dynamics
