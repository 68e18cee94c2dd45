#!/usr/bin/env bash
# Instructions per simulation step of a bench_dynamics build, counted by callgrind inside
# World::step() only (scenario load and world build left out): the steady measure of a step's
# cost, which unlike its time does not move with the machine's load (docs/solver.md, "Cost per
# step and the floor"). Needs valgrind (Debian package `valgrind`). Slow: ≈ 3 s per 1 000 steps.
# Usage: bench/instructions.sh [BIN=build/bin/bench_dynamics] [SECONDS=0.05] [bench_dynamics arguments…]
#   e.g. bench/instructions.sh build/bin/bench_dynamics 0.05 assets/scenarios/paper_dynamics_healthy.yaml \
#          --set solver.time_step_s=1e-5
# Without arguments: assets/scenarios/paper_dynamics_healthy.yaml at dt = 1e-5 s; arguments without
# a scenario first run that scenario at the dt they set (its own without one). With
# GEARSIM_CALLGRIND_OUT=FILE the callgrind profile is kept there (callgrind_annotate reads it).
set -euo pipefail
cd "$(dirname "$0")/.."
command -v valgrind >/dev/null || { echo "instructions: needs valgrind (apt-get install valgrind)" >&2; exit 2; }
bin=${1:-build/bin/bench_dynamics}
seconds=${2:-0.05}
[ $# -gt 0 ] && shift
[ $# -gt 0 ] && shift
[ -x "$bin" ] || { echo "instructions: not an executable: $bin" >&2; exit 2; }
args=("$@")
if [ ${#args[@]} -eq 0 ]; then
  args=(assets/scenarios/paper_dynamics_healthy.yaml --set solver.time_step_s=1e-5)
elif [ "${args[0]#-}" != "${args[0]}" ]; then
  args=(assets/scenarios/paper_dynamics_healthy.yaml "${args[@]}")
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
profile=${GEARSIM_CALLGRIND_OUT:-$work/callgrind.out}
if ! valgrind --tool=callgrind --callgrind-out-file="$profile" --toggle-collect='gearsim::physics::World::step*' \
  "$bin" "${args[0]}" "$seconds" "${args[@]:1}" >"$work/bench.txt" 2>"$work/valgrind.txt"; then
  echo "instructions: the run under callgrind failed:" >&2
  grep -v '^==' "$work/valgrind.txt" >&2 || true
  exit 1
fi
steps=$(awk '/^scenario / {for (i = 1; i <= NF; ++i) if ($i == "steps") print $(i - 1)}' "$work/bench.txt")
collected=$(awk '/Collected :/ {print $NF}' "$work/valgrind.txt")
[ -n "$steps" ] && [ -n "$collected" ] || { echo "instructions: no step count or no collected total" >&2; cat "$work/valgrind.txt" >&2; exit 1; }
head -1 "$work/bench.txt"
awk -v c="$collected" -v n="$steps" 'BEGIN {printf "World::step(): %d instructions in %d steps = %.1f k per step\n", c, n, c / n / 1000}'
