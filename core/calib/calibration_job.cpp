#include "core/calib/calibration_job.h"

#include <filesystem>

#include "core/calib/calibration_file.h"

namespace sightline {
namespace {

StatusOr<Detections> FromSource(const CalibrationRequest& request, const SourceOpener& open,
                                const DetectionCallbacks& callbacks) {
  if (!open) return NotFound(request.input + ": not an image folder");
  auto source = open(request.input);
  if (!source.ok()) return source.status();
  SourceDetectionOptions options;
  options.max_frames = request.max_frames;
  options.min_change = (*source)->info().live ? 0.05 : 0.0;
  return DetectBoardsInSource(source->get(), request.settings.board, options, callbacks);
}

StatusOr<Detections> Detect(const CalibrationRequest& request, const SourceOpener& open,
                            const DetectionCallbacks& callbacks) {
  const CalibrationSettings& s = request.settings;
  const bool folder = std::filesystem::is_directory(request.input);
  if (request.stereo) {
    if (request.files) return DetectBoardsInPairs(*request.files, s.board, callbacks);
    if (folder) {
      auto files = FindStereoImages(request.input);
      if (files.ok()) return DetectBoardsInPairs(*files, s.board, callbacks);
      if (files.status().code() != StatusCode::kNotFound) return files.status();
    }
    auto detections = FromSource(request, open, callbacks);
    if (detections.ok() && detections->right_views.size() != detections->views.size()) {
      return InvalidArgument(request.input + " is not a stereo source or stereo folder");
    }
    return detections;
  }
  if (folder) {
    auto files = ListCalibrationImages(request.input, request.pattern);
    if (files.ok()) return DetectBoardsInFiles(*files, s.board, callbacks);
    // A pattern that matches nothing is a mistake, not a request to read the whole folder.
    if (request.pattern != "*") return files.status();
  }
  return FromSource(request, open, callbacks);
}

}  // namespace

StatusOr<CalibrationOutcome> RunCalibration(const CalibrationRequest& request,
                                            const SourceOpener& open_source,
                                            const DetectionCallbacks& callbacks) {
  if (const std::string error = request.settings.Check(); !error.empty()) {
    return InvalidArgument(error);
  }
  CalibrationOutcome outcome;
  outcome.request = request;
  auto detections = Detect(request, open_source, callbacks);
  if (!detections.ok()) return detections.status();
  outcome.detections = std::move(*detections);
  const CalibrationSettings& s = request.settings;
  if (request.stereo) {
    auto stereo = CalibrateStereo(outcome.detections.views, outcome.detections.right_views, s.board,
                                  s.mono, s.stereo, s.coverage);
    if (!stereo.ok()) return stereo.status();
    outcome.report = StereoReport(*stereo, outcome.detections);
    outcome.stereo = std::move(*stereo);
  } else {
    auto mono = CalibrateMono(outcome.detections.views, s.board, s.mono, s.coverage);
    if (!mono.ok()) return mono.status();
    outcome.report = MonoReport(*mono, outcome.detections);
    outcome.mono = std::move(*mono);
  }
  return outcome;
}

Status SaveCalibration(const CalibrationOutcome& outcome, const std::string& path) {
  if (outcome.stereo)
    return SaveStereoCalibration(*outcome.stereo, outcome.request.settings.board, path);
  if (outcome.mono) return SaveMonoCalibration(*outcome.mono, outcome.request.settings.board, path);
  return FailedPrecondition("no calibration to save");
}

}  // namespace sightline
