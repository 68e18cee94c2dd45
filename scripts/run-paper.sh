#!/usr/bin/env bash
# The main job: build, generate the paper's gear set (gear table, checks, tolerances, meshes)
# into out/paper/, print the planet's tolerance table, then run and analyse the paper's dynamics:
# the healthy set and the set with the 43 µm flank error on planet 0 (1 s each, sun at
# 104.7 rad/s) into out/paper_dynamics_healthy/ and out/paper_dynamics/ (each with
# analysis.json: mesh harmonics, sidebands, the 8.89 Hz fault family, TE, per-tooth loads).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
build/bin/gearsim gears assets/specs/paper_gearset.yaml --out out/paper
echo
build/bin/gearsim tolerance --module 1 --teeth 36 --diameter 36 --quality 8
echo
# --force: out/paper_dynamics*/ are this script's own folders, also when an earlier gearsim (before
# folder manifests, docs/output-folders.md) wrote them; their outputs are replaced.
build/bin/gearsim run assets/scenarios/paper_dynamics_healthy.yaml --out out/paper_dynamics_healthy --force
echo
build/bin/gearsim run assets/scenarios/paper_dynamics.yaml --out out/paper_dynamics --force
echo
build/bin/gearsim report out/paper_dynamics --compare out/paper_dynamics_healthy
