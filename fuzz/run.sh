#!/usr/bin/env bash
# Runs each fuzz target for SECONDS, one after the other (fuzz/README.md; `make fuzz`,
# `make fuzz-smoke`). Per target: corpus in BUILD/corpus/<target> (kept between runs, new inputs
# added there), seeds from BUILD/seeds/<target> (fuzz/make_seeds.sh), findings (crash-*,
# timeout-*, leak-*, oom-*) in BUILD/artifacts/<target>/, the log in BUILD/logs/<target>.log.
#
# libFuzzer runs in fork mode (-fork=1) and goes on after a finding (-ignore_crashes,
# -ignore_timeouts, -ignore_ooms), so that one run collects every kind of failure it meets,
# HDF5's own crashes on damaged files among them; fuzz/triage.py then reruns each new finding
# alone and sorts it. Prints the inputs executed, exec/s and coverage (cov: edges, ft:
# features) per target; exits 1 when a target has a finding outside libhdf5.
# Usage: fuzz/run.sh BUILD SECONDS [TARGET...]
set -uo pipefail
cd "$(dirname "$0")/.."

build=${1:?usage: fuzz/run.sh BUILD SECONDS [TARGET...]}
seconds=${2:?usage: fuzz/run.sh BUILD SECONDS [TARGET...]}
shift 2
targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  targets=(case_loader_fuzz stl_reader_fuzz checkpoint_reader_fuzz)
fi

# One thread: the targets are single-threaded and the machine is shared. Every UBSan report
# is fatal (-fno-sanitize-recover) and comes with a stack. HDF5's own leaks are suppressed
# (fuzz/lsan.supp).
export OMP_NUM_THREADS=1
# The targets' scratch files go to a folder of this run, removed at the end: a child that
# crashes (fork mode goes on after it) cannot remove its own, and they piled up in /tmp.
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
export TMPDIR=$scratch
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$PWD/fuzz/lsan.supp:print_suppressions=0}

failed=0
summary=()
for target in "${targets[@]}"; do
  binary=$build/fuzz/$target
  corpus=$build/corpus/$target
  artifacts=$build/artifacts/$target
  log=$build/logs/$target.log
  mkdir -p "$corpus" "$artifacts" "$(dirname "$log")"
  before=$(mktemp)
  find "$artifacts" -type f | sort >"$before"
  options=(-fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1
           -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048
           -artifact_prefix="$artifacts/")
  dict=fuzz/${target%_fuzz}.dict
  if [ -f "$dict" ]; then
    options+=(-dict="$dict")
  fi
  echo "fuzz: $target for ${seconds} s (log: $log)"
  "$binary" "${options[@]}" "$corpus" "$build/seeds/$target" >"$log" 2>&1
  status=$?

  # The fork mode's last status line: "#<executed>: cov: C ft: F corp: N exec/s E
  # oom/timeout/crash: o/t/c time: Ts job: J ...".
  last=$(grep -E '^#[0-9]+: cov:' "$log" | tail -1)
  executed=$(sed -nE 's/^#([0-9]+):.*/\1/p' <<<"$last")
  elapsed=$(sed -nE 's/.* time: ([0-9]+)s.*/\1/p' <<<"$last")
  coverage=$(grep -Eo 'cov: [0-9]+ ft: [0-9]+' <<<"$last")
  failures=$(grep -Eo 'oom/timeout/crash: [0-9/]+' <<<"$last")
  per_second=?
  if [ -n "$executed" ] && [ -n "$elapsed" ] && [ "$elapsed" -gt 0 ]; then
    per_second=$((executed / elapsed))
  fi
  echo "stat::number_of_executed_units: ${executed:-?}" >>"$log"
  line="$target: ${executed:-?} inputs executed in ${elapsed:-?} s (${per_second} exec/s)"
  line="$line, ${coverage:-no coverage line}, ${failures:-no failure count}"
  new=$(find "$artifacts" -type f | sort | comm -13 "$before" -)
  rm -f "$before"
  # In fork mode libFuzzer exits with the status of its last job, so a status other than 0 is
  # a failure only when no finding explains it.
  if [ -z "$last" ] || { [ $status -ne 0 ] && [ -z "$new" ]; }; then
    failed=1
    line="$line: libFuzzer FAILED (exit $status), see $log"
  fi
  if [ -n "$new" ]; then
    echo "fuzz: $target: $(wc -l <<<"$new") new finding(s) in $artifacts/:"
    # shellcheck disable=SC2086
    if ! ./fuzz/triage.py "$binary" $new; then
      failed=1
      line="$line: FINDINGS in $artifacts/"
    else
      line="$line: new inputs fail inside libhdf5 only (or no longer fail)"
    fi
  fi
  echo "fuzz: $line"
  summary+=("$line")
done

echo "fuzz: summary"
printf '  %s\n' "${summary[@]}"
exit $failed
