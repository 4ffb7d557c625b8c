// libFuzzer target: ReadPcdFile on any bytes (ascii, binary and binary_compressed headers and
// bodies). Any input must give a cloud or an error, never a crash or a huge allocation.
#include "core/io/pcd_source.h"
#include "tests/fuzz/fuzz_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = sightline::fuzz::WriteInput("input.pcd", data, size);
  (void)sightline::ReadPcdFile(path);
  return 0;
}
