#include "core/ros/bag_messages.h"

#include <sensor_msgs/CompressedImage.h>
#include <sensor_msgs/Image.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>

#include "core/ros/message_check.h"

namespace sightline {
namespace {

// The encoding (Image) or format (CompressedImage) of a topic's first message.
std::string FirstEncoding(const rosbag::Bag& bag, const BagTopic& topic) {
  rosbag::View view(bag, rosbag::TopicQuery(topic.name));
  for (const rosbag::MessageInstance& m : view) {
    if (topic.type == kRosImageType) {
      if (auto image = InstantiateChecked<sensor_msgs::Image>(m)) return image->encoding;
    } else if (auto compressed = InstantiateChecked<sensor_msgs::CompressedImage>(m)) {
      return compressed->format;
    }
    break;
  }
  return "";
}

bool FiniteQuaternion(const geometry_msgs::Quaternion& q) {
  return std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z) && std::isfinite(q.w);
}

StatusOr<Eigen::Isometry3d> MakeIsometry(double x, double y, double z,
                                         const geometry_msgs::Quaternion& q) {
  if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z) || !FiniteQuaternion(q)) {
    return InvalidArgument("pose has a value that is not finite");
  }
  Eigen::Quaterniond rotation(q.w, q.x, q.y, q.z);
  if (rotation.norm() < 0.5) {
    return InvalidArgument("quaternion (" + std::to_string(q.x) + ", " + std::to_string(q.y) +
                           ", " + std::to_string(q.z) + ", " + std::to_string(q.w) +
                           ") is not a rotation");
  }
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = rotation.normalized().toRotationMatrix();
  pose.translation() = Eigen::Vector3d(x, y, z);
  return pose;
}

const sensor_msgs::PointField* FindField(const sensor_msgs::PointCloud2& msg,
                                         const std::string& name) {
  for (const sensor_msgs::PointField& f : msg.fields) {
    if (f.name == name) return &f;
  }
  return nullptr;
}

// Checks the byte layout of a cloud message: steps against the data size.
Status CheckCloudLayout(const sensor_msgs::PointCloud2& msg) {
  if (msg.is_bigendian) return InvalidArgument("big-endian PointCloud2 data is not read");
  if (msg.point_step == 0 && msg.width * msg.height > 0) {
    return ParseError("PointCloud2 point_step is 0");
  }
  if (static_cast<uint64_t>(msg.point_step) * msg.width > msg.row_step) {
    return ParseError("PointCloud2 row_step " + std::to_string(msg.row_step) + " is shorter than " +
                      std::to_string(msg.width) + " points of " + std::to_string(msg.point_step) +
                      " bytes");
  }
  const uint64_t needed = static_cast<uint64_t>(msg.row_step) * msg.height;
  if (msg.data.size() < needed) {
    return ParseError("PointCloud2 data holds " + std::to_string(msg.data.size()) +
                      " bytes, height " + std::to_string(msg.height) + " x row_step " +
                      std::to_string(msg.row_step) + " needs " + std::to_string(needed));
  }
  return Status::Ok();
}

}  // namespace

StatusOr<std::unique_ptr<rosbag::Bag>> OpenBagForReading(const std::string& path,
                                                         BagFileLayout* layout) {
  StatusOr<BagFileLayout> read = ReadBagFileLayout(path);
  if (!read.ok()) return read.status();
  if (layout != nullptr) *layout = *read;
  auto bag = std::make_unique<rosbag::Bag>();
  try {
    bag->open(path, rosbag::bagmode::Read);
  } catch (const std::exception& e) {
    return ParseError(path + ": rosbag cannot read it: " + e.what());
  } catch (...) {
    return ParseError(path + ": rosbag cannot read it (unknown error)");
  }
  return bag;
}

