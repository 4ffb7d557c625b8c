// libFuzzer target: OptionSet::LoadYaml (`--profile FILE`) on any bytes: nested maps, dotted
// keys, aliases, sequences or maps as keys, duplicate keys. An error or a loaded set, never a
// throw out of the reader, a crash or a huge allocation.
#include "tests/fuzz/fuzz_file.h"
#include "tests/fuzz/fuzz_options.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const sightline::OptionSet kDeclared = sightline::fuzz::FuzzOptionSet();
  sightline::OptionSet options = kDeclared;
  (void)options.LoadYaml(sightline::fuzz::WriteInput("profile.yaml", data, size));
  return 0;
}
