# Sourced by run-fuzzers.sh and run-sanitizers.sh: the build dirs of the hardening runs.
#   build-fuzz/  clang, ASan+UBSan and libFuzzer's coverage on every target: the fuzzers and the
#                ASan+UBSan tests, one build for both (SIGHTLINE_FUZZ=ON)
#   build-tsan/  the default compiler, TSan: the threaded tests
# Both at -O1 (what the sanitizers' own documentation advises; quicker to compile than -O2)
# with the line tables the reports need, no benchmarks, ccache when installed. Only the targets
# asked for are built. Both scripts configure build-fuzz identically, so neither undoes the
# other's build.

# hardening_configure DIR fuzz|thread: configures DIR (again: the same cache values, so nothing is
# rebuilt), quietly (the log is DIR/configure.log and printed on failure).
hardening_configure() {
  local dir="$1" kind="$2" args=()
  args=(-S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
        "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1" "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1"
        -DSIGHTLINE_BUILD_BENCHMARKS=OFF -DSIGHTLINE_BUILD_TESTS=ON)
  if [ "$kind" = fuzz ]; then
    local cxx="${SIGHTLINE_FUZZ_CXX:-clang++}" cc="${SIGHTLINE_FUZZ_CC:-clang}"
    command -v "$cxx" >/dev/null ||
      { echo "hardening: $cxx not found (apt-get install clang)" >&2; return 1; }
    args+=(-DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_C_COMPILER="$cc" -DSIGHTLINE_FUZZ=ON)
  else
    args+=(-DSIGHTLINE_SANITIZE="$kind")
  fi
  mkdir -p "$dir"
  cmake "${args[@]}" >"$dir/configure.log" 2>&1 || { cat "$dir/configure.log"; return 1; }
}

# hardening_build DIR TARGET...: builds the targets with SIGHTLINE_JOBS jobs (default: nproc).
hardening_build() {
  local dir="$1"
  shift
  cmake --build "$dir" -j"${SIGHTLINE_JOBS:-$(nproc)}" --target "$@"
}
