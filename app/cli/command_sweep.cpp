// `sightline-cli sweep stereo-vo PATH --subsample 1..10 [--out DIR]`: the stereo seed's Table 1
// (path-length error per subsampling factor) on any dataset with ground truth, as a table and a
// PNG plot of length error against the factor.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>

#include "app/cli/cli_args.h"
#include "app/cli/commands.h"
#include "core/eval/plot_canvas.h"
#include "core/eval/subsample_sweep.h"
#include "core/options/option_set.h"
#include "core/pipeline/pipeline_registry.h"
#include "core/pipeline/stereo_vo_sweep.h"

namespace sightline::cli {

namespace {

const char kHelp[] =
    "usage: sightline-cli sweep stereo-vo PATH --subsample A..B [--out DIR] [--profile F]\n"
    "                            [--set key=value]...\n"
    "\n"
    "Runs stereo visual odometry on PATH once per subsampling factor k = A..B (every k-th\n"
    "frame) and prints, per factor, the equivalent frame rate, the ground-truth and estimated\n"
    "path lengths and the length error, as in Table 1 of the stereo odometry paper. With --out,\n"
    "also writes DIR/sweep.csv and DIR/sweep.png (length error against factor). The dataset\n"
    "needs ground truth. Options as for 'sightline-cli run stereo-vo'.\n";

// "1..10" or "3" -> [first, last].
bool ParseRange(const std::string& text, int* first, int* last) {
  const size_t dots = text.find("..");
  try {
    if (dots == std::string::npos) {
      *first = *last = std::stoi(text);
    } else {
      *first = std::stoi(text.substr(0, dots));
      *last = std::stoi(text.substr(dots + 2));
    }
  } catch (...) {
    return false;
  }
  return *first >= 1 && *last >= *first && *last <= 1000;
}

cv::Mat DrawSweep(const std::vector<SubsampleRow>& rows) {
  double max_error = 1;
  for (const SubsampleRow& r : rows) max_error = std::max(max_error, r.length_error_pct);
  PlotCanvas canvas(
      800, 500, {static_cast<double>(rows.front().factor), static_cast<double>(rows.back().factor)},
      {0, max_error * 1.1}, false);
  canvas.DrawAxes("subsampling factor k", "length error [%]");
  canvas.DrawTitle("stereo-vo: path length error per subsampling factor");
  std::vector<Eigen::Vector2d> points;
  points.reserve(rows.size());
  for (const SubsampleRow& r : rows) points.emplace_back(r.factor, r.length_error_pct);
  canvas.DrawPolyline(points, PlotCanvas::kRed);
  for (const Eigen::Vector2d& p : points) canvas.DrawMarker(p, PlotCanvas::kRed, true);
  return canvas.image();
}

}  // namespace

int SweepCommand(const std::vector<std::string>& args) {
  StatusOr<CliArgs> parsed =
      CliArgs::Parse(args, {"--subsample", "--out", "--profile", "--set"}, {"--help"});
  if (!parsed.ok()) return Fail("sweep: " + parsed.status().message());
  if (parsed->Has("--help")) {
    std::fputs(kHelp, stdout);
    return 0;
  }
  if (parsed->positionals().size() != 2)
    return Fail("sweep: expected PIPELINE and PATH (see --help)");
  if (parsed->positionals()[0] != "stereo-vo") {
    return Fail("sweep: only the stereo-vo pipeline has a subsampling sweep");
  }
  const std::string path = parsed->positionals()[1];
  int first = 1, last = 10;
  if (auto range = parsed->Value("--subsample"); range && !ParseRange(*range, &first, &last)) {
    return Fail("sweep: --subsample expects A..B with 1 <= A <= B (e.g. 1..10), got '" + *range +
                "'");
  }

  // The pipeline's own option set, as `sightline-cli run stereo-vo` and the GUI declare it.
  const PipelineRegistry registry = BuiltinPipelines();
  OptionSet options;
  Status s = registry.Find("stereo-vo")->declare_options(&options);
  if (s.ok() && parsed->Value("--profile")) s = options.LoadYaml(*parsed->Value("--profile"));
  for (const std::string& assignment : parsed->Values("--set")) {
    if (s.ok()) s = options.ApplyOverride(assignment);
  }
  if (!s.ok()) return Fail("sweep: " + s.ToString());

  StatusOr<std::vector<SubsampleRow>> rows = SweepStereoVo(
      path, options, first, last, [](int k) { std::fprintf(stderr, "sweep: k = %d\n", k); });
  if (!rows.ok()) return Fail("sweep: " + rows.status().message());
  const std::string table = FormatSubsampleTable(*rows);
  std::fputs(table.c_str(), stdout);

  if (auto out = parsed->Value("--out")) {
    std::error_code ec;
    std::filesystem::create_directories(*out, ec);
    const std::string csv_path = (std::filesystem::path(*out) / "sweep.csv").string();
    std::ofstream csv(csv_path);
    csv << "factor,equivalent_fps,gt_length_m,estimate_length_m,length_error_pct,pairs\n";
    for (const SubsampleRow& r : *rows) {
      csv << r.factor << "," << r.equivalent_fps << "," << r.gt_length_m << ","
          << r.estimate_length_m << "," << r.length_error_pct << "," << r.pairs << "\n";
    }
    if (!csv) return Fail("sweep: cannot write " + csv_path);
    const std::string png_path = (std::filesystem::path(*out) / "sweep.png").string();
    if (!cv::imwrite(png_path, DrawSweep(*rows))) return Fail("sweep: cannot write " + png_path);
    std::printf("wrote %s and %s\n", csv_path.c_str(), png_path.c_str());
  }
  return 0;
}

}  // namespace sightline::cli
