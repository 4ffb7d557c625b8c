// libFuzzer target: ReadStereoCalibration on any bytes as the stereo calibration file (M1 D1 M2 D2
// R T).
#include "core/io/stereo_calibration_file.h"
#include "tests/fuzz/fuzz_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  (void)sightline::ReadStereoCalibration(sightline::fuzz::WriteInput("stereo.yml", data, size));
  return 0;
}
