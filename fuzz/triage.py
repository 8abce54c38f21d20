#!/usr/bin/env python3
"""Runs saved fuzz inputs once each through their target and sorts what they do (fuzz/README.md).

Usage: fuzz/triage.py BINARY INPUT...

Each input is run alone (no fuzzing) with full stacks. The first frame of the report that is
either in libhdf5 or in a source file (the sanitizer and libFuzzer runtimes, and libc, are
skipped) decides:
  passes       the input no longer fails (fixed, or it failed only after earlier inputs)
  libhdf5      the failure is inside HDF5 itself (its parser is not hardened against damaged
               files; the checkpoint header keeps such files out of a real run)
  finding      anything else: a crash, sanitizer report, uncaught exception, leak or timeout
               in partimix or the target
Prints a line per input that passes or is a finding, then one per kind of failure (with its
smallest input) and its top frames. Exits 1 when any
input is a finding.
"""
import collections
import os
import re
import subprocess
import sys

FRAME = re.compile(r"^\s+#\d+ 0x[0-9a-f]+ +(?:in (?P<function>.+?) )?(?P<where>\S+?)"
                   r"(?: \(BuildId: [0-9a-f]+\))?$")
SOURCE = re.compile(r"/(src|fuzz)/\S+\.(cpp|hpp|h):\d+")
RUNTIME = re.compile(r"^(__asan|__sanitizer|__interceptor|__lsan|__ubsan|fuzzer::|free$|malloc$|"
                     r"calloc$|realloc$|operator new|operator delete|abort$|raise$|"
                     r"__GI_|__libc|__pthread|pthread_kill|gsignal)")


def run(binary, path):
    environment = dict(os.environ)
    environment.setdefault("OMP_NUM_THREADS", "1")
    environment["ASAN_OPTIONS"] = environment.get("ASAN_OPTIONS", "") + ":fast_unwind_on_malloc=0"
    # Leaks are shown whole here, those inside HDF5 too, which the fuzzing runs suppress.
    environment.pop("LSAN_OPTIONS", None)
    result = subprocess.run([binary, "-timeout=10", "-rss_limit_mb=2048", path],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, env=environment,
                            check=False)
    return result.returncode, result.stdout.decode(errors="replace")


def short(function, where):
    where = re.sub(r"^/.*/(src|fuzz)/", r"\1/", where)
    function = function.replace("(anonymous namespace)", "{anonymous}").split("(")[0]
    return f"{function or '?'} {where}"


def kind_of_error(error):
    """The error line without its addresses and process number, to group inputs by."""
    match = re.search(r"ERROR: (\w+: [\w-]+(?: [\w-]+)*)", error)
    if match:
        return match.group(1)
    return re.sub(r"0x[0-9a-f]+|^\S+:\d+:\d+: ", "", error)[:100]


def classify(log):
    """('libhdf5' or 'finding', the error line, the top frames that decided)."""
    lines = log.splitlines()
    error = next((l.strip() for l in lines if "ERROR:" in l or "runtime error:" in l or
                  re.match(r"\w+_fuzz: ", l)), "no report")
    frames = []
    for line in lines:
        match = FRAME.match(line)
        if match:
            frames.append((match.group("function") or "", match.group("where")))
        elif frames:
            break  # the first stack only
    for k, (function, where) in enumerate(frames):
        if "libhdf5" in where:
            # The HDF5 call partimix made (the last HDF5 frame before partimix's) and the caller.
            caller = next((j for j in range(k, len(frames)) if SOURCE.search(frames[j][1])),
                          len(frames))
            top = [frames[k], frames[caller - 1]] + frames[caller:caller + 1]
            return "libhdf5", error, [short(f, w) for f, w in top]
        if SOURCE.search(where) and not RUNTIME.match(function):
            return "finding", error, [short(f, w) for f, w in frames[k:k + 3]]
    return "finding", error, [short(f, w) for f, w in frames[:3]]


def main():
    if len(sys.argv) < 3:
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    binary = sys.argv[1]
    kinds = collections.defaultdict(list)
    for path in sys.argv[2:]:
        status, log = run(binary, path)
        if status == 0:
            print(f"  passes   {path}")
            continue
        kind, error, top = classify(log)
        if kind == "finding":
            print(f"  {kind:<8} {path}: {error}")
        kinds[(kind, kind_of_error(error), tuple(top))].append(path)
    for (kind, error, top), paths in sorted(kinds.items()):
        print(f"  {kind}: {len(paths)} input(s), e.g. {min(paths, key=os.path.getsize)}: {error}")
        for frame in top:
            print(f"      {frame}")
    return 1 if any(kind == "finding" for kind, _, _ in kinds) else 0


if __name__ == "__main__":
    sys.exit(main())
