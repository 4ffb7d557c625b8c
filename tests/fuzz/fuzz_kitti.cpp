// libFuzzer target: the KITTI index files. The first byte picks the file: times.txt
// (ReadTimesFile), poses.txt (ReadKittiTrajectory) or calib.txt (read by KittiSource::Open in a
// folder with one 8x6 stereo pair).
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "core/common/trajectory.h"
#include "core/io/kitti_source.h"
#include "core/io/timed_file_list.h"
#include "tests/fuzz/fuzz_file.h"

namespace {

// A KITTI folder with one tiny stereo pair; calib.txt is the fuzzer's.
std::string KittiFolder() {
  static const std::string folder = [] {
    const std::string dir = sightline::fuzz::ScratchDir() + "/kitti";
    const cv::Mat grey(6, 8, CV_8UC1, cv::Scalar(100));
    std::filesystem::create_directories(dir + "/image_0");
    std::filesystem::create_directories(dir + "/image_1");
    cv::imwrite(dir + "/image_0/000000.png", grey);
    cv::imwrite(dir + "/image_1/000000.png", grey);
    return dir;
  }();
  return folder;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  const uint8_t which = data[0] % 3;
  ++data;
  --size;
  if (which == 0) {
    (void)sightline::ReadTimesFile(sightline::fuzz::WriteInput("times.txt", data, size));
  } else if (which == 1) {
    (void)sightline::ReadKittiTrajectory(sightline::fuzz::WriteInput("poses.txt", data, size), {},
                                         0.1);
  } else {
    const std::string folder = KittiFolder();
    sightline::fuzz::WriteInput("kitti/calib.txt", data, size);
    sightline::KittiSource source(folder);
    (void)source.Open();
  }
  return 0;
}
