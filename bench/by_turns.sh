#!/usr/bin/env bash
# Two or more builds of bench_dynamics compared by turns: each round runs every binary once, one
# after the other, on the same scenario and settings, and the CPU seconds per simulated second of
# the stepping ("stepping, CPU time" line) are collected; the least, the median and the largest per
# binary are printed, and the median of each round's ratio to the first binary. On a shared
# machine one run's figure moves by ±10 % from run to run (docs/solver.md, "Where it stands (stop
# 39)"): a change of a few per cent shows only in the ratios of many rounds, and instruction
# counts (bench/instructions.sh) are the steadier measure.
# Usage: bench/by_turns.sh ROUNDS SECONDS BIN_A BIN_B [BIN_C …] [-- bench_dynamics arguments]
#   e.g. bench/by_turns.sh 10 0.2 /tmp/old/bench_dynamics build/bin/bench_dynamics -- \
#          assets/scenarios/paper_dynamics_healthy.yaml --set solver.time_step_s=1e-5
# Without arguments after --: assets/scenarios/paper_dynamics_healthy.yaml at dt = 1e-5 s; arguments
# without a scenario first run that scenario at the dt they set (its own without one).
set -euo pipefail
cd "$(dirname "$0")/.."
if [ $# -lt 3 ]; then
  sed -n '2,13p' "$0" | sed 's/^# \{0,1\}//' >&2
  exit 2
fi
rounds=$1 seconds=$2
shift 2
bins=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do bins+=("$1"); shift; done
[ $# -gt 0 ] && shift
extra=("$@")
scenario=assets/scenarios/paper_dynamics_healthy.yaml
if [ ${#extra[@]} -eq 0 ]; then
  extra=(--set solver.time_step_s=1e-5)
elif [ "${extra[0]#-}" = "${extra[0]}" ]; then
  scenario=${extra[0]}
  extra=("${extra[@]:1}")
fi
case $rounds in '' | *[!0-9]*) echo "by_turns: ROUNDS must be a whole number, got '$rounds'" >&2; exit 2 ;; esac
for b in "${bins[@]}"; do
  [ -x "$b" ] || { echo "by_turns: not an executable: $b" >&2; exit 2; }
done

# Least, median and largest of the numbers on standard input, one a line.
spread() {
  sort -g | awk '{a[NR] = $1} END {printf "%.3f %.3f %.3f\n", a[1], (NR % 2 ? a[(NR + 1) / 2] : 0.5 * (a[NR / 2] + a[NR / 2 + 1])), a[NR]}'
}

out=$(mktemp)
trap 'rm -f "$out"' EXIT
for ((i = 1; i <= rounds; ++i)); do
  line=""
  for b in "${bins[@]}"; do
    v=$("$b" "$scenario" "$seconds" "${extra[@]}" | awk '/^stepping, CPU time/ {print $7}') ||
      { echo "by_turns: $b failed (exit code ${PIPESTATUS[0]:-?}): its run did not complete" >&2; exit 1; }
    [ -n "$v" ] || { echo "by_turns: $b printed no 'stepping, CPU time' line" >&2; exit 1; }
    line="$line $v"
  done
  echo "$line" >>"$out"
done
echo "by turns: $rounds rounds of $scenario, $seconds s simulated, ${extra[*]}; CPU s per simulated second"
for ((c = 1; c <= ${#bins[@]}; ++c)); do
  read -r least median largest < <(awk -v c="$c" '{print $c}' "$out" | spread)
  stats="least $least  median $median  largest $largest"
  ratio=""
  if [ "$c" -gt 1 ]; then
    read -r least median largest < <(awk -v c="$c" '{print $c / $1}' "$out" | spread)
    ratio="; median ratio to the first $median ($least to $largest)"
  fi
  echo "  ${bins[$((c - 1))]}: $stats$ratio"
done
