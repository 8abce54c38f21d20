#!/bin/bash
# The speed and fill sweeps of the seed's study drum, reduced (docs/dem.md, "The seed's study
# drum, reduced"): spheres (cases/drum_seed.yaml) and prolate spheroids of sigma = 1.5
# (cases/drum_seed_ellipsoids.yaml), the drum cut to 20 mm along its periodic axis (4,000 grains,
# the seed's 10,000 per 50 mm), at 20, 30, 40 and 50 rpm in the 200 mm drum (21% fill) and at
# 30 rpm in drums of 220, 240, 280 and 320 mm (18, 15, 11 and 8% fill), 6 s after settling. The
# mixing cells keep the size of the 200 mm drum's (20 mm), so the larger drums have more of them.
#
#     tools/drum_speed_fill_study.sh PARTIMIX OUT_DIR [JOBS] [SEED]
#
# Runs JOBS runs at a time (default 2), one thread each; a run whose folder holds a completed
# run.json is skipped, so the script resumes. SEED (default 1) is the fill's random seed; other
# seeds repeat the runs at 30 rpm in the 200 and 320 mm drums only (the run-to-run scatter),
# into folders named ..._seedSEED. Then summarise with
# tools/drum_speed_fill_study.py OUT_DIR.
set -euo pipefail

if [[ $# -lt 2 ]]; then
  echo "usage: $0 PARTIMIX OUT_DIR [JOBS] [SEED]" >&2
  exit 2
fi
partimix=$1
out=$2
jobs=${3:-2}
seed=${4:-1}
cases=$(cd "$(dirname "$0")/../cases" && pwd)
length=0.02
count=4000

# The keys of one run: shape (sphere or a sigma), rpm, drum radius [m].
run_keys() {
  local shape=$1 rpm=$2 radius=$3
  local edge cells half
  read -r edge cells half < <(awk -v r="${radius}" -v l="${length}" \
    'BEGIN { printf "%g %d %g\n", r + 0.001, r / 0.01 + 0.5, l / 2 }')
  echo "--set walls[0].radius=${radius} --set dem.fill.region.radius=${radius}"
  echo "--set domain.min=[-${edge},-${edge},0] --set domain.max=[${edge},${edge},${length}]"
  echo "--set dem.fill.region.height=${length} --set dem.fill.count=${count}"
  echo "--set analyses[0].min=[-${radius},-${radius},0]"
  echo "--set analyses[0].max=[${radius},${radius},${length}]"
  echo "--set analyses[0].cells=[${cells},${cells},1]"
  echo "--set analyses[2].start=[0,-${radius},${half}] --set analyses[2].end=[0,0,${half}]"
  echo "--set walls[0].motion.rpm=${rpm} --set time.end=6.0 --set time.output_interval=3.0"
  echo "--set dem.fill.seed=${seed}"
  if [[ ${shape} != sphere ]]; then
    echo "--set dem.species[0].shape.aspect_ratio=${shape}"
    echo "--set dem.species[1].shape.aspect_ratio=${shape}"
  fi
}

one_run() {
  local shape=$1 rpm=$2 radius=$3
  local name="${shape}_rpm${rpm}_r${radius}"
  [[ ${seed} != 1 ]] && name="${name}_seed${seed}"
  local case_file="${cases}/drum_seed_ellipsoids.yaml"
  [[ ${shape} == sphere ]] && case_file="${cases}/drum_seed.yaml"
  if grep -qs '"status": "completed"' "${out}/${name}/run.json"; then
    return 0
  fi
  # shellcheck disable=SC2046
  "${partimix}" run "${case_file}" -q --threads 1 --overwrite --out "${out}/${name}" \
    $(run_keys "${shape}" "${rpm}" "${radius}") >"${out}/${name}.log" 2>&1 ||
    echo "${name} failed: see ${out}/${name}.log" >&2
}
export -f one_run run_keys
export partimix out cases length count seed

mkdir -p "${out}"
{
  for shape in 1.5 sphere; do
    if [[ ${seed} != 1 ]]; then
      echo "${shape} 30 0.1"
      echo "${shape} 30 0.16"
      continue
    fi
    for rpm in 20 30 40 50; do
      echo "${shape} ${rpm} 0.1"
    done
    for radius in 0.11 0.12 0.14 0.16; do
      echo "${shape} 30 ${radius}"
    done
  done
} | xargs -P "${jobs}" -L 1 bash -c 'one_run "$@"' _
