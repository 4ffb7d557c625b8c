// The map of the monocular SLAM: map points (the product's "PTAM point cloud") and keyframes.
// Not thread-safe by itself: MonoSlam guards it with one mutex shared by tracking and mapping.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <map>
#include <memory>
#include <opencv2/core.hpp>
#include <unordered_map>
#include <vector>

namespace sightline {

// Undistorted keypoints with ORB descriptors of one image.
struct FrameFeatures {
  std::vector<cv::KeyPoint> keypoints;  // Pixel positions as detected (octave = pyramid level).
  std::vector<Eigen::Vector2d> pixels;  // Undistorted positions [px].
  cv::Mat descriptors;                  // One 32-byte ORB row per keypoint.
  int width = 0, height = 0;
  int cell_px = 32;
  int grid_columns = 0, grid_rows = 0;
  std::vector<std::vector<int>> grid;  // Keypoint indices per cell, row-major.

  size_t size() const { return keypoints.size(); }
  // Keypoints within `radius` px of (u, v).
  std::vector<int> InWindow(double u, double v, double radius) const;
  // The same into *out (cleared first), so loops reuse one buffer.
  void InWindow(double u, double v, double radius, std::vector<int>* out) const;
};

// One 3D point of the map.
struct MapPoint {
  int64_t id = -1;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // x_in_map [map units].
  cv::Mat descriptor;                                  // 1x32 CV_8U, from the creating view.
  int64_t first_keyframe = -1;                         // Keyframe that created it.
  std::map<int64_t, int> observations;                 // Keyframe id -> keypoint index.
  int visible = 0;                                     // Frames in whose image it was predicted ...
  int found = 0;                                       // ... and those in which tracking found it.
};

// One keyframe: its pose, its features and which keypoints observe which map points.
struct KeyFrame {
  int64_t id = -1;
  int64_t frame_index = -1;  // Sequence id of the source frame.
  double time_s = 0;
  Eigen::Isometry3d camera_from_map = Eigen::Isometry3d::Identity();
  FrameFeatures features;
  std::vector<int64_t> point_ids;  // Per keypoint: the map point it observes, or -1.
  int corrections_seen = 0;        // Revisit corrections applied to the map it was tracked on.

  Eigen::Vector3d CentreInMap() const { return camera_from_map.inverse().translation(); }
};

// Points and keyframes by id.
class SlamMap {
 public:
  int64_t AddPoint(MapPoint point);                         // Assigns the id.
  int64_t AddKeyFrame(std::shared_ptr<KeyFrame> keyframe);  // Assigns the id.
  // Records that keypoint `index` of `keyframe` sees `point` (both must exist).
  void AddObservation(int64_t point, int64_t keyframe, int index);
  // Removes a point and every keyframe's reference to it.
  void RemovePoint(int64_t point);
  // Removes one observation; the point goes when fewer than 2 remain.
  void RemoveObservation(int64_t point, int64_t keyframe);
  void Clear();

  MapPoint* FindPoint(int64_t id);
  const MapPoint* FindPoint(int64_t id) const;
  KeyFrame* FindKeyFrame(int64_t id);
  const std::unordered_map<int64_t, MapPoint>& points() const { return points_; }
  std::unordered_map<int64_t, MapPoint>& points() { return points_; }
  const std::vector<std::shared_ptr<KeyFrame>>& keyframes() const { return keyframes_; }

 private:
  std::unordered_map<int64_t, MapPoint> points_;
  std::vector<std::shared_ptr<KeyFrame>> keyframes_;  // In insertion (id) order.
  int64_t next_point_id_ = 0;
  int64_t next_keyframe_id_ = 0;
};

// An immutable copy of the map for views and output files.
struct MapSnapshot {
  struct Point {
    int64_t id;
    Eigen::Vector3d position;
    int64_t first_keyframe;
    int observations;
  };
  struct Frame {
    int64_t id;
    int64_t frame_index;
    double time_s;
    Eigen::Isometry3d map_from_camera;
    int points;  // Map points it observes.
  };
  std::vector<Point> points;
  std::vector<Frame> keyframes;
};

// Copies the map (call with the map's lock held).
std::shared_ptr<const MapSnapshot> SnapshotOf(const SlamMap& map);

}  // namespace sightline
