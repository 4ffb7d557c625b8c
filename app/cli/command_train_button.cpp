// sightline-cli train-button-classifier: trains the region classifier (button or printed label,
// core/button/region_classifier.h) on hand-labelled panel photos and writes its weights as the
// C++ initialisers that are built into the detector.
#include <cstdio>
#include <fstream>
#include <opencv2/imgcodecs.hpp>

#include "app/cli/cli_args.h"
#include "app/cli/commands.h"
#include "core/button/panel_labels.h"
#include "core/button/region_classifier.h"
#include "core/button/region_samples.h"

namespace sightline::cli {

namespace {

const char kHelp[] =
    "usage: sightline-cli train-button-classifier LABELS.csv PHOTO_DIR --out FILE\n"
    "\n"
    "Taps each labelled button and printed label of the photos (at its centre and four points\n"
    "around it), keeps the region the detector (button.detect.method=multiscale) selects, and\n"
    "trains the logistic model that tells the tapped button's region from a region selected at\n"
    "a label. FILE receives the model as C++ initialisers (core/button/\n"
    "region_classifier_weights.inc is the built-in one). LABELS.csv is in the format of\n"
    "tests/data/button_panels/labels.csv.\n";

}  // namespace

int TrainButtonClassifierCommand(const std::vector<std::string>& argv) {
  auto parsed = CliArgs::Parse(argv, {"--out"}, {"--help"});
  if (!parsed.ok()) return Fail("train-button-classifier: " + parsed.status().message());
  if (parsed->Has("--help")) {
    std::fputs(kHelp, stdout);
    return 0;
  }
  if (parsed->positionals().size() != 2 || !parsed->Value("--out")) {
    return Fail("train-button-classifier: expected LABELS.csv PHOTO_DIR --out FILE (see --help)");
  }
  const std::string labels_path = parsed->positionals()[0], dir = parsed->positionals()[1];
  StatusOr<std::vector<PanelLabel>> labels = ReadPanelLabels(labels_path);
  if (!labels.ok()) return Fail("train-button-classifier: " + labels.status().message());
  ButtonDetectorOptions options;
  options.method = "multiscale";
  std::vector<Eigen::VectorXd> features;
  std::vector<int> is_button;
  int photos = 0;
  for (const auto& [file, photo_labels] : ByPhoto(*labels)) {
    const std::string path = dir + "/" + file;
    const cv::Mat photo = cv::imread(path);
    if (photo.empty()) return Fail("train-button-classifier: cannot read photo " + path);
    ++photos;
    for (const RegionSample& s : SampleRegions(options, photo, photo_labels, true)) {
      features.push_back(s.features);
      is_button.push_back(s.is_button);
    }
  }
  StatusOr<RegionClassifier> model = RegionClassifier::Train(features, is_button);
  if (!model.ok()) return Fail("train-button-classifier: " + model.status().message());
  int right = 0, buttons = 0;
  for (size_t i = 0; i < features.size(); ++i) {
    buttons += is_button[i];
    right += (model->ButtonProbability(features[i]) >= 0.5) == (is_button[i] == 1);
  }
  const std::string out_path = *parsed->Value("--out");
  std::ofstream out(out_path);
  out << "// The built-in region classifier (core/button/region_classifier.h), written by\n"
      << "// `sightline-cli train-button-classifier` from " << photos << " photos:\n"
      << "// " << buttons << " button regions, " << features.size() - buttons
      << " regions at labels.\n"
      << model->ToSource();
  out.close();
  if (!out) return Fail("train-button-classifier: cannot write " + out_path);
  std::printf(
      "%d photos, %d button regions, %zu regions at labels; %d of %zu right on the "
      "training samples at p = 0.5; wrote %s\n",
      photos, buttons, features.size() - buttons, right, features.size(), out_path.c_str());
  return 0;
}

}  // namespace sightline::cli
