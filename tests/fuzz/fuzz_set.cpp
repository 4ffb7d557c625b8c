// libFuzzer target: OptionSet::ApplyOverride, the parser of `--set KEY=VALUE`, on any text.
#include "tests/fuzz/fuzz_file.h"
#include "tests/fuzz/fuzz_options.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const sightline::OptionSet kDeclared = sightline::fuzz::FuzzOptionSet();
  sightline::OptionSet options = kDeclared;
  (void)options.ApplyOverride(sightline::fuzz::AsText(data, size));
  return 0;
}
