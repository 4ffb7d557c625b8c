// Immutable, timestamped sensor payloads. Sources produce them, stages consume them through
// std::shared_ptr<const ...>, so one frame can feed several consumers without copies.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <opencv2/core.hpp>
#include <variant>
#include <vector>

namespace sightline {

// When and in what order a payload was made.
struct FrameStamp {
  int64_t sequence_id = -1;  // Index in the source's stream, from 0.
  double sensor_time_s = 0;  // Sensor (or dataset) timestamp in seconds.
  double host_time_s = 0;    // Host clock (steady, seconds) when the frame was received/read.
};

// A registered colour + depth pair. Depth is in metres, NaN where the sensor gave nothing.
struct RgbdFrame {
  FrameStamp stamp;
  cv::Mat color;    // CV_8UC3, BGR. May be empty for depth-only sources.
  cv::Mat depth_m;  // CV_32FC1 metres, NaN = invalid. Same size as color when both exist.
};

// A stereo pair, rectified or raw as the source's StereoRig says.
struct StereoFrame {
  FrameStamp stamp;
  cv::Mat left;   // CV_8UC1 or CV_8UC3.
  cv::Mat right;  // Same size and type as left.
};

// One image from a single camera.
struct MonoFrame {
  FrameStamp stamp;
  cv::Mat image;  // CV_8UC1 or CV_8UC3 (BGR).
};

// A point cloud with optional colour; organized when width * height == size().
struct PointCloud {
  std::vector<Eigen::Vector3f> points;               // Metres in the sensor frame; NaN = invalid.
  std::vector<Eigen::Matrix<uint8_t, 3, 1>> colors;  // RGB, empty or one per point.
  int width = 0;                                     // Columns when organized, else size().
  int height = 1;                                    // Rows when organized, else 1.

  size_t size() const { return points.size(); }
  bool empty() const { return points.empty(); }
  bool organized() const { return height > 1 && static_cast<size_t>(width) * height == size(); }
  bool has_colors() const { return !colors.empty() && colors.size() == points.size(); }
};

// A point cloud as a stream payload.
struct CloudFrame {
  FrameStamp stamp;
  std::shared_ptr<const PointCloud> cloud;
};

// Any frame a source can produce.
using Frame = std::variant<RgbdFrame, StereoFrame, MonoFrame, CloudFrame>;

// Returns the stamp of any frame.
const FrameStamp& StampOf(const Frame& frame);

}  // namespace sightline
