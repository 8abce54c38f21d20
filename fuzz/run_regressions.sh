#!/usr/bin/env bash
# Runs each saved finding of fuzz/regressions/<target>/ once through its fuzz target
# (`make fuzz-regressions`; fuzz/README.md) and sorts it with fuzz/triage.py: "passes" once
# fixed, "libhdf5" while it fails inside HDF5 only, "finding" while partimix still fails on it.
# Exits 1 while any is a finding.
# Usage: fuzz/run_regressions.sh BUILD
set -uo pipefail
cd "$(dirname "$0")/.."

build=${1:?usage: fuzz/run_regressions.sh BUILD}
export OMP_NUM_THREADS=1
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}

failed=0
for target in case_loader_fuzz stl_reader_fuzz checkpoint_reader_fuzz; do
  inputs=()
  for input in fuzz/regressions/"$target"/*; do
    if [ -f "$input" ] && [ "$(basename "$input")" != README.md ]; then
      inputs+=("$input")
    fi
  done
  if [ ${#inputs[@]} -eq 0 ]; then
    continue
  fi
  echo "regressions: $target"
  ./fuzz/triage.py "$build/fuzz/$target" "${inputs[@]}" || failed=1
done
exit $failed
