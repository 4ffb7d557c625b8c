#include "core/sensors/v4l2_source.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "core/sensors/driver_registry.h"

namespace sightline {
namespace {

// No webcam is attached on the build machines: the tests check that absence is reported
// clearly, naming the device, instead of hanging or crashing.

TEST(V4l2Source, AbsentDeviceIsUnavailableAndNamed) {
  const std::string node = "/dev/video57";
  if (std::filesystem::exists(node)) GTEST_SKIP() << node << " exists here";
  V4l2Source source(node, V4l2Options());
  const Status opened = source.Open();
  ASSERT_FALSE(opened.ok());
  EXPECT_EQ(opened.code(), StatusCode::kUnavailable);
  EXPECT_NE(opened.message().find("/dev/video57"), std::string::npos) << opened.message();
  EXPECT_FALSE(source.is_open());
  EXPECT_EQ(source.stats().state, SensorState::kClosed);
  EXPECT_EQ(source.Grab().code(), StatusCode::kFailedPrecondition);
}

TEST(V4l2Source, IndexUrisThroughTheRegistry) {
  EXPECT_EQ(V4l2Source::DevicePath("3"), "/dev/video3");
  EXPECT_EQ(V4l2Source::DevicePath("/dev/video3"), "/dev/video3");
  if (std::filesystem::exists("/dev/video9")) GTEST_SKIP() << "/dev/video9 exists here";
  StatusOr<std::unique_ptr<Source>> source = OpenSource("v4l2://9");
  ASSERT_FALSE(source.ok());
  EXPECT_EQ(source.status().code(), StatusCode::kUnavailable);
  EXPECT_NE(source.status().message().find("V4L2 device /dev/video9"), std::string::npos)
      << source.status().message();
}

TEST(V4l2Source, InvalidOptionsAreRefusedBeforeOpening) {
  V4l2Options options;
  options.fourcc = "H";
  V4l2Source source("0", options);
  const Status opened = source.Open();
  ASSERT_FALSE(opened.ok());
  EXPECT_EQ(opened.code(), StatusCode::kInvalidArgument);
  EXPECT_NE(opened.message().find("fourcc"), std::string::npos);
}

}  // namespace
}  // namespace sightline
