#!/usr/bin/env bash
# Fuzzes one input path of Gearsim with libFuzzer for a given time (issue 16: safe with any
# input file). Builds build-fuzz/ with clang (GEARSIM_FUZZ: the libraries with ASan + UBSan and
# libFuzzer's coverage hooks), assembles the seed corpus from the repository, runs the target and
# prints executions, exec/s and the crashes found.
# Usage: scripts/fuzz.sh fuzz_scenario|fuzz_mesh|fuzz_mesh_obj|fuzz_run_record|fuzz_set SECONDS [JOBS]
#   fuzz_scenario  the bytes as a scenario file (load_scenario); seeds: assets/scenarios/*.yaml
#                  and small scenarios like the tests' (a wheel, MCAD pairs, gear_from, tables)
#   fuzz_mesh      byte 0 picks the unit, the rest is an STL file (read_mesh_gear: import,
#                  validation, prism, gear recognition); seeds: the MCAD meshes of
#                  tests/data/mcad (35–154 kB binary STL) and the z 12 one as ASCII STL;
#                  assets/gears/ (0.36–1.4 MB) are larger than -max_len and left out
#   fuzz_mesh_obj  the same with an OBJ file (a target of its own: Assimp's OBJ importer fills a
#                  16 MiB buffer per file, ~80 ms under ASan); seeds: the z 12 one as OBJ, a cube
#   fuzz_run_record  byte 0 picks scenario.json, summary.json or the manifest, the rest is the
#                  record (the readers of analyze/report/render); seeds: a short spur-pair run's
#                  records (made with build/bin/gearsim when it is built) and two damaged ones
#   fuzz_set       the bytes as --set overrides, one a line, on a small scenario; seeds: a few
#                  overrides, recursive and multiplying aliases among them
#   JOBS           fuzzing processes side by side, default 1
# Outputs in out/fuzz/TARGET/: crash-*, leak-*, timeout-*, oom-* (reproducers: run
# `build-fuzz/bin/TARGET FILE`), corpus/ (grows, kept between runs), seeds/, fuzz-JOB.RUN.log.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD

usage() { sed -n 's/^# Usage: //p' "$0" >&2; exit 2; }
[[ $# -ge 2 && $2 =~ ^[0-9]+$ ]] || usage
target=$1 seconds=$2 jobs=${3:-1}
# -timeout: an input running longer is a finding (saved as timeout-*). Loading a planetary
# scenario of the paper's spec takes 5–12 s in this build (the tip-interference scan of its
# meshes under ASan; 1.7 s in the GCC Release build): 30 s for scenarios, 10 s for meshes.
case $target in
  fuzz_scenario) max_len=65536 timeout=30 ;;  # 64 KiB: the largest shipped scenario is 5 kB
  fuzz_mesh | fuzz_mesh_obj) max_len=262144 timeout=10 ;;  # 256 KiB: the MCAD ring (154 kB) fits
  fuzz_run_record) max_len=131072 timeout=10 ;;  # 128 KiB: a paper run's summary is ~10 kB
  fuzz_set) max_len=4096 timeout=10 ;;
  *) usage ;;
esac

# Build (niced, 2 jobs at most: the machine is shared).
CC=clang CXX=clang++ nice -n 10 cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGEARSIM_FUZZ=ON \
  -DGEARSIM_BUILD_TESTS=OFF -DGEARSIM_BUILD_BENCH=OFF >/dev/null
nice -n 10 cmake --build build-fuzz --target "$target" -j2

out=$root/out/fuzz/$target
seeds=$out/seeds
mkdir -p "$out/corpus"
rm -rf "$seeds" && mkdir -p "$seeds"

