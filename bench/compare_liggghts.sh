#!/usr/bin/env bash
# Runs the seed drum (cases/drum_seed.yaml, 10,000 spheres, 30 rpm) in LIGGGHTS 3.8 (Debian's
# package, installed here when missing) and in partimix's bench (drum_10k), on 1 and 2 cores in
# one sitting, and prints particle-steps per second and the ratio (docs/performance.md).
# LIGGGHTS runs on MPI ranks (1 and 2), partimix on OpenMP threads (1 and 2). Both settle the
# bed for 0.3 s with the drum at rest before the timed steps.
# Usage: bench/compare_liggghts.sh [BUILD_DIR]   (default build; needs partimix_bench built)
set -euo pipefail

here="$(cd "$(dirname "$0")" && pwd)"
build="${1:-$here/../build}"
bench="$build/bench/partimix_bench"
[ -x "$bench" ] || { echo "compare_liggghts: build $bench first (make build)" >&2; exit 1; }

if ! command -v liggghts >/dev/null; then
  [ "$(id -u)" -eq 0 ] || { echo "compare_liggghts: need root to install liggghts" >&2; exit 1; }
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq liggghts >/dev/null
fi

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# The drum wall: a cylinder of radius 0.1 m from z = 0 to 0.05 m, 360 facets around, normals
# inwards (LIGGGHTS meshes are two-sided; the orientation does not matter for contacts).
awk -v n=360 -v r=0.1 -v l=0.05 'BEGIN {
  pi = atan2(0, -1); print "solid drum";
  for (k = 0; k < n; ++k) {
    a = 2 * pi * k / n; b = 2 * pi * (k + 1) / n;
    x0 = r * cos(a); y0 = r * sin(a); x1 = r * cos(b); y1 = r * sin(b);
    nx = -cos((a + b) / 2); ny = -sin((a + b) / 2);
    printf "facet normal %g %g 0\nouter loop\nvertex %.9g %.9g 0\nvertex %.9g %.9g 0\n", nx, ny, x0, y0, x1, y1;
    printf "vertex %.9g %.9g %g\nendloop\nendfacet\n", x1, y1, l;
    printf "facet normal %g %g 0\nouter loop\nvertex %.9g %.9g 0\nvertex %.9g %.9g %g\n", nx, ny, x0, y0, x1, y1, l;
    printf "vertex %.9g %.9g %g\nendloop\nendfacet\n", x0, y0, l;
  }
  print "endsolid drum" }' > "$work/drum.stl"

settle_steps=${SETTLE_STEPS:-8667}   # 0.3 s
timed_steps=${TIMED_STEPS:-3000}
skin=${SKIN:-0.001}

# particle-steps/s of the last "Loop time" line of a LIGGGHTS screen file.
loop_rate() {
  awk '/^Loop time of/ { t = $4; n = $9; m = $12 } END { printf "%.4g", n * m / t }' "$1"
}

liggghts_rate() {
  local ranks="$1" screen="$work/screen_$1.txt"
  (cd "$work" && mpirun --allow-run-as-root --oversubscribe -np "$ranks" liggghts \
     -in "$here/liggghts/drum_seed.in" -log none -screen "$screen" -var stl "$work/drum.stl" \
     -var skin "$skin" -var settle_steps "$settle_steps" -var timed_steps "$timed_steps" \
     </dev/null >/dev/null)
  loop_rate "$screen"
}

partimix_rates() {
  "$bench" --benchmark_filter='^drum_10k/' --benchmark_format=json 2>/dev/null |
    /usr/bin/python3 -c 'import json, sys
for b in json.load(sys.stdin)["benchmarks"]:
    print("%.4g" % b["particle_steps_per_s"])'
}

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)"
echo "LIGGGHTS skin: $skin m, timed steps: $timed_steps"
l1=$(liggghts_rate 1)
l2=$(liggghts_rate 2)
mapfile -t p < <(partimix_rates)
printf "%-8s %-14s %-14s %s\n" cores LIGGGHTS partimix "partimix/LIGGGHTS"
printf "%-8s %-14s %-14s %.2f\n" 1 "$l1" "${p[0]}" "$(awk -v a="${p[0]}" -v b="$l1" 'BEGIN { print a / b }')"
printf "%-8s %-14s %-14s %.2f\n" 2 "$l2" "${p[1]}" "$(awk -v a="${p[1]}" -v b="$l2" 'BEGIN { print a / b }')"
