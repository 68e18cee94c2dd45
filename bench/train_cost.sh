#!/usr/bin/env bash
# Cost per step of a gear train against its stages run alone: instructions per World::step()
# (bench/instructions.sh, callgrind) of assets/scenarios/wind_turbine_3stage.yaml and of each of
# its three stages as a scenario of its own (the same gears, contact, solver and step; a motor on
# the stage's input member at its speed in the train, on its output the torque it carries there,
# both with the train's ramps). A train costs the sum
# of its stages when nothing but the shafts joins them. Needs valgrind and python3-yaml (Debian
# packages). ≈ 1 min.
# Usage: bench/train_cost.sh [BIN=build/bin/bench_dynamics] [SECONDS=0.02]
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${1:-build/bin/bench_dynamics}
seconds=${2:-0.02}
train=assets/scenarios/wind_turbine_3stage.yaml
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 - "$train" "$work" <<'EOF'
import math, sys, yaml
train, work = sys.argv[1], sys.argv[2]
s = yaml.safe_load(open(train))
carrier = s['motors'][0]['target_speed_rad_s']
sun = carrier * (1 + 99 / 21)  # the stage-1 sun and the stage-2 wheel on its shaft
# Each stage's output carries the torque it passes on in the train: the generator's, stepped up
# through 88/22 and 82/23, against the sense the member turns.
generator = s['loads'][0]['constant_torque_N_m']
inputs = {'s1': ('s1_carrier', carrier, 's1_sun', generator * 88 / 22 * 82 / 23),
          's2': ('s2_wheel', sun, 's2_pinion', -generator * 88 / 22),
          's3': ('s3_wheel', -sun * 82 / 23, 's3_pinion', generator)}
for st in s['stages']:
    one = {k: v for k, v in s.items() if k not in ('stages', 'shafts', 'transmission', 'motors', 'loads')}
    one['name'] = 'stage_' + st['name']
    one['stages'] = [st]
    joint, speed, out, torque = inputs[st['name']]
    one['motors'] = [{**s['motors'][0], 'joint': joint, 'target_speed_rad_s': speed}]
    one['loads'] = [{**s['loads'][0], 'joint': out, 'constant_torque_N_m': torque}]
    yaml.safe_dump(one, open(f"{work}/{st['name']}.yaml", 'w'))
EOF
count() {  # instructions per step, k
  bench/instructions.sh "$bin" "$seconds" "$1" | awk '/World::step/ {print $(NF - 3)}'
}
whole=$(count "$train")
sum=0
for st in s1 s2 s3; do
  k=$(count "$work/$st.yaml")
  echo "stage $st alone: $k k instructions per step"
  sum=$(awk -v a="$sum" -v b="$k" 'BEGIN {print a + b}')
done
echo "three stages alone, summed: $sum k per step"
echo "the train (wind_turbine_3stage.yaml): $whole k per step ($(awk -v a="$whole" -v b="$sum" 'BEGIN {printf "%.3f", a / b}') × the sum)"
