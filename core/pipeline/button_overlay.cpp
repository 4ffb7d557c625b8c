#include "core/pipeline/button_overlay.h"

#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>
#include <system_error>

namespace sightline {

namespace fs = std::filesystem;

bool ButtonOverlayOptions::IsValid(std::string* error) const {
  if (!(video_fps > 0 && video_fps <= 1000)) {
    if (error) *error = "button.overlay.video_fps must be in (0, 1000]";
    return false;
  }
  if (trail < 0) {
    if (error) *error = "button.overlay.trail must be >= 0";
    return false;
  }
  return true;
}

OptionTable<ButtonOverlayOptions> ButtonOverlayOptions::Describe() {
  using O = ButtonOverlayOptions;
  return OptionTable<O>("button.overlay")
      .Bool("png", &O::png,
            "Headless runs write the overlay of the track from the tap on as a PNG sequence "
            "(overlay/frame_NNNNNN.png, one per row of button.csv).")
      .Bool("video", &O::video,
            "With png: also overlay.avi (Motion-JPEG through OpenCV's built-in writer).")
      .Double("video_fps", &O::video_fps, "1/s", 0.1, 1000, 1, "Frame rate of overlay.avi.")
      .Int("trail", &O::trail, "frames", 0, 10000, 1,
           "Track points drawn behind the button on the overlay.");
}

cv::Mat DrawButtonOverlay(const cv::Mat& image, const ButtonTrack& track,
                          const std::deque<cv::Point2d>& trail,
                          const std::vector<std::string>& caption) {
  cv::Mat out;
  if (image.channels() == 1) {
    cv::cvtColor(image, out, cv::COLOR_GRAY2BGR);
  } else if (image.channels() == 4) {
    cv::cvtColor(image, out, cv::COLOR_BGRA2BGR);
  } else {
    out = image.clone();
  }
  const cv::Scalar kTrail(255, 200, 0), kRing(0, 255, 0), kLost(0, 0, 255);
  for (size_t i = 1; i < trail.size(); ++i) {
    cv::line(out, trail[i - 1], trail[i], kTrail, 2, cv::LINE_AA);
  }
  if (track.found) {
    const cv::Point2d c = track.center;
    const int r = std::max(4, static_cast<int>(std::lround(track.radius_px)));
    cv::circle(out, c, r, kRing, 2, cv::LINE_AA);
    cv::drawMarker(out, c, kRing, cv::MARKER_CROSS, 10, 1, cv::LINE_AA);
  }
  const double font = std::max(0.4, out.cols / 1600.0);
  int y = static_cast<int>(22 * font / 0.4 * 0.8);
  for (const std::string& line : caption) {
    const cv::Point at(8, y);
    cv::putText(out, line, at, cv::FONT_HERSHEY_SIMPLEX, font, cv::Scalar(0, 0, 0), 3, cv::LINE_AA);
    cv::putText(out, line, at, cv::FONT_HERSHEY_SIMPLEX, font,
                track.found ? cv::Scalar(255, 255, 255) : kLost, 1, cv::LINE_AA);
    y += static_cast<int>(30 * font / 0.4 * 0.7);
  }
  return out;
}

namespace {

// A new empty folder of this process under the system's temporary folder.
std::string MakeTempDir() {
  static std::atomic<int> counter{0};
  const auto now = std::chrono::steady_clock::now().time_since_epoch().count();
  std::error_code ec;
  for (int attempt = 0; attempt < 100; ++attempt) {
    const fs::path dir = fs::temp_directory_path(ec) / ("sightline-overlay-" + std::to_string(now) +
                                                        "-" + std::to_string(counter.fetch_add(1)));
    if (fs::create_directory(dir, ec)) return dir.string();
  }
  return "";
}

// Moves `from` to `to` (a copy when they lie on different file systems).
Status MoveFile(const fs::path& from, const fs::path& to) {
  std::error_code ec;
  fs::rename(from, to, ec);
  if (!ec) return Status::Ok();
  ec.clear();
  fs::copy_file(from, to, fs::copy_options::overwrite_existing, ec);
  if (ec) return Unavailable("cannot write " + to.string() + ": " + ec.message());
  return Status::Ok();
}

}  // namespace

ButtonOverlayWriter::ButtonOverlayWriter(ButtonOverlayOptions options)
    : options_(options), temp_dir_(MakeTempDir()) {}

ButtonOverlayWriter::~ButtonOverlayWriter() {
  video_.release();
  std::error_code ec;
  if (!temp_dir_.empty()) fs::remove_all(temp_dir_, ec);
}

Status ButtonOverlayWriter::Add(const cv::Mat& image, int64_t frame_id, const ButtonTrack& track,
                                const std::vector<std::string>& caption) {
  if (temp_dir_.empty()) return Unavailable("cannot create a temporary folder for the overlay");
  if (image.empty()) return Status::Ok();
  if (track.found) trail_.push_back(track.center);
  while (static_cast<int>(trail_.size()) > options_.trail) trail_.pop_front();
  char name[64];
  std::snprintf(name, sizeof(name), "frame_%06lld.png", static_cast<long long>(frame_id));
  const std::string path = (fs::path(temp_dir_) / name).string();
  const cv::Mat drawn = DrawButtonOverlay(image, track, trail_, caption);
  if (!cv::imwrite(path, drawn)) return Unavailable("cannot write the overlay frame " + path);
  names_.push_back(name);
  ++frames_;
  if (options_.video) AddToVideo(drawn);
  return Status::Ok();
}

void ButtonOverlayWriter::AddToVideo(const cv::Mat& drawn) {
  if (!video_note_.empty()) return;
  if (!video_.isOpened()) {
    const std::string path = (fs::path(temp_dir_) / "overlay.avi").string();
    video_size_ = drawn.size();
    if (!video_.open(path, cv::CAP_OPENCV_MJPEG, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'),
                     options_.video_fps, video_size_)) {
      video_note_ = "overlay.avi not written: OpenCV's MJPEG writer did not open " + path;
      return;
    }
  }
  cv::Mat frame = drawn;  // BGR (DrawButtonOverlay).
  if (frame.size() != video_size_) cv::resize(frame, frame, video_size_);
  video_.write(frame);
}

Status ButtonOverlayWriter::Finish(const std::string& out_dir, std::vector<std::string>* outputs,
                                   std::vector<std::string>* notes) {
  if (names_.empty()) return Status::Ok();
  const fs::path dir = fs::path(out_dir) / "overlay";
  std::error_code ec;
  fs::remove_all(dir, ec);  // The overlay of an earlier run into the same folder.
  fs::create_directories(dir, ec);
  if (ec) return Unavailable("cannot create " + dir.string() + ": " + ec.message());
  for (const std::string& name : names_) {
    SIGHTLINE_RETURN_IF_ERROR(MoveFile(fs::path(temp_dir_) / name, dir / name));
  }
  outputs->push_back("overlay/");
  if (!options_.video) return Status::Ok();
  if (!video_.isOpened()) {
    notes->push_back(video_note_ + " (the PNG sequence is in overlay/)");
    return Status::Ok();
  }
  video_.release();
  SIGHTLINE_RETURN_IF_ERROR(
      MoveFile(fs::path(temp_dir_) / "overlay.avi", fs::path(out_dir) / "overlay.avi"));
  outputs->push_back("overlay.avi");
  return Status::Ok();
}

}  // namespace sightline
