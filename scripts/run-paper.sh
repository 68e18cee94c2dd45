#!/usr/bin/env bash
# The main job: build, then generate the paper's gear set (gear table, checks, tolerances,
# meshes) into out/paper/ and print the tolerance table of the planet.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
build/bin/gearsim gears assets/specs/paper_gearset.yaml --out out/paper
echo
build/bin/gearsim tolerance --module 1 --teeth 36 --diameter 36 --quality 8
