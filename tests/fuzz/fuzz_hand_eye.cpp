// libFuzzer target: ReadHandEyeFile on any bytes as hand_eye.yaml (the camera's mount on the arm).
#include "core/io/hand_eye_file.h"
#include "tests/fuzz/fuzz_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  (void)sightline::ReadHandEyeFile(sightline::fuzz::WriteInput("hand_eye.yaml", data, size));
  return 0;
}
