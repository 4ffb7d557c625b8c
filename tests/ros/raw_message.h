// A message whose serialized bytes the test writes by hand, announced as the type M (its
// md5sum, name and definition): for bags and publishers that lie about an array's length.
// ROS headers: included by the C++17 test sources only.
#pragma once

#include <ros/message_traits.h>
#include <ros/serialization.h>
#include <sensor_msgs/CameraInfo.h>

#include <cstdint>
#include <cstring>
#include <vector>

namespace sightline::testing {

template <class M>
struct RawMessage {
  std::vector<uint8_t> bytes;
};

// The bytes of `message` as roscpp serializes it.
template <class M>
std::vector<uint8_t> SerializedBytes(const M& message) {
  std::vector<uint8_t> bytes(ros::serialization::serializationLength(message));
  ros::serialization::OStream out(bytes.data(), static_cast<uint32_t>(bytes.size()));
  ros::serialization::serialize(out, message);
  return bytes;
}

// Overwrites the little-endian uint32 at `offset` (an array's element count, say).
inline void PutUint32(std::vector<uint8_t>* bytes, size_t offset, uint32_t value) {
  for (int i = 0; i < 4; ++i) (*bytes)[offset + static_cast<size_t>(i)] = (value >> (8 * i)) & 0xff;
}

// `info` with its distortion D claiming 0xfffffff0 doubles (34 GB) in a message of a few hundred
// bytes.
inline RawMessage<sensor_msgs::CameraInfo> LyingCameraInfo(const sensor_msgs::CameraInfo& info) {
  RawMessage<sensor_msgs::CameraInfo> raw;
  raw.bytes = SerializedBytes(info);
  // header (seq, stamp, frame_id), height, width, distortion_model, then D's element count.
  const size_t d_count =
      4 + 8 + 4 + info.header.frame_id.size() + 4 + 4 + 4 + info.distortion_model.size();
  PutUint32(&raw.bytes, d_count, 0xfffffff0u);
  return raw;
}

}  // namespace sightline::testing

namespace ros {
namespace message_traits {
template <class M>
struct MD5Sum<sightline::testing::RawMessage<M>> {
  static const char* value() { return MD5Sum<M>::value(); }
  static const char* value(const sightline::testing::RawMessage<M>&) { return value(); }
};
template <class M>
struct DataType<sightline::testing::RawMessage<M>> {
  static const char* value() { return DataType<M>::value(); }
  static const char* value(const sightline::testing::RawMessage<M>&) { return value(); }
};
template <class M>
struct Definition<sightline::testing::RawMessage<M>> {
  static const char* value() { return Definition<M>::value(); }
  static const char* value(const sightline::testing::RawMessage<M>&) { return value(); }
};
}  // namespace message_traits
namespace serialization {
template <class M>
struct Serializer<sightline::testing::RawMessage<M>> {
  template <typename Stream>
  inline static void write(Stream& stream, const sightline::testing::RawMessage<M>& m) {
    if (!m.bytes.empty())
      std::memcpy(stream.advance(m.bytes.size()), m.bytes.data(), m.bytes.size());
  }
  inline static uint32_t serializedLength(const sightline::testing::RawMessage<M>& m) {
    return static_cast<uint32_t>(m.bytes.size());
  }
};
}  // namespace serialization
}  // namespace ros
