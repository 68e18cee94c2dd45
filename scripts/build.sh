#!/usr/bin/env bash
# Installs the dependencies (Debian packages) and builds Gearsim into build/ (Release).
# Usage: scripts/build.sh [--pgo] [extra cmake -D options]
#   --pgo: profile-guided optimisation, two stages in build/: the libraries and the CLI built
#          instrumented, a few short runs of scenarios other than the paper's healthy and faulty
#          sets (the benchmarks' cases) write the profile into build/pgo-profile/, then everything
#          is built again with it. About twice the build time; the same results bit for bit, the
#          paper step ≈ 9.7 % fewer instructions, 3–10 % less CPU by turns (docs/solver.md, "Where
#          it stands (stop 39)"). Without --pgo the build is the plain one (a build folder left
#          in PGO mode is switched back).
set -euo pipefail
cd "$(dirname "$0")/.."
pgo=0
if [ "${1:-}" = "--pgo" ]; then
  pgo=1
  shift
fi
scripts/install-deps.sh
if [ "$pgo" = 1 ]; then
  profile="$PWD/build/pgo-profile"
  rm -rf "$profile"
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DGEARSIM_PGO=generate -DGEARSIM_PGO_DIR="$profile" "$@"
  cmake --build build -j"$(nproc)" --target gearsim
  # The training runs: other scenarios than the benchmarks' (paper_dynamics_healthy.yaml,
  # paper_dynamics.yaml) — the paper's gears on bearings, a sequential planetary, a spur pair from
  # STL files, Lin and Parker's set —, each with its logs and analysis, as a user's run.
  runs=$(mktemp -d)
  trap 'rm -rf "$runs"' EXIT
  for s in paper_dynamics_bearings:0.05 sequential_planetary:0.05 spur_pair:0.05 lin_parker_1999:0.02; do
    name=${s%%:*}
    build/bin/gearsim run "assets/scenarios/$name.yaml" --duration "${s##*:}" --set solver.time_step_s=1e-5 \
      --out "$runs/$name" >/dev/null
  done
  echo "build: PGO profile from $(find "$profile" -name '*.gcda' | wc -l) files of counters; building with it"
  cmake -S . -B build -DGEARSIM_PGO=use "$@"
else
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DGEARSIM_PGO= "$@"
fi
cmake --build build -j"$(nproc)"
