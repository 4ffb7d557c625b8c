// The detector on real elevator panel photos (../shared/data/button_panels/test_panels) with
// the hand-labelled boxes of tests/data/button_panels/labels.csv: a tap at a button's centre
// selects a region whose centroid lies inside that button's box, and a tap on blank wall or
// plate is "no button here".
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <opencv2/imgcodecs.hpp>
#include <sstream>

#include "core/button/button_detector.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

struct Label {
  std::string file, kind, name;
  cv::Rect2d box;   // Buttons.
  cv::Point2d tap;  // Blank taps; the box centre for buttons.
};

std::vector<Label> ReadLabels(const std::string& path) {
  std::vector<Label> labels;
  std::ifstream in(path);
  EXPECT_TRUE(in.good()) << "cannot read " << path;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> f;
    std::stringstream ss(line);
    std::string field;
    while (std::getline(ss, field, ',')) f.push_back(field);
    f.resize(7);
    Label l;
    l.file = f[0], l.kind = f[1], l.name = f[6];
    if (l.kind == "button") {
      const double x0 = std::stod(f[2]), y0 = std::stod(f[3]), x1 = std::stod(f[4]),
                   y1 = std::stod(f[5]);
      l.box = cv::Rect2d(x0, y0, x1 - x0 + 1, y1 - y0 + 1);
      l.tap = {0.5 * (x0 + x1), 0.5 * (y0 + y1)};
    } else if (l.kind == "blank") {
      l.tap = {std::stod(f[2]), std::stod(f[3])};
    } else {
      ADD_FAILURE() << path << " line " << number << ": unknown kind '" << l.kind << "'";
      continue;
    }
    labels.push_back(l);
  }
  return labels;
}

TEST(RealPanels, TapAtAButtonCentreSelectsThatButton) {
  SIGHTLINE_REQUIRE_DATA(dir, "button_panels/test_panels");
  const std::vector<Label> labels = ReadLabels(SIGHTLINE_BUTTON_LABELS);
  std::map<std::string, cv::Mat> photos;
  std::map<std::string, int> photo_hits, photo_taps;
  int taps = 0, hits = 0;
  ButtonDetector detector;
  for (const Label& l : labels) {
    if (l.kind != "button") continue;
    cv::Mat& photo = photos[l.file];
    if (photo.empty()) photo = cv::imread(dir + "/" + l.file);
    ASSERT_FALSE(photo.empty()) << l.file;
    ++taps;
    ++photo_taps[l.file];
    auto model = detector.Detect(photo, l.tap);
    const bool hit = model.ok() && l.box.contains((*model)->center);
    if (hit) {
      ++hits;
      ++photo_hits[l.file];
    } else {
      std::printf("  miss %s '%s' tap (%.0f, %.0f): %s\n", l.file.c_str(), l.name.c_str(), l.tap.x,
                  l.tap.y,
                  model.ok() ? ("centroid (" + std::to_string(int((*model)->center.x)) + ", " +
                                std::to_string(int((*model)->center.y)) + ") outside the box")
                                   .c_str()
                             : model.status().message().c_str());
    }
  }
  for (const auto& [file, n] : photo_taps)
    std::printf("  %s: %d / %d\n", file.c_str(), photo_hits[file], n);
  const double rate = double(hits) / std::max(1, taps);
  std::printf("real panels: %d of %d taps (%.1f %%) on %zu photos select the tapped button\n", hits,
              taps, 100 * rate, photos.size());
  EXPECT_GE(photos.size(), 10u);
  EXPECT_GE(taps, 100);
  EXPECT_GE(rate, 0.90);
}

TEST(RealPanels, TapOnBlankWallIsNoButtonHere) {
  SIGHTLINE_REQUIRE_DATA(dir, "button_panels/test_panels");
  const std::vector<Label> labels = ReadLabels(SIGHTLINE_BUTTON_LABELS);
  ButtonDetector detector;
  int blanks = 0;
  for (const Label& l : labels) {
    if (l.kind != "blank") continue;
    ++blanks;
    const cv::Mat photo = cv::imread(dir + "/" + l.file);
    ASSERT_FALSE(photo.empty()) << l.file;
    auto model = detector.Detect(photo, l.tap);
    ASSERT_FALSE(model.ok()) << l.file << " blank tap (" << l.tap.x << ", " << l.tap.y
                             << ") selected a region at " << (*model)->center;
    EXPECT_EQ(model.status().code(), StatusCode::kNotFound);
    EXPECT_NE(model.status().message().find("no button here"), std::string::npos);
  }
  EXPECT_GE(blanks, 10);
}

}  // namespace
}  // namespace sightline
