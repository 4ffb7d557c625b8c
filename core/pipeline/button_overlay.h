// The overlay of a button run: each frame from the tap on with the tracked button ringed, its
// recent track, the state and (without a metric scale) the words "tracking only". Written as a
// PNG sequence (overlay/frame_NNNNNN.png, one per row of button.csv) and, when OpenCV's own
// MJPEG writer opens, as overlay.avi. Options "button.overlay.*".
#pragma once

#include <cstdint>
#include <deque>
#include <opencv2/core.hpp>
#include <opencv2/videoio.hpp>
#include <string>
#include <vector>

#include "core/button/button_types.h"
#include "core/common/status.h"
#include "core/options/option_table.h"

namespace sightline {

struct ButtonOverlayOptions {
  bool png = true;        // Write the PNG sequence (headless runs).
  bool video = true;      // Also overlay.avi (Motion-JPEG, OpenCV's built-in writer).
  double video_fps = 10;  // Frames per second of overlay.avi [1/s].
  int trail = 30;         // Track points drawn behind the button [frames].

  bool IsValid(std::string* error) const;
  static OptionTable<ButtonOverlayOptions> Describe();
};

// One frame of the overlay: `image` (grey or BGR) with the track and the caption lines drawn.
cv::Mat DrawButtonOverlay(const cv::Mat& image, const ButtonTrack& track,
                          const std::deque<cv::Point2d>& trail,
                          const std::vector<std::string>& caption);

// Writes the overlay frames (and the video, frame by frame) into a private temporary folder while
// the run goes on (the output folder is known only at the end) and moves them into place on
// Finish, which therefore takes no longer after a long live run than after a short one. Not
// thread-safe.
class ButtonOverlayWriter {
 public:
  explicit ButtonOverlayWriter(ButtonOverlayOptions options);
  ~ButtonOverlayWriter();  // Removes the temporary folder when Finish did not run.
  ButtonOverlayWriter(const ButtonOverlayWriter&) = delete;
  ButtonOverlayWriter& operator=(const ButtonOverlayWriter&) = delete;

  // Draws and stores one frame. Unavailable naming the file when it cannot be written.
  Status Add(const cv::Mat& image, int64_t frame_id, const ButtonTrack& track,
             const std::vector<std::string>& caption);
  int64_t frames() const { return frames_; }
  // Moves the PNGs to out_dir/overlay/ and the video to out_dir/overlay.avi; `outputs` gets the
  // names written, `notes` says why the video is missing when it is.
  Status Finish(const std::string& out_dir, std::vector<std::string>* outputs,
                std::vector<std::string>* notes);

 private:
  // Appends `drawn` to the video in the temporary folder, opening it on the first frame.
  void AddToVideo(const cv::Mat& drawn);

  ButtonOverlayOptions options_;
  std::string temp_dir_;
  std::vector<std::string> names_;  // PNG file names, in order.
  std::deque<cv::Point2d> trail_;
  int64_t frames_ = 0;
  cv::VideoWriter video_;
  cv::Size video_size_;
  std::string video_note_;  // Why there is no video (the writer did not open).
};

}  // namespace sightline
