// CheckSerializedMessage: real messages pass; a count or length that does not fit in the bytes
// that follow is refused before anything is allocated, naming the field.
#include "core/ros/message_check.h"

#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/PointCloud2.h>
#include <tf2_msgs/TFMessage.h>

#include "tests/ros/raw_message.h"

namespace sightline {
namespace {

template <class M>
Status Check(const std::vector<uint8_t>& bytes) {
  return CheckSerializedMessage(ros::message_traits::DataType<M>::value(),
                                ros::message_traits::Definition<M>::value(), bytes.data(),
                                bytes.size());
}

sensor_msgs::PointCloud2 Cloud() {
  sensor_msgs::PointCloud2 cloud;
  cloud.header.frame_id = "camera";
  cloud.height = 1;
  cloud.width = 2;
  for (const char* name : {"x", "y", "z"}) {
    sensor_msgs::PointField f;
    f.name = name;
    f.offset = static_cast<uint32_t>(4 * cloud.fields.size());
    f.datatype = sensor_msgs::PointField::FLOAT32;
    f.count = 1;
    cloud.fields.push_back(f);
  }
  cloud.point_step = 12;
  cloud.row_step = 24;
  cloud.data.assign(24, 7);
  return cloud;
}

TEST(MessageCheck, RealMessagesPass) {
  sensor_msgs::CameraInfo info;
  info.header.frame_id = "camera";
  info.distortion_model = "plumb_bob";
  info.D = {0.1, -0.2, 0, 0, 0};
  EXPECT_TRUE(Check<sensor_msgs::CameraInfo>(testing::SerializedBytes(info)).ok());
  sensor_msgs::Image image;
  image.encoding = "mono8";
  image.data.assign(640 * 480, 3);
  EXPECT_TRUE(Check<sensor_msgs::Image>(testing::SerializedBytes(image)).ok());
  EXPECT_TRUE(Check<sensor_msgs::PointCloud2>(testing::SerializedBytes(Cloud())).ok());
  tf2_msgs::TFMessage tf;
  tf.transforms.resize(3);
  tf.transforms[2].child_frame_id = "base_link";
  EXPECT_TRUE(Check<tf2_msgs::TFMessage>(testing::SerializedBytes(tf)).ok());
  EXPECT_TRUE(Check<nav_msgs::Odometry>(testing::SerializedBytes(nav_msgs::Odometry())).ok());
}

TEST(MessageCheck, ALyingArrayCountIsNamedWithWhatItClaims) {
  sensor_msgs::CameraInfo info;
  info.header.frame_id = "camera";
  info.distortion_model = "plumb_bob";
  info.D = {0.1, -0.2, 0, 0, 0};
  const Status lie = Check<sensor_msgs::CameraInfo>(testing::LyingCameraInfo(info).bytes);
  ASSERT_FALSE(lie.ok());
  EXPECT_EQ(lie.code(), StatusCode::kInvalidArgument);
  EXPECT_NE(lie.message().find("sensor_msgs/CameraInfo: field D declares 4294967280 float64 "
                               "values (34359738240 bytes) but the message has"),
            std::string::npos)
      << lie.ToString();
}

TEST(MessageCheck, NestedCountsAndStringsAreCheckedToo) {
  std::vector<uint8_t> bytes = testing::SerializedBytes(Cloud());
  // header: seq, stamp, frame_id "camera"; height, width; then the count of `fields`.
  const size_t fields_count = 4 + 8 + 4 + 6 + 4 + 4;
  std::vector<uint8_t> many = bytes;
  testing::PutUint32(&many, fields_count, 100000000u);
  const Status count = Check<sensor_msgs::PointCloud2>(many);
  ASSERT_FALSE(count.ok());
  EXPECT_NE(count.message().find("field fields declares 100000000 elements"), std::string::npos)
      << count.ToString();
  // fields[1].name ("y"): after the count and fields[0] (name "x", offset, datatype, count).
  const size_t name_1 = fields_count + 4 + (4 + 1 + 4 + 1 + 4);
  std::vector<uint8_t> long_name = bytes;
  testing::PutUint32(&long_name, name_1, 0x7fffffffu);
  const Status name = Check<sensor_msgs::PointCloud2>(long_name);
  ASSERT_FALSE(name.ok());
  EXPECT_NE(name.message().find("field fields[1].name needs 2147483647 bytes"), std::string::npos)
      << name.ToString();
}

TEST(MessageCheck, ATruncatedMessageIsRefused) {
  std::vector<uint8_t> bytes = testing::SerializedBytes(Cloud());
  bytes.resize(bytes.size() - 5);  // The end of `data`, then is_dense.
  const Status cut = Check<sensor_msgs::PointCloud2>(bytes);
  ASSERT_FALSE(cut.ok());
  EXPECT_NE(cut.message().find("field data declares 24 uint8 values"), std::string::npos)
      << cut.ToString();
  EXPECT_FALSE(Check<sensor_msgs::PointCloud2>({}).ok());
}

TEST(MessageCheck, ADefinitionThatNamesAnUndefinedTypeIsNamed) {
  const std::vector<uint8_t> bytes(16, 0);
  const Status s = CheckSerializedMessage("pkg/A", "uint32 n\nOther thing\n", bytes.data(), 16);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("does not define pkg/Other (field thing)"), std::string::npos)
      << s.ToString();
  const Status bad = CheckSerializedMessage("pkg/A", "uint8[x9] n\n", bytes.data(), 16);
  EXPECT_NE(bad.message().find("array size \"x9\""), std::string::npos) << bad.ToString();
}

}  // namespace
}  // namespace sightline
