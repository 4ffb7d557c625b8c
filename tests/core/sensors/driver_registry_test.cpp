#include "core/sensors/driver_registry.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iostream>

#include "tests/support/test_data.h"

namespace sightline {
namespace {

TEST(DriverRegistry, ListsEveryDriverWithAvailabilityAndReason) {
  const std::vector<DriverInfo> drivers = BuiltinDrivers();
  ASSERT_EQ(drivers.size(), 5u);
  EXPECT_EQ(drivers[0].name, "openni2");
  EXPECT_EQ(drivers[1].name, "aravis");
  EXPECT_EQ(drivers[2].name, "v4l2");
  EXPECT_EQ(drivers[3].name, "replay");
  EXPECT_EQ(drivers[4].name, "rosbag");
  for (const DriverInfo& d : drivers) {
    EXPECT_FALSE(d.description.empty()) << d.name;
    EXPECT_EQ(d.scheme, d.name + "://");
    ASSERT_TRUE(d.available && d.enumerate && d.declare_options && d.create) << d.name;
    const Status available = d.available();
    if (!available.ok()) {
      EXPECT_EQ(available.code(), StatusCode::kUnavailable) << d.name;
      EXPECT_FALSE(available.message().empty()) << d.name << " gives no reason";
    }
    std::cout << d.name << ": " << (available.ok() ? "available" : available.message()) << "\n";
  }
#ifdef SIGHTLINE_HAVE_ARAVIS
  EXPECT_TRUE(FindDriver(drivers, "aravis")->available().ok());
#else
  EXPECT_NE(FindDriver(drivers, "aravis")->available().message().find("not built"),
            std::string::npos);
#endif
#ifdef SIGHTLINE_HAVE_ROS
  EXPECT_TRUE(FindDriver(drivers, "rosbag")->available().ok());
#else
  EXPECT_NE(FindDriver(drivers, "rosbag")->available().message().find("not built"),
            std::string::npos);
#endif
#ifndef SIGHTLINE_HAVE_OPENNI2
  EXPECT_NE(FindDriver(drivers, "openni2")->available().message().find("not built"),
            std::string::npos);
#endif
  EXPECT_EQ(FindDriver(drivers, "kinect"), nullptr);
}

TEST(DriverRegistry, V4l2AvailabilityFollowsDeviceNodes) {
  bool any_node = false;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator("/dev", ec)) {
    any_node = any_node || e.path().filename().string().rfind("video", 0) == 0;
  }
  const Status available = FindDriver(BuiltinDrivers(), "v4l2")->available();
  EXPECT_EQ(available.ok(), any_node) << available.message();
  if (!any_node) {
    EXPECT_NE(available.message().find("/dev/video"), std::string::npos) << available.message();
    EXPECT_TRUE(FindDriver(BuiltinDrivers(), "v4l2")->enumerate(OptionSet()).empty());
  }
}

TEST(DriverRegistry, SensorUris) {
  EXPECT_TRUE(IsSensorUri("openni2://"));
  EXPECT_TRUE(IsSensorUri("aravis://Fake_1"));
  EXPECT_TRUE(IsSensorUri("v4l2://0"));
  EXPECT_TRUE(IsSensorUri("/data/room.ONI"));
  EXPECT_TRUE(IsSensorUri("/data/walk.bag"));
  EXPECT_TRUE(IsSensorUri("rosbag:///data/walk.bag"));
  EXPECT_FALSE(IsSensorUri("../shared/data/tum_fr1_desk"));
}

TEST(DriverRegistry, OpenSourceRejectsUnknownSchemesClearly) {
  StatusOr<std::unique_ptr<Source>> source = OpenSource("kinect://0");
  ASSERT_FALSE(source.ok());
  EXPECT_EQ(source.status().code(), StatusCode::kInvalidArgument);
  EXPECT_NE(source.status().message().find("kinect://"), std::string::npos);
  EXPECT_NE(source.status().message().find("aravis://"), std::string::npos);
}

TEST(DriverRegistry, OpenSourceChecksOptionsBeforeTouchingDevices) {
  OptionSet options;
  ASSERT_TRUE(DeclareSensorOptions(&options).ok());
  ASSERT_TRUE(options.ApplyOverride("sensors.aravis.trigger=software").ok());
  StatusOr<std::unique_ptr<Source>> source = OpenSource("aravis://Fake_1", options);
  ASSERT_FALSE(source.ok());
#ifdef SIGHTLINE_HAVE_ARAVIS
  EXPECT_EQ(source.status().code(), StatusCode::kInvalidArgument);
  EXPECT_NE(source.status().message().find("frame_rate_hz"), std::string::npos);
  StatusOr<std::unique_ptr<Source>> three = OpenSource("aravis://a,b,c");
  ASSERT_FALSE(three.ok());
  EXPECT_NE(three.status().message().find("LEFT_ID,RIGHT_ID"), std::string::npos);
  // URI options: only calibration_file, only on a pair.
  StatusOr<std::unique_ptr<Source>> unknown = OpenSource("aravis://a,b?fps=3");
  ASSERT_FALSE(unknown.ok());
  EXPECT_EQ(unknown.status().code(), StatusCode::kInvalidArgument);
  EXPECT_NE(unknown.status().message().find("calibration_file=FILE"), std::string::npos);
  StatusOr<std::unique_ptr<Source>> mono = OpenSource("aravis://a?calibration_file=rig.yaml");
  ASSERT_FALSE(mono.ok());
  EXPECT_NE(mono.status().message().find("only a stereo pair"), std::string::npos);
#endif
}

TEST(DriverRegistry, OpenSourceFallsBackToDatasets) {
  SIGHTLINE_REQUIRE_DATA(path, "tum_fr1_desk");
  StatusOr<std::unique_ptr<Source>> source = OpenSource(path);
  ASSERT_TRUE(source.ok()) << source.status().ToString();
  EXPECT_EQ((*source)->info().kind, SourceKind::kRgbd);
  EXPECT_FALSE((*source)->info().live);
}

TEST(DriverRegistry, MissingRecordingNamesTheFile) {
  StatusOr<std::unique_ptr<Source>> source = OpenSource("/nonexistent/room.oni");
  ASSERT_FALSE(source.ok());
#ifdef SIGHTLINE_HAVE_OPENNI2
  EXPECT_EQ(source.status().code(), StatusCode::kNotFound);
  EXPECT_NE(source.status().message().find("/nonexistent/room.oni"), std::string::npos)
      << source.status().message();
#else
  EXPECT_NE(source.status().message().find("not built"), std::string::npos);
#endif
}

// A broken .oni said only "could not be opened:" (OpenNI2's own words); each now says why.
TEST(DriverRegistry, ABrokenOniSaysWhatIsWrongWithIt) {
  const std::string dir = testing::TempDir("broken_oni");
  struct Case {
    std::string path;
    StatusCode code;
    std::string says;
  };
  std::filesystem::create_directories(dir + "/folder.oni");
  std::ofstream(dir + "/short.oni") << "NI10";
  std::ofstream(dir + "/text.oni") << std::string(64, 'x');
  std::filesystem::create_symlink("/dev/zero", dir + "/device.oni");
  for (const Case& c : {
           Case{dir + "/missing.oni", StatusCode::kNotFound, "missing.oni: no such file"},
           Case{dir + "/folder.oni", StatusCode::kInvalidArgument, "folder.oni is a folder"},
           Case{dir + "/device.oni", StatusCode::kInvalidArgument,
                "device.oni is not a regular file"},
           Case{dir + "/short.oni", StatusCode::kParseError,
                "short.oni is too short for an ONI recording (4 bytes"},
           Case{dir + "/text.oni", StatusCode::kParseError, "text.oni is not an ONI recording"},
       }) {
    const StatusOr<std::unique_ptr<Source>> source = OpenSource(c.path);
    ASSERT_FALSE(source.ok()) << c.path;
    EXPECT_EQ(source.status().code(), c.code) << source.status().ToString();
    EXPECT_NE(source.status().message().find(c.says), std::string::npos)
        << source.status().ToString();
  }
  const std::string real = testing::DataPath("oni_livingroom/test.oni");
  if (!real.empty()) EXPECT_TRUE(CheckOniFile(real).ok()) << CheckOniFile(real).ToString();
}

}  // namespace
}  // namespace sightline
