// libFuzzer target: any bytes as a ROS bag file, opened by BagSource (its record-layout check,
// then Debian's rosbag) and read for up to eight frames.
#include "core/ros/bag_file.h"
#include "core/ros/bag_source.h"
#include "tests/fuzz/fuzz_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = sightline::fuzz::WriteInput("input.bag", data, size);
  (void)sightline::ReadBagFileLayout(path);
  sightline::BagSource source(path);
  if (!source.Open().ok()) return 0;
  for (int i = 0; i < 8 && source.Grab().ok(); ++i) (void)source.Retrieve();
  return 0;
}