StatusOr<BagSummary> SummarizeBag(const rosbag::Bag& bag, const std::string& path,
                                  const BagFileLayout& layout) {
  BagSummary summary;
  summary.path = path;
  summary.layout = layout;
  try {
    rosbag::View all(bag);
    std::map<std::string, BagTopic> topics;
    for (const rosbag::ConnectionInfo* c : all.getConnections()) {
      BagTopic& t = topics[c->topic];
      t.name = c->topic;
      t.type = c->datatype == "tf/tfMessage" ? kRosTfType : c->datatype;
    }
    for (auto& [name, topic] : topics) {
      topic.messages = rosbag::View(bag, rosbag::TopicQuery(name)).size();
      summary.messages += topic.messages;
      if (topic.type == kRosImageType || topic.type == kRosCompressedImageType) {
        topic.encoding = FirstEncoding(bag, topic);
      }
      summary.topics.push_back(topic);
    }
    if (summary.messages > 0) {
      summary.start_s = all.getBeginTime().toSec();
      summary.end_s = all.getEndTime().toSec();
    }
  } catch (const std::exception& e) {
    return ParseError(path + ": rosbag cannot read its index: " + e.what());
  }
  return summary;
}

double MessageStampS(const rosbag::MessageInstance& message) {
  boost::shared_ptr<RosStampOnly> stamp = message.instantiate<RosStampOnly>();
  if (stamp && !stamp->stamp.isZero()) return stamp->stamp.toSec();
  return message.getTime().toSec();
}

StatusOr<PointCloud> CloudFromRos(const sensor_msgs::PointCloud2& msg) {
  SIGHTLINE_RETURN_IF_ERROR(CheckCloudLayout(msg));
  uint32_t offsets[3];
  const char* names[3] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) {
    const sensor_msgs::PointField* f = FindField(msg, names[i]);
    if (f == nullptr) return InvalidArgument(std::string("PointCloud2 has no field ") + names[i]);
    if (f->datatype != sensor_msgs::PointField::FLOAT32 || f->offset + 4 > msg.point_step) {
      return InvalidArgument(std::string("PointCloud2 field ") + names[i] + " has datatype " +
                             std::to_string(f->datatype) + "; only float32 (7) x, y, z are read");
    }
    offsets[i] = f->offset;
  }
  const sensor_msgs::PointField* rgb = FindField(msg, "rgb");
  if (rgb == nullptr) rgb = FindField(msg, "rgba");
  const bool colored = rgb != nullptr && rgb->offset + 4 <= msg.point_step &&
                       (rgb->datatype == sensor_msgs::PointField::FLOAT32 ||
                        rgb->datatype == sensor_msgs::PointField::UINT32);
  PointCloud cloud;
  const size_t count = static_cast<size_t>(msg.width) * msg.height;
  cloud.points.reserve(count);
  if (colored) cloud.colors.reserve(count);
  for (uint32_t r = 0; r < msg.height; ++r) {
    const uint8_t* row = msg.data.data() + static_cast<size_t>(r) * msg.row_step;
    for (uint32_t c = 0; c < msg.width; ++c) {
      const uint8_t* p = row + static_cast<size_t>(c) * msg.point_step;
      float xyz[3];
      for (int i = 0; i < 3; ++i) std::memcpy(&xyz[i], p + offsets[i], 4);
      cloud.points.emplace_back(xyz[0], xyz[1], xyz[2]);
      if (colored)
        cloud.colors.emplace_back(p[rgb->offset + 2], p[rgb->offset + 1], p[rgb->offset]);
    }
  }
  cloud.width = static_cast<int>(msg.height > 1 ? msg.width : count);
  cloud.height = static_cast<int>(msg.height > 1 ? msg.height : 1);
  return cloud;
}

StatusOr<Eigen::Isometry3d> IsometryFromRos(const geometry_msgs::Vector3& t,
                                            const geometry_msgs::Quaternion& q) {
  return MakeIsometry(t.x, t.y, t.z, q);
}

StatusOr<Eigen::Isometry3d> IsometryFromRos(const geometry_msgs::Point& t,
                                            const geometry_msgs::Quaternion& q) {
  return MakeIsometry(t.x, t.y, t.z, q);
}

}  // namespace sightline
