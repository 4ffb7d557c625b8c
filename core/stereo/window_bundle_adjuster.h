// Sliding-window bundle adjustment of the stereo odometry: the last few frames' poses and the
// points their tracks see are refined together on the stereo reprojection error (left u, v and
// right u of every observation), with the oldest frame of the window held fixed. A track seen in
// several frames ties their poses to one 3D point, so the per-frame motion errors of
// frame-to-frame estimation do not simply add up. Frames that left the window keep observing as
// fixed frames for a while (as the fixed keyframes of a local bundle adjustment do).
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <deque>
#include <string>
#include <vector>

#include "core/options/option_table.h"
#include "core/stereo/stereo_geometry.h"

namespace sightline {

// Keys "stereo.window.*".
struct WindowBundleOptions {
  bool enabled = true;  // Refine each accepted pose in the window.
  int frames = 6;       // Frames in the window (the oldest is held fixed).
  // Frames that left the window stay this long as fixed observers: their poses are not changed,
  // but their observations still constrain the points, so the window's poses stay tied to
  // where the older frames saw the same tracks and its drift does not restart at every slide.
  int fixed_frames = 6;
  // A frame stays in the window when the camera moved at least min_parallax of its points'
  // median depth, or turned min_rotation_deg, since the previous frame that stayed; otherwise the
  // next frame replaces it. So slow motion keeps enough parallax between window frames.
  double min_parallax = 0.05;
  double min_rotation_deg = 2.0;
  int max_iterations = 4;         // Levenberg-Marquardt iterations per frame.
  double huber_px = 0.5;          // Huber threshold of the robust weight [px].
  double max_error_px = 2.0;      // Observations reprojecting worse after refinement are dropped.
  double min_disparity_px = 0.5;  // Observations with less disparity (no depth) are not used.
  bool center_weighting =
      false;  // Weight by 1 / (|u - cx| / cx + 0.05) (see MotionRefinerOptions).

  bool IsValid(std::string* error) const;
  static OptionTable<WindowBundleOptions> Describe();
};

// One stereo observation of a track in a rectified frame.
struct TrackObservation {
  int64_t track_id = -1;
  float left_u = 0, v = 0, right_u = 0;
};

// What one adjustment did.
struct WindowBundleSummary {
  int frames = 0;             // Frames in the window.
  int fixed_frames = 0;       // Older frames observing with fixed poses (options.fixed_frames).
  int points = 0;             // Tracks seen in at least two of them (the adjusted points).
  int observations = 0;       // Their observations.
  int dropped = 0;            // Observations dropped as outliers.
  int iterations = 0;         // Iterations run.
  double initial_rms_px = 0;  // RMS reprojection error before ...
  double final_rms_px = 0;    // ... and after.
  bool adjusted = false;      // False when the window held too little to adjust.
};

// The window. Add() each accepted frame with its pose estimate and observations; it returns the
// refined pose of that frame. Reset() after a frame whose motion could not be measured.
class WindowBundleAdjuster {
 public:
  explicit WindowBundleAdjuster(WindowBundleOptions options = {}) : options_(options) {}

  // Appends the frame (dropping the oldest beyond options.frames), adjusts the window and returns
  // the refined world_from_camera of the appended frame (its input when nothing could be adjusted).
  // `disparity_offset_px` is added to every observation's disparity in the window (the rig's
  // estimated offset, see disparity_offset.h), so all frames are adjusted with the current one.
  Eigen::Isometry3d Add(const RectifiedStereoCamera& camera,
                        const Eigen::Isometry3d& world_from_camera,
                        std::vector<TrackObservation> observations,
                        WindowBundleSummary* summary = nullptr, double disparity_offset_px = 0);
  void Reset() { frames_.clear(); }
  size_t size() const { return frames_.size(); }

 private:
  struct Frame {
    Eigen::Isometry3d camera_from_world;
    std::vector<TrackObservation> observations;
    std::vector<unsigned char> usable;  // Per observation: not (yet) dropped as an outlier.
    bool keep = true;  // Stays when the next frame arrives (else the next frame replaces it).
  };

  // Appends the frame with its usable observations (replacing the last frame when it did not
  // move enough) and drops the frames beyond the window and its fixed observers.
  void AppendFrame(const Eigen::Isometry3d& world_from_camera,
                   std::vector<TrackObservation> observations);
  // Whether `to` moved enough from `from` to stay in the window (see WindowBundleOptions).
  bool EnoughMotion(const RectifiedStereoCamera& camera, const Frame& from, const Frame& to) const;

  WindowBundleOptions options_;
  std::deque<Frame> frames_;
};

}  // namespace sightline
