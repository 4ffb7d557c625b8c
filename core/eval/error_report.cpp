#include "core/eval/error_report.h"

#include <cstdarg>
#include <cstdio>
#include <map>

#include "core/common/json_writer.h"

namespace sightline {

namespace {

// Unit and meaning of each accuracy key, for the table.
struct FigureInfo {
  const char* unit;
  const char* meaning;
};

const std::map<std::string, FigureInfo>& FigureInfos() {
  static const std::map<std::string, FigureInfo> infos = {
      {"ate_rmse_m", {"m", "absolute trajectory error, RMSE"}},
      {"ate_mean_m", {"m", "absolute trajectory error, mean"}},
      {"ate_median_m", {"m", "absolute trajectory error, median"}},
      {"ate_max_m", {"m", "absolute trajectory error, maximum"}},
      {"rpe_trans_pct", {"%", "relative translation error per distance travelled"}},
      {"rpe_rot_deg_per_m", {"deg/m", "relative rotation error per distance travelled"}},
      {"rpe_trans_m", {"m", "relative translation error, RMSE"}},
      {"rpe_rot_deg", {"deg", "relative rotation error, RMSE"}},
      {"length_error_pct", {"%", "|estimated - true path length| / true length"}},
      {"endpoint_error_pct", {"%", "final position error / true path length"}},
      {"kitti_t_err_pct", {"%", "KITTI segment translation error"}},
      {"kitti_r_err_deg_per_100m", {"deg/100m", "KITTI segment rotation error"}},
      {"scale", {"", "Sim(3) scale applied to the estimate"}},
      {"pairs", {"", "associated poses"}},
  };
  return infos;
}

std::string Printf(const char* format, ...) __attribute__((format(printf, 1, 2)));

std::string Printf(const char* format, ...) {
  char text[512];
  va_list args;
  va_start(args, format);
  std::vsnprintf(text, sizeof(text), format, args);
  va_end(args);
  return text;
}

std::string PairDescription(const TrajectoryErrors& errors) {
  std::string rpe_pairs = Printf("RPE pairs %d frame%s apart", errors.rpe_delta_frames,
                                 errors.rpe_delta_frames == 1 ? "" : "s");
  if (errors.rpe_delta_m > 0) rpe_pairs += Printf(", %% and deg/m over %g m", errors.rpe_delta_m);
  return rpe_pairs;
}

}  // namespace

AccuracyFigureInfo DescribeAccuracyFigure(const std::string& key) {
  const auto it = FigureInfos().find(key);
  if (it == FigureInfos().end()) return {};
  return {it->second.unit, it->second.meaning};
}

std::string FormatErrorTable(const TrajectoryErrors& errors) {
  std::string out;
  out += Printf("%zu associated poses (%zu estimated and %zu ground-truth poses unmatched)\n",
                errors.pairs, errors.unmatched_estimate, errors.unmatched_ground_truth);
  out += Printf("alignment %s", AlignmentModeName(errors.alignment));
  if (errors.alignment == AlignmentMode::kSim3) {
    out += Printf(" (scale %.6g applied to the estimate)", errors.ground_truth_from_estimate.scale);
  }
  out += Printf("; path length: ground truth %.3f m, estimate %.3f m; %s\n",
                errors.ground_truth_length_m, errors.estimate_length_m,
                PairDescription(errors).c_str());
  out += "\n";
  out += Printf("%-26s %12s  %-9s %s\n", "figure", "value", "unit", "meaning");
  for (const auto& [key, value] : AccuracyFigures(errors)) {
    const auto it = FigureInfos().find(key);
    const FigureInfo info = it != FigureInfos().end() ? it->second : FigureInfo{"", ""};
    const std::string number = key == "pairs" ? Printf("%.0f", value) : Printf("%.6f", value);
    out += Printf("%-26s %12s  %-9s %s\n", key.c_str(), number.c_str(), info.unit, info.meaning);
  }
  if (errors.kitti) {
    out += "\nKITTI segment errors by length\n";
    out +=
        Printf("%10s %10s %12s %18s\n", "length_m", "segments", "t_err_pct", "r_err_deg_per_100m");
    for (const SegmentLengthSummary& s : errors.kitti->per_length) {
      out += Printf("%10g %10zu %12.4f %18.4f\n", s.length_m, s.segments, s.translation_error_pct,
                    s.rotation_error_deg_per_100m);
    }
  }
  for (const std::string& note : errors.notes) out += "note: " + note + "\n";
  return out;
}

std::string AccuracyToJson(const std::vector<std::pair<std::string, double>>& figures,
                           bool pretty) {
  JsonWriter writer(pretty);
  writer.BeginObject();
  for (const auto& [key, value] : figures) {
    writer.Key(key).Double(value);  // As metrics.json writes it; integers print as integers.
  }
  writer.EndObject();
  return writer.str();
}

}  // namespace sightline
