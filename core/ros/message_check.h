// Checks a serialized ROS 1 message against its definition before it is deserialized.
//
// roscpp's deserializer sizes an array from the 4-byte count in front of it before it reads the
// elements, so a message of a few hundred bytes that claims 4e9 doubles makes it allocate 32 GB
// before it notices the bytes are missing. CheckSerializedMessage() walks the bytes with the
// message's definition (the text every generated type and every bag connection carries) and
// refuses any count or length that does not fit in what follows, naming the field.
// Only core/ros's .cpp files include this header (it pulls ROS headers).
#pragma once

#include <ros/message_traits.h>
#include <ros/serialization.h>
#include <rosbag/message_instance.h>

#include <boost/shared_ptr.hpp>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/common/status.h"

namespace sightline {

// OK when every variable-length field of the serialized message `data` (of type `type`, whose
// full definition with its nested "MSG:" sections is `definition`) fits in `size` bytes.
// InvalidArgument naming the field path ("D", "fields[2].name"), the count and the bytes left
// otherwise; also for a definition that names a type it does not define.
Status CheckSerializedMessage(const std::string& type, const std::string& definition,
                              const uint8_t* data, size_t size);

// The largest message the bag reader accepts (rosbag would copy it whole before decoding).
constexpr uint32_t kMaxRosMessageBytes = 1u << 30;

// rosbag's MessageInstance::instantiate<T>() after CheckSerializedMessage(): null when the
// message is not a T (as instantiate), std::invalid_argument naming the topic, the type and the
// field when its bytes do not hold what it declares. Callers already turn rosbag's exceptions
// into errors that name the bag and the message.
template <class T>
boost::shared_ptr<T> InstantiateChecked(const rosbag::MessageInstance& m) {
  if (!m.isType<T>()) return nullptr;
  const uint32_t size = m.size();
  if (size > kMaxRosMessageBytes) {
    throw std::invalid_argument(m.getTopic() + ": a " + m.getDataType() + " of " +
                                std::to_string(size) + " bytes (more than " +
                                std::to_string(kMaxRosMessageBytes) + " bytes)");
  }
  std::vector<uint8_t> bytes(size);
  ros::serialization::OStream out(bytes.data(), size);
  m.write(out);
  Status ok = CheckSerializedMessage(ros::message_traits::DataType<T>::value(),
                                     ros::message_traits::Definition<T>::value(), bytes.data(),
                                     bytes.size());
  if (!ok.ok()) throw std::invalid_argument(m.getTopic() + ": " + ok.message());
  boost::shared_ptr<T> message(new T());
  ros::serialization::IStream in(bytes.data(), size);
  ros::serialization::deserialize(in, *message);
  return message;
}

}  // namespace sightline
