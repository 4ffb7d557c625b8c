#include <gtest/gtest.h>

#include <set>
#include <string>

#include "core/options/option_set.h"
#include "core/sensors/aravis_options.h"
#include "core/sensors/driver_registry.h"
#include "core/sensors/openni2_options.h"
#include "core/sensors/sensor_stats.h"
#include "core/sensors/v4l2_source.h"

namespace sightline {
namespace {

TEST(SensorOptions, EveryDriverDeclaresItsKeysWithValidDefaults) {
  OptionSet options;
  ASSERT_TRUE(DeclareSensorOptions(&options).ok());
  for (const char* key :
       {"sensors.aravis.exposure_us", "sensors.aravis.gain_db", "sensors.aravis.frame_rate_hz",
        "sensors.aravis.pixel_format", "sensors.aravis.socket_buffer_bytes",
        "sensors.aravis.trigger", "sensors.aravis.queue_capacity",
        "sensors.aravis.stereo.pair_tolerance_ms", "sensors.openni2.registration",
        "sensors.openni2.mirror", "sensors.openni2.loop", "sensors.openni2.stall_timeout_ms",
        "sensors.v4l2.width", "sensors.v4l2.latest_only"}) {
    EXPECT_TRUE(options.Has(key)) << key;
  }
  for (const OptionSpec& spec : options.specs()) {
    EXPECT_FALSE(spec.description.empty()) << spec.key;
  }
  std::string error;
  EXPECT_TRUE(AravisOptions().IsValid(&error)) << error;
  EXPECT_TRUE(AravisStereoOptions().IsValid(&error)) << error;
  EXPECT_TRUE(OpenNi2Options().IsValid(&error)) << error;
  EXPECT_TRUE(V4l2Options().IsValid(&error)) << error;
}

TEST(SensorOptions, OverridesReachTheTypedStructs) {
  OptionSet options;
  ASSERT_TRUE(DeclareSensorOptions(&options).ok());
  ASSERT_TRUE(options.ApplyOverride("sensors.aravis.exposure_us=5000").ok());
  ASSERT_TRUE(options.ApplyOverride("sensors.aravis.queue_capacity=5").ok());
  ASSERT_TRUE(options.ApplyOverride("sensors.openni2.loop=true").ok());
  const AravisOptions aravis = options.Extract(AravisOptions::Describe());
  EXPECT_DOUBLE_EQ(aravis.exposure_us, 5000);
  EXPECT_EQ(aravis.live.queue_capacity, 5);
  EXPECT_TRUE(options.Extract(OpenNi2Options::Describe()).loop);
  EXPECT_FALSE(options.ApplyOverride("sensors.aravis.trigger=sometimes").ok());
  EXPECT_FALSE(options.ApplyOverride("sensors.aravis.exposre_us=5").ok()) << "misspelt key";
}

TEST(SensorOptions, InconsistentSettingsAreNamed) {
  std::string error;
  AravisOptions software;
  software.trigger = "software";
  EXPECT_FALSE(software.IsValid(&error));
  EXPECT_NE(error.find("frame_rate_hz"), std::string::npos) << error;
  OpenNi2Options half_size;
  half_size.width = 640;
  EXPECT_FALSE(half_size.IsValid(&error));
  EXPECT_NE(error.find("width and height"), std::string::npos) << error;
  V4l2Options fourcc;
  fourcc.fourcc = "MJPEG";
  EXPECT_FALSE(fourcc.IsValid(&error));
  LiveSourceOptions live;
  live.queue_capacity = 0;
  EXPECT_FALSE(live.IsValid(&error));
}

TEST(SensorStats, NamedValuesForPlots) {
  SensorStats stats;
  stats.state = SensorState::kStreaming;
  stats.frames_dropped = 3;
  stats.last_latency_ms = 12.5;
  std::set<std::string> keys;
  for (const auto& [key, value] : SensorStatValues(stats)) {
    keys.insert(key);
    if (key == "sensors/frames_dropped") EXPECT_EQ(value, 3);
    if (key == "sensors/latency_ms") EXPECT_EQ(value, 12.5);
    if (key == "sensors/streaming") EXPECT_EQ(value, 1);
  }
  EXPECT_TRUE(keys.count("sensors/incomplete_frames"));
  EXPECT_TRUE(keys.count("sensors/reconnects"));
  EXPECT_STREQ(SensorStateName(SensorState::kDisconnected), "disconnected");
}

}  // namespace
}  // namespace sightline
