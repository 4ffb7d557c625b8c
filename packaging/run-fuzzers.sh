#!/usr/bin/env bash
# Builds the libFuzzer targets (tests/fuzz; clang, ASan+UBSan) in build-fuzz/ (hardening-build.sh;
# the ASan+UBSan tests of run-sanitizers.sh share it) and runs each for
# a bounded time: `bash packaging/run-fuzzers.sh [SECONDS_PER_TARGET] [TARGET...]` (default 60 s,
# every target). Each target starts from its seed corpus tests/fuzz/corpus/<target>/ (never
# changed by a run; new inputs go to build-fuzz/corpus/<target>/). Fails on any finding: the
# crashing input is kept as build-fuzz/findings/<target>/crash-*; fix the reader and copy the
# input into tests/fuzz/corpus/<target>/ as a regression input.
# SIGHTLINE_FUZZ_JOBS fuzzers run at once (default 1); the execution counts are printed.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"
seconds="${1:-60}"
shift || true
build=build-fuzz
# shellcheck source=packaging/hardening-build.sh
source packaging/hardening-build.sh

start=$(date +%s)
hardening_configure "$build" fuzz
hardening_build "$build" fuzzers
echo "run-fuzzers.sh: build took $(( $(date +%s) - start )) s"

targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  for dir in tests/fuzz/corpus/*/; do targets+=("$(basename "$dir")"); done
fi
export ASAN_OPTIONS="${ASAN_OPTIONS:-allocator_may_return_null=0:detect_leaks=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"

run_one() {
  local t="$1" log="$build/logs/$1.log"
  mkdir -p "$build/corpus/$t" "$build/findings/$t" "$build/logs"
  # -rss_limit_mb / -malloc_limit_mb: a reader that allocates more than 1 GB for one input is a
  # finding (headers that lie about their sizes). -timeout: 10 s for one input is a hang.
  if "$build/bin/fuzz_$t" "$build/corpus/$t" "tests/fuzz/corpus/$t" -max_total_time="$seconds" \
      -rss_limit_mb=2048 -malloc_limit_mb=1024 -timeout=10 -max_len=65536 -print_final_stats=1 \
      -artifact_prefix="$build/findings/$t/" >"$log" 2>&1; then
    echo "fuzz_$t: $(grep -m1 'stat::number_of_executed_units' "$log" | awk '{print $2}') executions in ${seconds} s, no finding"
  else
    echo "fuzz_$t: FINDING (see $log and $build/findings/$t/)"
    grep -m3 -E 'ERROR: |runtime error|SUMMARY' "$log" || tail -5 "$log"
    return 1
  fi
}

failed=0
jobs_at_once="${SIGHTLINE_FUZZ_JOBS:-1}"
pids=()
for t in "${targets[@]}"; do
  run_one "$t" &
  pids+=($!)
  if [ ${#pids[@]} -ge "$jobs_at_once" ]; then
    wait "${pids[0]}" || failed=1
    pids=("${pids[@]:1}")
  fi
done
for pid in "${pids[@]}"; do wait "$pid" || failed=1; done
echo "run-fuzzers.sh: ${#targets[@]} target(s), $(( $(date +%s) - start )) s in all"
exit $failed
