#include "core/eval/kitti_metrics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>

#include "core/common/text_file.h"

namespace sightline {

namespace {

constexpr double kDegPerRad = 180.0 / std::numbers::pi;

std::string FormatLength(double metres) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.3g m", metres);
  return text;
}

}  // namespace

std::vector<double> KittiSegmentLengthsM() { return {100, 200, 300, 400, 500, 600, 700, 800}; }

StatusOr<std::vector<double>> ParseSegmentLengths(const std::string& text) {
  const std::vector<std::string> fields = SplitFields(text);
  if (fields.size() == 1 && fields[0] == "kitti") return KittiSegmentLengthsM();
  if (fields.empty()) {
    return InvalidArgument("segment lengths are empty (expected e.g. \"5,10,20,40\" or kitti)");
  }
  std::vector<double> lengths;
  for (const std::string& field : fields) {
    char* end = nullptr;
    const double value = std::strtod(field.c_str(), &end);
    if (end == field.c_str() || *end != '\0' || !std::isfinite(value) || !(value > 0)) {
      return InvalidArgument("segment length '" + field + "' in \"" + text +
                             "\" is not a positive number of metres");
    }
    lengths.push_back(value);
  }
  return lengths;
}

StatusOr<KittiErrors> ComputeKittiErrors(const PoseList& estimate, const PoseList& ground_truth,
                                         const std::vector<double>& lengths_m, int step_frames) {
  if (estimate.size() != ground_truth.size()) {
    return InvalidArgument(
        "segment errors need associated poses: " + std::to_string(estimate.size()) +
        " estimated vs " + std::to_string(ground_truth.size()) + " ground-truth poses");
  }
  if (step_frames < 1) return InvalidArgument("segment step must be at least 1 frame");
  if (lengths_m.empty()) return InvalidArgument("no segment lengths given");
  for (double length : lengths_m) {
    if (!(length > 0) || !std::isfinite(length)) {
      return InvalidArgument("segment length " + std::to_string(length) + " is not positive");
    }
  }
  const std::vector<double> d = PathDistances(ground_truth);
  const size_t n = d.size();
  KittiErrors result;
  for (double length : lengths_m) {
    SegmentLengthSummary summary;
    summary.length_m = length;
    size_t last = 0;
    for (size_t first = 0; first < n; first += static_cast<size_t>(step_frames)) {
      // The end frame only moves forward as the first frame does.
      last = std::max(last, first);
      while (last < n && d[last] - d[first] < length) ++last;
      if (last >= n) break;
      const RelativeError e = RelativePoseError(estimate, ground_truth, d, first, last);
      SegmentError segment;
      segment.first_frame = first;
      segment.last_frame = last;
      segment.length_m = length;
      segment.translation_error_pct = 100.0 * e.translation_m / length;
      segment.rotation_error_deg_per_100m = 100.0 * e.rotation_deg / length;
      result.segments.push_back(segment);
      ++summary.segments;
      summary.translation_error_pct += segment.translation_error_pct;
      summary.rotation_error_deg_per_100m += segment.rotation_error_deg_per_100m;
    }
    if (summary.segments == 0) continue;
    summary.translation_error_pct /= static_cast<double>(summary.segments);
    summary.rotation_error_deg_per_100m /= static_cast<double>(summary.segments);
    result.per_length.push_back(summary);
  }
  if (result.segments.empty()) {
    return InvalidArgument("no KITTI segment fits: the ground-truth path is " +
                           FormatLength(d.empty() ? 0.0 : d.back()) +
                           " long and the shortest segment length is " +
                           FormatLength(*std::min_element(lengths_m.begin(), lengths_m.end())));
  }
  for (const SegmentError& s : result.segments) {
    result.translation_error_pct += s.translation_error_pct;
    result.rotation_error_deg_per_100m += s.rotation_error_deg_per_100m;
  }
  result.translation_error_pct /= static_cast<double>(result.segments.size());
  result.rotation_error_deg_per_100m /= static_cast<double>(result.segments.size());
  return result;
}

}  // namespace sightline
