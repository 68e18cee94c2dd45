#!/usr/bin/env bash
# Sweep throughput: cases per hour of one sweep of the spur pair run locally with --jobs 1 and
# --jobs 2, and under MPI with -np 3 (rank 0 hands out the cases, 2 workers run them), and the
# parallel efficiency of each against --jobs 1: (cases/h) / (cases/h at --jobs 1 × workers).
# A measurement, not a timed test. Usage:
#   bench/sweep_throughput.sh [BUILD_DIR (default build)] [CASES (default 16)] [DURATION_S (default 0.3)]
# Writes into a temporary folder; prints one line per mode and a table for docs/sweep.md.
set -euo pipefail

here="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$here/build}"
cases="${2:-16}"
duration="${3:-0.3}"
gearsim="$build/bin/gearsim"
[ -x "$gearsim" ] || { echo "no $gearsim: build the gearsim target first" >&2; exit 2; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# The cases: the pinion's speed over an even grid (every case the same work: same duration).
cat > "$work/sweep.yaml" <<YAML
name: throughput bench
scenario: $here/assets/scenarios/spur_pair.yaml
set: ["duration_s=$duration"]
grid:
  motors[0].target_speed_rad_s: {from: 20, to: 80, steps: $cases}
collect:
  metrics: [dynamic_factor_band_limited, mesh_frequency_hz, rms_dynamic_te_rad]
YAML

calc() { awk "BEGIN { print $1 }"; }

# Wall seconds of one sweep (fresh each time).
timed() {
  local start end
  start=$(date +%s.%N)
  "$@" > "$work/last.log" 2>&1 || { cat "$work/last.log" >&2; exit 1; }
  end=$(date +%s.%N)
  calc "$end - $start"
}

t1=$(timed "$gearsim" sweep "$work/sweep.yaml" --out "$work/j1" --jobs 1 --fresh)
t2=$(timed "$gearsim" sweep "$work/sweep.yaml" --out "$work/j2" --jobs 2 --fresh)
tm="skipped"
if command -v mpirun > /dev/null; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
  tm=$(timed mpirun --oversubscribe -np 3 "$gearsim" sweep "$work/sweep.yaml" --out "$work/mpi" --fresh)
  cmp -s "$work/j1/sweep.csv" "$work/mpi/sweep.csv" && same="identical" || same="DIFFERENT"
fi
cmp -s "$work/j1/sweep.csv" "$work/j2/sweep.csv" && same2="identical" || same2="DIFFERENT"

rate() { calc "3600 * $cases / $1"; }
r1=$(rate "$t1")
r2=$(rate "$t2")
printf "cases: %d of spur_pair.yaml, %s s simulated each, on %d cores\n" "$cases" "$duration" "$(nproc)"
printf "| mode | wall, s | cases/h | parallel efficiency |\n|---|---|---|---|\n"
printf "| local --jobs 1 | %.1f | %.0f | 1 |\n" "$t1" "$r1"
printf "| local --jobs 2 | %.1f | %.0f | %.2f |\n" "$t2" "$r2" "$(calc "$r2 / (2 * $r1)")"
if [ "$tm" != "skipped" ]; then
  rm_=$(rate "$tm")
  printf "| mpirun -np 3 (1 master + 2 workers) | %.1f | %.0f | %.2f |\n" "$tm" "$rm_" "$(calc "$rm_ / (2 * $r1)")"
  echo "sweep.csv --jobs 2 vs --jobs 1: $same2; MPI vs --jobs 1: $same"
else
  echo "mpirun not installed: MPI skipped; sweep.csv --jobs 2 vs --jobs 1: $same2"
fi
