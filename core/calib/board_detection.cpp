#include "core/calib/board_detection.h"

#include <fnmatch.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <opencv2/imgproc.hpp>
#include <variant>

#include "core/io/file_listing.h"
#include "core/io/image_loading.h"

namespace sightline {
namespace {

std::string Join(const std::string& dir, const std::string& name) {
  return (std::filesystem::path(dir) / name).string();
}

Status CheckCancel(const DetectionCallbacks& callbacks) {
  if (callbacks.cancel && callbacks.cancel->load()) return Cancelled("detection stopped");
  return Status::Ok();
}

Status NoBoardError(const ChessboardOptions& board, int inputs, const std::string& first,
                    const char* what) {
  return InvalidArgument("no " + board.SizeText() + " chessboard found in any of " +
                         std::to_string(inputs) + " " + what + " (first: " + first +
                         "); check the board size (inner corners, COLUMNSxROWS)");
}

// Loads `file` and finds the board; *found tells whether it was there.
Status DetectInFile(const std::string& file, const ChessboardOptions& board, BoardView* view,
                    bool* found) {
  StatusOr<cv::Mat> image = LoadImage8(file);
  if (!image.ok()) return image.status();
  view->name = BaseName(file);
  view->path = file;
  view->image_size = image->size();
  *found = FindChessboard(*image, board, &view->corners);
  return Status::Ok();
}

Status CheckSize(const BoardView& view, const std::vector<BoardView>& views) {
  if (views.empty() || view.image_size == views[0].image_size) return Status::Ok();
  return InvalidArgument("image '" + view.name + "' is " + std::to_string(view.image_size.width) +
                         "x" + std::to_string(view.image_size.height) + " but '" + views[0].name +
                         "' is " + std::to_string(views[0].image_size.width) + "x" +
                         std::to_string(views[0].image_size.height) +
                         "; calibrate one camera at one resolution");
}

}  // namespace

StatusOr<std::vector<std::string>> ListCalibrationImages(const std::string& dir,
                                                         const std::string& pattern) {
  auto names = ListFiles(dir, ImageExtensions());
  if (!names.ok()) return names.status();
  std::vector<std::string> files;
  for (const std::string& name : *names) {
    if (fnmatch(pattern.c_str(), name.c_str(), 0) == 0) files.push_back(Join(dir, name));
  }
  if (files.empty()) {
    return NotFound("no image in " + dir + " matches '" + pattern + "' (.png, .jpg)");
  }
  return files;
}

StatusOr<StereoImageFiles> PairImageLists(std::vector<std::string> left,
                                          std::vector<std::string> right) {
  if (left.size() != right.size()) {
    return InvalidArgument(std::to_string(left.size()) + " left images but " +
                           std::to_string(right.size()) +
                           " right images; stereo calibration needs them in pairs");
  }
  StereoImageFiles files;
  files.left = std::move(left);
  files.right = std::move(right);
  return files;
}

StatusOr<StereoImageFiles> FindStereoImages(const std::string& dir) {
  if (!std::filesystem::is_directory(dir)) return NotFound(dir + " is not a folder");
  for (const auto& [l, r] :
       {std::pair{"left", "right"}, std::pair{"image_0", "image_1"}, std::pair{"cam0", "cam1"}}) {
    const std::string ld = Join(dir, l), rd = Join(dir, r);
    if (std::filesystem::is_directory(ld) && std::filesystem::is_directory(rd)) {
      auto left = ListCalibrationImages(ld);
      if (!left.ok()) return left.status();
      auto right = ListCalibrationImages(rd);
      if (!right.ok()) return right.status();
      return PairImageLists(std::move(*left), std::move(*right));
    }
  }
  auto names = ListFiles(dir, ImageExtensions());
  if (!names.ok()) return names.status();
  std::map<std::string, std::string> left_by_key, right_by_key;
  for (const std::string& name : *names) {
    if (name.rfind("left", 0) == 0) left_by_key[name.substr(4)] = Join(dir, name);
    if (name.rfind("right", 0) == 0) right_by_key[name.substr(5)] = Join(dir, name);
  }
  if (left_by_key.empty() && right_by_key.empty()) {
    return NotFound(dir +
                    " holds no stereo images: expected left/ and right/ (or image_0/ and "
                    "image_1/, cam0/ and cam1/) folders, or files named left*/right*");
  }
  StereoImageFiles files;
  std::vector<std::string> keys;
  for (const auto& [key, path] : left_by_key) {
    auto it = right_by_key.find(key);
    if (it == right_by_key.end()) {
      return InvalidArgument(dir + ": left" + key + " has no partner right" + key);
    }
    keys.push_back(key);
  }
  for (const auto& [key, path] : right_by_key) {
    if (left_by_key.count(key) == 0) {
      return InvalidArgument(dir + ": right" + key + " has no partner left" + key);
    }
  }
  std::sort(keys.begin(), keys.end(), NaturalLess);
  for (const std::string& key : keys) {
    files.left.push_back(left_by_key[key]);
    files.right.push_back(right_by_key[key]);
  }
  return files;
}

StatusOr<Detections> DetectBoardsInFiles(const std::vector<std::string>& files,
                                         const ChessboardOptions& board,
                                         const DetectionCallbacks& callbacks) {
  std::string error;
  if (!board.IsValid(&error)) return InvalidArgument(error);
  if (files.empty()) return InvalidArgument("no images to calibrate from");
  Detections result;
  for (const std::string& file : files) {
    SIGHTLINE_RETURN_IF_ERROR(CheckCancel(callbacks));
    BoardView view;
    bool found = false;
    SIGHTLINE_RETURN_IF_ERROR(DetectInFile(file, board, &view, &found));
    ++result.inputs;
    if (found) {
      SIGHTLINE_RETURN_IF_ERROR(CheckSize(view, result.views));
      result.views.push_back(std::move(view));
    } else {
      result.without_board.push_back(view.name);
    }
    if (callbacks.progress) callbacks.progress(result.inputs, static_cast<int>(files.size()));
  }
  if (result.views.empty()) return NoBoardError(board, result.inputs, BaseName(files[0]), "images");
  return result;
}

StatusOr<Detections> DetectBoardsInPairs(const StereoImageFiles& files,
                                         const ChessboardOptions& board,
                                         const DetectionCallbacks& callbacks) {
  std::string error;
  if (!board.IsValid(&error)) return InvalidArgument(error);
  auto paired = PairImageLists(files.left, files.right);
  if (!paired.ok()) return paired.status();
  if (files.left.empty()) return InvalidArgument("no stereo pairs to calibrate from");
  Detections result;
  for (size_t i = 0; i < files.left.size(); ++i) {
    SIGHTLINE_RETURN_IF_ERROR(CheckCancel(callbacks));
    BoardView left, right;
    bool found_left = false, found_right = false;
    SIGHTLINE_RETURN_IF_ERROR(DetectInFile(files.left[i], board, &left, &found_left));
    SIGHTLINE_RETURN_IF_ERROR(DetectInFile(files.right[i], board, &right, &found_right));
    ++result.inputs;
    if (found_left && found_right) {
      SIGHTLINE_RETURN_IF_ERROR(CheckSize(left, result.views));
      SIGHTLINE_RETURN_IF_ERROR(CheckSize(right, result.right_views));
      result.views.push_back(std::move(left));
      result.right_views.push_back(std::move(right));
    } else {
      result.without_board.push_back(left.name + " | " + right.name);
    }
    if (callbacks.progress) callbacks.progress(result.inputs, static_cast<int>(files.left.size()));
  }
  if (result.views.empty()) {
    return NoBoardError(board, result.inputs, BaseName(files.left[0]),
                        "stereo pairs (both images)");
  }
  return result;
}

bool IsNewView(const BoardView& view, const std::vector<BoardView>& accepted, double min_change) {
  if (min_change <= 0) return true;
  const double diagonal = std::hypot(view.image_size.width, view.image_size.height);
  for (const BoardView& other : accepted) {
    if (other.corners.size() != view.corners.size() || view.corners.empty()) continue;
    // Mean corner displacement: grows with a shift, a change of size and a change of tilt.
    double sum = 0;
    for (size_t i = 0; i < view.corners.size(); ++i) {
      sum += cv::norm(view.corners[i] - other.corners[i]);
    }
    if (sum / view.corners.size() / diagonal < min_change) return false;
  }
  return true;
}

StatusOr<Detections> DetectBoardsInSource(Source* source, const ChessboardOptions& board,
                                          const SourceDetectionOptions& options,
                                          const DetectionCallbacks& callbacks) {
  std::string error;
  if (!board.IsValid(&error)) return InvalidArgument(error);
  const SourceInfo& info = source->info();
  const bool stereo = info.kind == SourceKind::kStereo;
  Detections result;
  const int total = info.frame_count > 0
                        ? static_cast<int>(std::min<int64_t>(info.frame_count, options.max_frames))
                        : options.max_frames;
  while (result.inputs < options.max_frames &&
         static_cast<int>(result.views.size()) < options.max_views) {
    SIGHTLINE_RETURN_IF_ERROR(CheckCancel(callbacks));
    Status grabbed = source->Grab();
    if (grabbed.code() == StatusCode::kOutOfRange) break;
    SIGHTLINE_RETURN_IF_ERROR(grabbed);
    StatusOr<Frame> frame = source->Retrieve();
    if (!frame.ok()) return frame.status();
    const std::string label = "frame " + std::to_string(StampOf(*frame).sequence_id);
    cv::Mat first, second;
    if (const auto* s = std::get_if<StereoFrame>(&*frame)) {
      first = s->left;
      second = s->right;
    } else if (const auto* m = std::get_if<MonoFrame>(&*frame)) {
      first = m->image;
    } else if (const auto* r = std::get_if<RgbdFrame>(&*frame)) {
      first = r->color;
    } else {
      return InvalidArgument(info.path +
                             ": point clouds cannot be used for chessboard calibration");
    }
    ++result.inputs;
    const double t = StampOf(*frame).sensor_time_s;
    BoardView left{label, first.size(), {}, t, {}}, right{label, second.size(), {}, t, {}};
    const bool found = FindChessboard(first, board, &left.corners) &&
                       (!stereo || FindChessboard(second, board, &right.corners));
    if (found && IsNewView(left, result.views, options.min_change)) {
      result.views.push_back(std::move(left));
      if (stereo) result.right_views.push_back(std::move(right));
    } else if (!found) {
      result.without_board.push_back(label);
    }
    if (callbacks.progress) callbacks.progress(result.inputs, total);
  }
  if (result.views.empty()) {
    return NoBoardError(board, result.inputs, info.path, "frames");
  }
  return result;
}

}  // namespace sightline
