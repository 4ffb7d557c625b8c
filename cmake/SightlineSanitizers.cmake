# Sanitizer and fuzzing instrumentation (packaging/run-sanitizers.sh, packaging/run-fuzzers.sh).
# SIGHTLINE_SANITIZE="address,undefined" or "thread" instruments every target of the build dir;
# SIGHTLINE_FUZZ=ON adds ASan+UBSan and libFuzzer's coverage to every target (clang only).
if(SIGHTLINE_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "SIGHTLINE_FUZZ=ON needs clang: -DCMAKE_CXX_COMPILER=clang++")
  endif()
  set(SIGHTLINE_SANITIZE "address,undefined")
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
if(SIGHTLINE_SANITIZE)
  # UBSan findings abort so that a test or fuzzer fails on them; frame pointers for reports.
  add_compile_options(-fsanitize=${SIGHTLINE_SANITIZE} -fno-omit-frame-pointer -g1)
  add_link_options(-fsanitize=${SIGHTLINE_SANITIZE})
  if(SIGHTLINE_SANITIZE MATCHES "undefined")
    add_compile_options(-fno-sanitize-recover=undefined)
  endif()
endif()
