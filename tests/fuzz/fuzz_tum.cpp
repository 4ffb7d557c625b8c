// libFuzzer target: the TUM RGB-D index files. The first byte picks the file: rgb.txt/depth.txt
// (ReadTimedFileList), groundtruth.txt (ReadTumTrajectory) or associations.txt (read by
// TumRgbdSource::Open, in a folder with no images).
#include "core/common/trajectory.h"
#include "core/io/timed_file_list.h"
#include "core/io/tum_rgbd_source.h"
#include "tests/fuzz/fuzz_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  const uint8_t which = data[0] % 3;
  ++data;
  --size;
  if (which == 0) {
    (void)sightline::ReadTimedFileList(sightline::fuzz::WriteInput("rgb.txt", data, size));
  } else if (which == 1) {
    (void)sightline::ReadTumTrajectory(sightline::fuzz::WriteInput("groundtruth.txt", data, size));
  } else {
    const std::string path = sightline::fuzz::WriteInput("tum/associations.txt", data, size);
    sightline::TumRgbdSource source(path.substr(0, path.rfind('/')));
    (void)source.Open();
  }
  return 0;
}
