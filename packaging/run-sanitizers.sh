#!/usr/bin/env bash
# Builds tests with sanitizers, each kind in its own build dir (hardening-build.sh), and runs them:
#   build-fuzz/  clang, ASan+UBSan (the fuzzers' build): the core tests (SIGHTLINE_ASAN_TESTS,
#                default every tests/core test)
#   build-tsan/  TSan: the threaded tests (SIGHTLINE_TSAN_TESTS)
# Both lists hold "test_target[:gtest_filter]" entries separated by white space.
# `bash packaging/run-sanitizers.sh [asan|tsan|all]` (default all). Only the listed test targets
# and what they link are built (no GUI, no benchmarks); ccache is used. Any report fails the
# run (UBSan aborts on the first finding; ASan and TSan exit non-zero).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"
which="${1:-all}"

# Every test target of tests/core (one per sightline_add_gtest line), hardware-free ones only.
core_tests() {
  grep -rhoE 'sightline_add_gtest\([a-z_0-9]+ [a-z_0-9]+' tests/core | awk '{print "test_"$2}' |
    grep -vE 'aravis|openni2' | sort -u | tr '\n' ' '
}
# "target[:gtest filter]" of the threaded tests: the bounded queue, stage workers, the player,
# live sources (the synthetic ones), the recorder, the arm server and the threaded mono mode.
default_tsan_tests="test_bounded_queue test_stage test_record
  test_sensors:ReplaySource*:SensorStats*:TimestampPairer* test_aravis_fake
  test_arm_link:ArmServer*:ArmClient* test_mono_threaded"

words() {  # array name, text: splits on any white space (newlines too), no globbing of '*'
  local -n out="$1"
  set -f
  # shellcheck disable=SC2206
  out=($2)
  set +f
}

# shellcheck source=packaging/hardening-build.sh
source packaging/hardening-build.sh
configure_and_build() {  # dir, fuzz|thread, targets...
  local dir="$1" kind="$2"
  shift 2
  local start=$(date +%s)
  hardening_configure "$dir" "$kind"
  hardening_build "$dir" "$@"
  echo "run-sanitizers.sh: $dir build took $(( $(date +%s) - start )) s"
}

run_tests() {  # dir, "target[:filter]"...
  local dir="$1" failed=0
  shift
  for entry in "$@"; do
    local target="${entry%%:*}" filter="*"
    [ "$entry" != "$target" ] && filter="${entry#*:}"
    local start=$(date +%s)
    if "$dir/bin/$target" --gtest_filter="$filter" >"$dir/$target.log" 2>&1; then
      echo "$dir $target: passed ($(grep -m1 -oE '[0-9]+ tests? from [0-9]+ test suites? ran' "$dir/$target.log"), $(( $(date +%s) - start )) s)"
    else
      echo "$dir $target: FAILED (see $dir/$target.log)"
      grep -m5 -E 'ERROR: (Address|Thread|Leak)Sanitizer|WARNING: ThreadSanitizer|runtime error|SUMMARY|\[  FAILED  \]' "$dir/$target.log" || tail -5 "$dir/$target.log"
      failed=1
    fi
  done
  return $failed
}

failed=0
export SIGHTLINE_DATA_DIR="${SIGHTLINE_DATA_DIR:-$(cd .. && pwd)/shared/data}"
if [ "$which" = all ] || [ "$which" = asan ]; then
  words asan "${SIGHTLINE_ASAN_TESTS:-$(core_tests)}"
  targets=()
  for entry in "${asan[@]}"; do targets+=("${entry%%:*}"); done
  configure_and_build build-fuzz fuzz "${targets[@]}"
  export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=0}"
  export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
  export LSAN_OPTIONS="suppressions=$here/packaging/sanitizer-suppressions/lsan.txt"
  run_tests build-fuzz "${asan[@]}" || failed=1
fi
if [ "$which" = all ] || [ "$which" = tsan ]; then
  words tsan "${SIGHTLINE_TSAN_TESTS:-$default_tsan_tests}"
  targets=()
  for entry in "${tsan[@]}"; do targets+=("${entry%%:*}"); done
  # Set before the build: gtest_discover_tests runs each test binary at build time.
  export TSAN_OPTIONS="${TSAN_OPTIONS:-halt_on_error=1:second_deadlock_stack=1:suppressions=$here/packaging/sanitizer-suppressions/tsan.txt}"
  configure_and_build build-tsan thread "${targets[@]}"
  # TSan needs the kernel's default address-space layout: run without ASLR when available.
  runner=()
  setarch "$(uname -m)" -R true 2>/dev/null && runner=(setarch "$(uname -m)" -R)
  if [ ${#runner[@]} -gt 0 ]; then
    "${runner[@]}" bash -c "$(declare -f run_tests); run_tests build-tsan ${tsan[*]@Q}" || failed=1
  else
    run_tests build-tsan "${tsan[@]}" || failed=1
  fi
fi
exit $failed
