// Finding the board in calibration inputs: image files (a folder, a name pattern, a stereo
// folder with left/right images) and frame sources (recordings and live cameras), with progress,
// cancellation and clear errors for inputs without boards.
#pragma once

#include <atomic>
#include <functional>
#include <string>
#include <vector>

#include "core/calib/chessboard.h"
#include "core/common/status.h"
#include "core/io/source.h"

namespace sightline {

// Hooks of a long detection run (the GUI's worker thread).
struct DetectionCallbacks {
  std::function<void(int done, int total)> progress;  // After every image or pair.
  const std::atomic<bool>* cancel = nullptr;          // Checked between images.
};

// Boards found in a set of images.
struct Detections {
  std::vector<BoardView> views;            // Mono: one per image with a board.
  std::vector<BoardView> right_views;      // Stereo: right[i] pairs with views[i].
  std::vector<std::string> without_board;  // Images (or pairs) where the board was not found.
  int inputs = 0;                          // Images or pairs examined.
};

// Image files (full paths) in `dir` whose names match `pattern` (shell wildcards, e.g.
// "left*.jpg"), in natural order. NotFound for a missing folder or no matching image.
StatusOr<std::vector<std::string>> ListCalibrationImages(const std::string& dir,
                                                         const std::string& pattern = "*");

// Left and right image files of a stereo set, paired by position.
struct StereoImageFiles {
  std::vector<std::string> left, right;
};

// The pairs of a stereo folder: sub-folders left/ and right/ (or image_0/ and image_1/, cam0/
// and cam1/), else files named left*/right* paired by the rest of the name (left01.jpg with
// right01.jpg). NotFound when neither is there; InvalidArgument for unpaired files.
StatusOr<StereoImageFiles> FindStereoImages(const std::string& dir);

// Pairs two lists by position. InvalidArgument naming both counts when they differ.
StatusOr<StereoImageFiles> PairImageLists(std::vector<std::string> left,
                                          std::vector<std::string> right);

// Detects the board in every file. InvalidArgument when no image shows a board of this size
// (the message suggests checking the board size), or when image sizes differ; the decoder's
// error for unreadable files; Cancelled when stopped.
StatusOr<Detections> DetectBoardsInFiles(const std::vector<std::string>& files,
                                         const ChessboardOptions& board,
                                         const DetectionCallbacks& callbacks = {});

// Detects the board in both images of every pair; keeps pairs where both show it.
StatusOr<Detections> DetectBoardsInPairs(const StereoImageFiles& files,
                                         const ChessboardOptions& board,
                                         const DetectionCallbacks& callbacks = {});

// How to take views from a frame source.
struct SourceDetectionOptions {
  int max_frames = 2000;  // Frames to examine at most.
  int max_views = 40;     // Stop after this many accepted views.
  // Live cameras: accept a view only when its corners moved on average by this fraction of the
  // image diagonal against every accepted view (shift, distance or tilt changed; 0 = all).
  double min_change = 0.0;
};

// Detects the board in a source's frames (mono, or the pairs of a stereo source; RGB-D: colour).
StatusOr<Detections> DetectBoardsInSource(Source* source, const ChessboardOptions& board,
                                          const SourceDetectionOptions& options,
                                          const DetectionCallbacks& callbacks = {});

// True when the corners of `view` moved on average by at least `min_change` of the image
// diagonal against every view in `accepted`.
bool IsNewView(const BoardView& view, const std::vector<BoardView>& accepted, double min_change);

}  // namespace sightline
