// libFuzzer target: ReadCameraYaml on any bytes as camera.yaml (intrinsics, distortion, depth
// scale).
#include "core/io/camera_yaml.h"
#include "tests/fuzz/fuzz_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  (void)sightline::ReadCameraYaml(sightline::fuzz::WriteInput("camera.yaml", data, size));
  return 0;
}
