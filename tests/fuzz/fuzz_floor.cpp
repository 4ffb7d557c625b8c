// libFuzzer target: ReadFloorCalibration on any bytes as the floor file (floor plane and
// tolerance).
#include "core/io/floor_file.h"
#include "tests/fuzz/fuzz_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  (void)sightline::ReadFloorCalibration(sightline::fuzz::WriteInput("floor.yaml", data, size));
  return 0;
}