# Seeds, rebuilt from the repository at each run.
if [[ $target == fuzz_scenario ]]; then
  # The input is written as scenarios/input.yaml beside specs/, gears/ and data/ (linked to
  # assets/specs, assets/gears, tests/data): the shipped scenarios' relative paths resolve.
  cp assets/scenarios/*.yaml "$seeds/"
  cat >"$seeds/wheel.yaml" <<'EOF'
name: t
duration_s: 0.1
bodies:
  - {name: wheel, mass_kg: 1.0, principal_inertia_kg_m2: [0.01, 0.01, 0.02], position_m: [0, 0, 0], angle_deg: 5}
joints:
  - {name: hinge, body: wheel, axis: [0, 0, 1], bearing: {radial_stiffness_N_per_m: 1e7}}
motors:
  - {joint: hinge, target_speed_rad_s: 1, ramp_time_s: 0.01, max_torque_N_m: 1}
loads:
  - {joint: hinge, constant_torque_N_m: -0.1, viscous_N_m_s_per_rad: 0.01}
transmission: {input_joint: hinge, output_joint: hinge, ratio: 1}
solver: {time_step_s: 1.0e-5}
output: {sample_rate_hz: 1000, per_step_log: false}
render: {camera: overview, fps: 30, slowmo: 2, from_s: 0, to_s: 0.05, width_px: 64, height_px: 64, msaa: 0}
EOF
  cat >"$seeds/mcad_pair.yaml" <<'EOF'
name: mcad pair
duration_s: 0.15
pair:
  driver: {name: pinion, density_kg_m3: 7850, mesh: {file: ../data/mcad/mcad_m1_z12_a20_f5_b005.stl, unit: mm, teeth: 12, tooth0_deg: 0}}
  driven: {name: wheel, density_kg_m3: 7850, mesh: {file: ../data/mcad/mcad_m1_z24_a20_f5_b005.stl, unit: mm}}
  centre_distance_m: 0.018
motors: [{joint: pinion, target_speed_rad_s: 20, ramp_time_s: 0.05, max_torque_N_m: 5}]
loads:  [{joint: wheel, constant_torque_N_m: 1.1276, ramp_time_s: 0.05}]
EOF
  cat >"$seeds/mcad_planetary.yaml" <<'EOF'
name: mcad planetary
duration_s: 0.15
planetary:
  sun: {density_kg_m3: 7850, mesh: {file: ../data/mcad/mcad_m1_z12_a20_f5_b005.stl, unit: mm}}
  planet: {density_kg_m3: 7850, mesh: {file: ../data/mcad/mcad_m1_z18_a20_f5_b005.stl, unit: mm}}
  ring: {density_kg_m3: 7850, mesh: {file: ../data/mcad/mcadring_m1_z48_a20_f5_b005.stl, unit: mm}}
  planets: 3
  carrier: {mass_kg: 0.3, inertia_z_kg_m2: 2.0e-4}
motors: [{joint: sun, target_speed_rad_s: 20, max_torque_N_m: 5}]
loads: [{joint: carrier, constant_torque_N_m: -1}]
EOF
  cat >"$seeds/star_stages.yaml" <<'EOF'
name: star stages
reference: paper
duration_s: 0.05
stages:
  - name: a
    planetary:
      sun: {density_kg_m3: 7850, mesh: {file: ../data/mcad/mcad_m1_z12_a20_f5_b005.stl, unit: mm}}
      planet: {density_kg_m3: 7850, mesh: {file: ../data/mcad/mcad_m1_z18_a20_f5_b005.stl, unit: mm}}
      ring: {density_kg_m3: 7850, mesh: {file: ../data/mcad/mcadring_m1_z48_a20_f5_b005.stl, unit: mm}}
      planets: 3
      fixed: carrier
      carrier: {mass_kg: 0.3, inertia_z_kg_m2: 2.0e-4}
  - name: b
    planetary:
      origin_m: [0, 0, 0.01]
      sun: {density_kg_m3: 7850, mesh: {file: ../data/mcad/mcad_m1_z12_a20_f5_b005.stl, unit: mm}}
      planet: {density_kg_m3: 7850, mesh: {file: ../data/mcad/mcad_m1_z18_a20_f5_b005.stl, unit: mm}}
      ring: {density_kg_m3: 7850, mesh: {file: ../data/mcad/mcadring_m1_z48_a20_f5_b005.stl, unit: mm}}
      planets: 3
      fixed: sun
      carrier: {mass_kg: 0.3, inertia_z_kg_m2: 2.0e-4}
shafts:
  - {from: a_ring, to: b_ring, torsional_stiffness_N_m_per_rad: 1.0e4}
motors: [{joint: a_sun, target_speed_rad_s: 20, max_torque_N_m: 5}]
loads: [{joint: b_carrier, constant_torque_N_m: -1}]
EOF
  cat >"$seeds/helical_pair.yaml" <<'EOF'
name: helical pair
duration_s: 0.01
pair:
  driver: {name: pinion, density_kg_m3: 7850, gear: {kind: external, teeth: 20, normal_module_m: 0.002, normal_pressure_angle_deg: 20, helix_angle_deg: 15, hand: right, face_width_m: 0.02, bore_diameter_m: 0.008, thinning_per_flank_m: 1.0e-5, errors: {flank_offsets: [{tooth: 0, flank: ccw, normal_offset_m: -4.3e-5}]}}}
  driven: {name: wheel, density_kg_m3: 7850, gear: {kind: external, teeth: 40, normal_module_m: 0.002, helix_angle_deg: 15, hand: left, face_width_m: 0.02, bore_diameter_m: 0.01}}
motors: [{joint: pinion, target_speed_rad_s: 10, max_torque_N_m: 5}]
EOF
  cat >"$seeds/ring_pair.yaml" <<'EOF'
name: ring_pair
duration_s: 0.01
pair:
  driver: {name: planet, gear_from: {spec: ../specs/paper_gearset.yaml, gear: planet}}
  driven: {name: ring_relieved, gear_from: {spec: ../specs/paper_gearset.yaml, gear: ring_relieved}}
motors: [{joint: planet, target_speed_rad_s: 20, max_torque_N_m: 10}]
EOF
  cat >"$seeds/tables.yaml" <<'EOF'
name: t
duration_s: 0.01
contact:
  stiffness_tables:
    - {gears: [sun, planet], file: ../specs/paper_fe_sun_planet_stiffness.csv, body_stiffness_N_per_m: 1.86775e8}
    - {gears: [planet, ring], file: ../specs/paper_fe_planet_ring_stiffness.csv}
planetary:
  spec: ../specs/paper_gearset.yaml
  ring: ring_relieved
  carrier: {mass_kg: 0.3, inertia_z_kg_m2: 2.0e-4}
EOF
elif [[ $target == fuzz_run_record ]]; then
  rec=$(mktemp -d)
  if [[ -x build/bin/gearsim ]]; then
    build/bin/gearsim run assets/scenarios/spur_pair.yaml --out "$rec/r" --duration 0.2 >/dev/null
    { printf '\x00'; cat "$rec/r/scenario.json"; } >"$seeds/scenario.json"
    { printf '\x01'; cat "$rec/r/summary.json"; } >"$seeds/summary.json"
    { printf '\x02'; cat "$rec/r/.gearsim-manifest"; } >"$seeds/manifest"
  fi
  printf '\x01{"sim_seconds": "abc"}' >"$seeds/bad_summary.json"
  printf '\x02state.csv\n../../etc/passwd\n' >"$seeds/bad_manifest"
  rm -rf "$rec"
elif [[ $target == fuzz_set ]]; then
  printf 'solver.time_step_s=1e-5' >"$seeds/step"
  printf 'x=&r [1, *r]' >"$seeds/recursive"
  printf 'bodies[0].mass_kg=2\nduration_s=0.2' >"$seeds/two"
  printf 'solver={time_step_s: 1e-4, time_step_s: 1e-5}' >"$seeds/twice"
  printf 'x={a: &a [1, 1, 1], b: &b [*a, *a, *a], c: [*b, *b, *b]}' >"$seeds/aliases"
else
  # Byte 0: byte % 3 = unit (mm, m, in); \x00 is mm, \x01 m.
  if [[ $target == fuzz_mesh ]]; then
    for f in tests/data/mcad/*.stl; do
      { printf '\x00'; cat "$f"; } >"$seeds/$(basename "$f")"
    done
  fi
  # The z 12 pinion as ASCII STL and as OBJ (shared vertices), converted here from its binary STL.
  python3 - tests/data/mcad/mcad_m1_z12_a20_f5_b005.stl "$seeds" "$target" <<'EOF'
import struct, sys
data = open(sys.argv[1], 'rb').read()
n = struct.unpack_from('<I', data, 80)[0]
facets = [struct.unpack_from('<12f', data, 84 + 50 * i) for i in range(n)]
obj = sys.argv[3] == 'fuzz_mesh_obj'
with open(sys.argv[2] + '/z12_ascii.stl', 'wb') if not obj else open('/dev/null', 'wb') as f:
    f.write(b'\x00solid z12\n')
    for t in facets:
        f.write(b'facet normal %g %g %g\n outer loop\n' % t[:3])
        for k in range(3):
            f.write(b'  vertex %.9g %.9g %.9g\n' % t[3 + 3 * k:6 + 3 * k])
        f.write(b' endloop\nendfacet\n')
    f.write(b'endsolid z12\n')
index, lines, faces = {}, [], []
for t in facets:
    face = []
    for k in range(3):
        v = t[3 + 3 * k:6 + 3 * k]
        if v not in index:
            index[v] = len(index) + 1
            lines.append(b'v %.9g %.9g %.9g\n' % v)
        face.append(index[v])
    faces.append(b'f %d %d %d\n' % tuple(face))
if obj:
    with open(sys.argv[2] + '/z12.obj', 'wb') as f:
        f.write(b'\x00' + b''.join(lines) + b''.join(faces))
EOF
  # A unit cube (a solid, not a gear), as OBJ in metres.
  if [[ $target == fuzz_mesh_obj ]]; then
    printf '\x01v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\nf 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n' \
      >"$seeds/cube.obj"
  fi
fi

# Run: JOBS fuzzing loops side by side, sharing corpus/ (libFuzzer reloads it). A crash, leak,
# out-of-memory or sanitizer report ends its loop with a reproducer; a timeout is saved as
# timeout-* and the loop starts libFuzzer again until SECONDS are spent.
# (libFuzzer's own -fork mode re-runs its seeds at every short job: with paper scenarios at
# seconds each it did almost nothing else.)
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
export LSAN_OPTIONS="suppressions=$root/scripts/lsan.supp:print_suppressions=0"
cd "$out"
rm -f fuzz-*.log
before=$(ls crash-* leak-* timeout-* oom-* 2>/dev/null | sort || true)
start=$(date +%s)
fuzz_loop() {
  local job=$1 run=0 left
  while left=$((start + seconds - $(date +%s))) && [[ $left -gt 0 ]]; do
    run=$((run + 1))
    # Faster inputs are mutated more often (up to 30×): a paper scenario loads for seconds.
    nice -n 10 "$root/build-fuzz/bin/$target" -max_len=$max_len -rss_limit_mb=2048 -timeout=$timeout \
      -entropic_scale_per_exec_time=1 -max_total_time=$left -print_final_stats=1 -artifact_prefix="$out/" corpus seeds \
      >"fuzz-$job.$run.log" 2>&1 && break
    grep -q 'ERROR: libFuzzer: timeout' "fuzz-$job.$run.log" || break
    # The slow input is kept as timeout-SHA1; out of corpus/ so that the next start skips it.
    # A seed that times out stops the loop: it needs a look, not another start.
    unit=$(sed -n 's/.*Test unit written to .*timeout-\([0-9a-f]*\).*/\1/p' "fuzz-$job.$run.log" | tail -1)
    [[ -n $unit ]] && rm -f "corpus/$unit"
    [[ -n $unit ]] && sha1sum seeds/* | grep -q "^$unit " && break
  done
}
for job in $(seq 1 "$jobs"); do fuzz_loop "$job" & done
wait
wall=$(($(date +%s) - start))

# Summary: executions summed over every run's final stats.
execs=$(cat fuzz-*.log | sed -n 's/^stat::number_of_executed_units: *//p' | awk '{s += $1} END {print s + 0}')
after=$(ls crash-* leak-* timeout-* oom-* 2>/dev/null | sort || true)
found=$(comm -13 <(echo "$before") <(echo "$after") | sed '/^$/d')
echo "target:     $target ($jobs job(s), -max_len=$max_len -rss_limit_mb=2048 -timeout=$timeout)"
echo "wall:       ${wall} s"
echo "executions: $execs"
echo "exec/s:     $((execs / (wall > 0 ? wall : 1))) (over the wall time, all jobs)"
echo "corpus:     $(ls corpus | wc -l) inputs in $out/corpus"
echo "found:      $(echo -n "$found" | grep -c . || true) (crash-*, leak-*, oom-*: bugs; timeout-*: inputs over $timeout s)"
for f in $found; do echo "  $out/$f  (reproduce: build-fuzz/bin/$target $out/$f)"; done
echo "logs:       $out/fuzz-JOB.RUN.log"
