// What a ROS bag holds (topics, types, counts, duration, compression) and which of its topics
// make Sightline's frames. ROS-free: the CLI's `info` and the driver registry include it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/common/status.h"
#include "core/io/rosbag_options.h"
#include "core/io/source.h"
#include "core/ros/bag_file.h"

namespace sightline {

// ROS message types the reader knows.
inline constexpr char kRosImageType[] = "sensor_msgs/Image";
inline constexpr char kRosCompressedImageType[] = "sensor_msgs/CompressedImage";
inline constexpr char kRosCameraInfoType[] = "sensor_msgs/CameraInfo";
inline constexpr char kRosPointCloud2Type[] = "sensor_msgs/PointCloud2";
inline constexpr char kRosOdometryType[] = "nav_msgs/Odometry";
inline constexpr char kRosTfType[] = "tf2_msgs/TFMessage";

// One topic of a bag.
struct BagTopic {
  std::string name;  // As recorded ("/camera/rgb/image_color"; may lack the leading '/').
  std::string type;  // "sensor_msgs/Image".
  int64_t messages = 0;
  std::string encoding;  // Image: the first message's encoding; CompressedImage: its format.

  bool IsColorImage() const;  // An Image of a colour/grey encoding, or a CompressedImage.
  bool IsDepthImage() const;  // An Image of encoding 16UC1, mono16 or 32FC1.
};

// A bag's table of contents.
struct BagSummary {
  std::string path;
  std::vector<BagTopic> topics;  // In name order.
  int64_t messages = 0;
  double start_s = 0, end_s = 0;  // Record times of the first and last message.
  BagFileLayout layout;

  // The topic called `name`, with or without the leading '/'; nullptr when none.
  const BagTopic* Find(const std::string& name) const;
  // Topics of type `type`.
  std::vector<const BagTopic*> OfType(const std::string& type) const;
};

// The topics that make a bag's frames, camera and ground truth.
struct BagTopicChoice {
  SourceKind kind = SourceKind::kMono;
  std::string image;               // Colour (RGB-D), left (stereo) or the mono image.
  std::string depth;               // RGB-D.
  std::string camera_info;         // Of `image`.
  std::string right_image;         // Stereo.
  std::string right_camera_info;   // Stereo.
  std::string cloud;               // Point clouds.
  std::string odometry;            // nav_msgs/Odometry, "" when none.
  std::vector<std::string> notes;  // How each topic was chosen.

  // "RGB-D frames from /a (colour) + /b (depth)", "mono images from /a", ...
  std::string Describe() const;
};

// The topics for `options` (kind and topic names; empty ones chosen when the bag leaves no
// doubt). Auto kind: RGB-D (one colour and one depth topic), else stereo (two image topics whose
// names differ only in left/right), else mono (one image topic), else point clouds (one
// PointCloud2 topic). Errors name the bag, the topics found and the options that choose:
// "x.bag: 2 image topics (/a, /b) and no rule picks one: choose with --set
// io.rosbag.image_topic=TOPIC"; a CameraInfo topic that is missing: "x.bag: no CameraInfo for
// /cam/image: looked for /cam/camera_info; ... --set io.rosbag.camera_info_topic=TOPIC".
StatusOr<BagTopicChoice> ChooseBagTopics(const BagSummary& bag, const RosBagOptions& options);

// One choice for each kind of frames the bag can give with `options`' topics (for `info`).
std::vector<BagTopicChoice> PossibleBagChoices(const BagSummary& bag, const RosBagOptions& options);

// Reads the table of contents of the bag at `path` (rosbag's index, and the first message of
// each image topic for its encoding). Errors as ReadBagFileLayout's, or "x.bag: rosbag cannot
// read it: <reason>".
StatusOr<BagSummary> ReadBagSummary(const std::string& path);

// "topics:" lines (name, type, messages), duration and compression, as `info` prints them.
std::string DescribeBagSummaryText(const BagSummary& bag);
// The same as a JSON object: {"duration_s", "messages", "compression", "chunks", "topics":
// [{"name", "type", "messages", "encoding"}]} (`info --json`'s "bag").
std::string DescribeBagSummaryJson(const BagSummary& bag);

}  // namespace sightline
