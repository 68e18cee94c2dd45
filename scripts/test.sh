#!/usr/bin/env bash
# Builds Gearsim with its tests and runs them all (ctest). Exit code 0 only if every test passes.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh -DGEARSIM_BUILD_TESTS=ON
ctest --test-dir build --output-on-failure -j"$(nproc)" --timeout 600
