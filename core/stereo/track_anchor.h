// Drift-free track positions for the stereo odometry. Frame-to-frame KLT adds a small error at
// every frame, so a track's position wanders off its surface point like a random walk (on the
// simulator's corridor 0.32 px after one frame, 0.81 px after ten), and so do the poses that the
// sliding window ties to it. Here each track keeps an anchor: the left image position and depth
// where it was first seen (or last re-anchored). Every later position is refined by aligning the
// anchor's patch, warped by the predicted motion from the anchor's frame as the plane its
// neighbouring tracks show (or, without enough of them, as facing the camera at the anchor's
// depth), to the current image, starting from the KLT result.
// Positions then stay tied to the anchor's observation; they start over from a new anchor only
// when the anchor is max_frames old, the patch would be scaled too much or seen from too far
// aside, or the alignment fails.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <deque>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/options/option_table.h"
#include "core/stereo/stereo_geometry.h"

namespace sightline {

// Keys "stereo.anchor.*".
struct TrackAnchorOptions {
  bool enabled = true;
  int patch_px = 9;                // Side of the aligned patch [px] (odd).
  int max_frames = 10;             // An anchor is used for at most this many frames.
  double max_scale_change = 0.25;  // A patch scaled more than this (1 +- s) gets a new anchor.
  double max_correction_px = 1.0;  // An alignment moving the KLT position further failed.
  double min_zncc = 0.8;           // An aligned patch correlating less with its anchor failed.
  int max_iterations = 8;          // Gauss-Newton iterations of the alignment.
  // Seen from a direction this far from the anchor's, a wrongly fitted or assumed surface
  // misleads the warp: re-anchor. 2-3 deg suits subsampled driving (the road seen 5 m further
  // on); the corridor's walls need their anchors longer.
  double max_view_change_deg = 30;
  // The patch's surface is fitted to the tracks within this radius at a similar depth (at least
  // normal_min_points of them), so a slanted surface (the road, a wall) is warped as what it is;
  // 0 = every patch is taken as facing the camera.
  double normal_radius_px = 40;
  int normal_min_points = 6;

  bool IsValid(std::string* error) const;
  static OptionTable<TrackAnchorOptions> Describe();
};

// Where a track was anchored: a frame's number, its left position and disparity there.
struct TrackAnchor {
  int64_t frame = -1;  // -1 = none.
  cv::Point2f left;
  float disparity_px = 0;
  // The surface's normal there, in the anchor camera's frame, when the neighbouring tracks
  // showed a plane; zero = unknown (the patch is then taken as facing the camera).
  Eigen::Vector3f normal = Eigen::Vector3f::Zero();
};

// Surface normals at the tracks `which` from the neighbouring tracks' 3D points (`points`, in
// the camera frame, at image positions `pixels`): a plane fitted to the points within
// options.normal_radius_px at a similar depth, when enough of them lie on one; zero otherwise.
std::vector<Eigen::Vector3f> SurfaceNormals(const std::vector<Eigen::Vector3d>& points,
                                            const std::vector<cv::Point2f>& pixels,
                                            const std::vector<size_t>& which,
                                            const TrackAnchorOptions& options);

enum class AnchorAlignment {
  kAligned,    // The position was refined against the anchor.
  kUnchanged,  // The anchor is the previous frame (KLT already measured against it) or absent.
  kRenew,      // Not aligned (anchor too old, too much scale, alignment failed): re-anchor.
};

// The recent left images and poses anchors refer to, and the alignment.
class TrackAnchors {
 public:
  explicit TrackAnchors(TrackAnchorOptions options = {}) : options_(options) {}
  const TrackAnchorOptions& options() const { return options_; }

  // Keeps a copy of frame `frame`'s rectified left image (CV_8UC1) and its pose; frames
  // that no anchor may refer to any more are dropped.
  void AddFrame(int64_t frame, const cv::Mat& left, const Eigen::Isometry3d& world_from_camera);
  void Reset() { frames_.clear(); }

  // Refines `*position`, tracked into `current` (frame `frame`, predicted pose
  // `world_from_current`), against `anchor`. The position is changed only when kAligned.
  AnchorAlignment Align(const RectifiedStereoCamera& camera, const TrackAnchor& anchor,
                        int64_t frame, const cv::Mat& current,
                        const Eigen::Isometry3d& world_from_current, cv::Point2f* position) const;

  // Whether an anchor set at `anchor_frame` may still be used at frame `next_frame`.
  bool Usable(int64_t anchor_frame, int64_t next_frame) const {
    return anchor_frame >= 0 && next_frame - anchor_frame <= options_.max_frames;
  }

 private:
  struct Frame {
    int64_t frame;
    cv::Mat left;
    Eigen::Isometry3d world_from_camera;
  };
  const Frame* Find(int64_t frame) const;

  TrackAnchorOptions options_;
  std::deque<Frame> frames_;
};

}  // namespace sightline
