#!/usr/bin/env bash
# Assembles the seed inputs of the fuzz targets into OUT/<target>/ (fuzz/README.md):
#   case_loader_fuzz        cases/*.yaml, fuzz/seeds/case_loader/*.yaml, and a few cases
#                           followed by "---set" override lines (the input format of the target)
#   stl_reader_fuzz         fuzz/seeds/stl/*.stl (hand-made ASCII and binary meshes)
#   checkpoint_reader_fuzz  fuzz/seeds/checkpoint/*.h5, and a fresh checkpoint of
#                           fuzz/seeds/checkpoint_case.yaml when PARTIMIX (a built partimix
#                           program) is given, each once as it is (mode byte 0) and once with the
#                           header repaired by the target (mode byte 1)
# Usage: fuzz/make_seeds.sh OUT [PARTIMIX]
set -euo pipefail
cd "$(dirname "$0")/.."

out=${1:?usage: fuzz/make_seeds.sh OUT [PARTIMIX]}
partimix=${2:-}

rm -rf "$out"
mkdir -p "$out/case_loader_fuzz" "$out/stl_reader_fuzz" "$out/checkpoint_reader_fuzz"

# --- case loader ---
cp cases/*.yaml fuzz/seeds/case_loader/*.yaml "$out/case_loader_fuzz/"
with_overrides() {
  local case_file=$1 name=$2
  shift 2
  {
    cat "$case_file"
    printf -- '---set\n'
    printf '%s\n' "$@"
  } >"$out/case_loader_fuzz/$name"
}
with_overrides cases/dam_break_2d.yaml set_dam_break.yaml \
  'sph.spacing=0.05' 'walls[0].open=[y+, x+]' 'sph.density.delta=0.2' \
  'fluid.regions[1]={shape: box, min: [1, 0], max: [1.5, 0.5]}'
with_overrides cases/hydrostatic_tank_2d.yaml set_rheology.yaml \
  'fluid.viscosity=null' 'sph.spacing=0.1' \
  'fluid.rheology={model: power_law, consistency: 0.1, flow_index: 0.5, viscosity_max: 100}'
with_overrides cases/drum_validation.yaml set_drum.yaml \
  'dem.fill.count=50' 'dem.fill.settle_time=0' 'walls[0].motion.rpm=40' 'analyses[0].cells=[2, 2, 1]'
with_overrides fuzz/seeds/case_loader/dem_mesh_walls.yaml set_mesh.yaml \
  'walls[0].file=open.stl' 'walls[1].scale=2' 'time.dt=1.0e-4' 'time.sub_steps={dem: 3}'
with_overrides cases/poiseuille_2d.yaml set_periodic.yaml \
  'domain.periodic=[x, y]' 'sph.kernel=hyperbolic' 'name=' 'description=~'

# --- STL reader ---
cp fuzz/seeds/stl/*.stl "$out/stl_reader_fuzz/"

# --- checkpoint reader ---
for file in fuzz/seeds/checkpoint/*.h5; do
  cp "$file" "$out/checkpoint_reader_fuzz/committed_$(basename "$file")"
done
if [ -n "$partimix" ]; then
  scratch=$(mktemp -d)
  if OMP_NUM_THREADS=1 "$partimix" run fuzz/seeds/checkpoint_case.yaml --out "$scratch/run" \
    --quiet >"$scratch/log" 2>&1; then
    for file in "$scratch"/run/checkpoints/*.h5; do
      cp "$file" "$out/checkpoint_reader_fuzz/fresh_$(basename "$file")"
    done
  else
    echo "make_seeds: $partimix could not write a fresh checkpoint (using the committed one):" >&2
    cat "$scratch/log" >&2
  fi
fi
for file in "$out"/checkpoint_reader_fuzz/*.h5; do
  { printf '\000'; cat "$file"; } >"${file%.h5}_as_is"
  { printf '\001'; cat "$file"; } >"${file%.h5}_repaired"
  rm "$file"
done
if [ -n "${scratch:-}" ]; then
  rm -rf "$scratch"
fi

for target in case_loader_fuzz stl_reader_fuzz checkpoint_reader_fuzz; do
  echo "make_seeds: $(find "$out/$target" -type f | wc -l) seeds for $target"
done
