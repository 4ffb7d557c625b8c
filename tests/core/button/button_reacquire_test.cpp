// Re-acquisition on sequences synthesised from the real panel photos
// (../shared/data/button_panels/test_panels): a 480x360 view slides over the photo so the
// tapped button leaves the view and comes back, then a finger-like occluder covers it and is
// taken away. The track must never be reported away from the tapped button, must be lost
// while the button is out of view, and must be re-acquired within a few frames once the
// button is whole in view again.
#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/button/button_detector.h"
#include "core/button/button_tracker.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

constexpr int kViewW = 480, kViewH = 360;
constexpr int kReacquireWithin = 3;  // Frames after the button is whole in view again.

struct Case {
  const char* file;
  cv::Rect2d box;  // The tapped button's labelled box (labels.csv).
};

// A finger from the bottom edge of the view up to `tip`, `width` px wide, skin coloured.
void DrawFinger(cv::Mat& view, cv::Point2d tip, double width) {
  const cv::Scalar skin(120, 150, 205);  // BGR.
  const int w = int(width);
  cv::rectangle(view, cv::Rect(int(tip.x - w / 2), int(tip.y), w, view.rows), skin, cv::FILLED);
  cv::ellipse(view, cv::Point(int(tip.x), int(tip.y)), cv::Size(w / 2, w / 2), 0, 180, 360, skin,
              cv::FILLED, cv::LINE_AA);
  cv::ellipse(view, cv::Point(int(tip.x), int(tip.y + 0.3 * w)), cv::Size(w / 3, w / 4), 0, 180,
              360, cv::Scalar(150, 175, 225), cv::FILLED, cv::LINE_AA);  // Nail.
}

struct Frame {
  cv::Point offset;  // View origin in the photo.
  bool finger = false;
};

void RunCase(const std::string& dir, const Case& c) {
  SCOPED_TRACE(c.file);
  const cv::Mat photo = cv::imread(dir + "/" + c.file);
  ASSERT_FALSE(photo.empty());
  const cv::Point2d centre(c.box.x + 0.5 * c.box.width, c.box.y + 0.5 * c.box.height);
  const double half = 0.5 * std::max(c.box.width, c.box.height);
  auto clamp_x = [&](int x) { return std::clamp(x, 0, photo.cols - kViewW); };
  const int y0 = std::clamp(int(centre.y) - kViewH / 2, 0, photo.rows - kViewH);
  const int x_start = clamp_x(int(centre.x) - kViewW / 2);
  // Out of view: the view's left edge beyond the button's right edge (or the photo's end).
  std::vector<Frame> frames;
  const int step = 24;
  int x = x_start;
  frames.push_back({{x, y0}});
  while (x < photo.cols - kViewW && x < int(c.box.x + c.box.width) + 60) {
    x = clamp_x(x + step);
    frames.push_back({{x, y0}});
  }
  for (int i = 0; i < 3; ++i) frames.push_back({{x, y0}});
  while (x > x_start) {
    x = std::max(x_start, x - step);
    frames.push_back({{x, y0}});
  }
  for (int i = 0; i < 4; ++i) frames.push_back({{x, y0}});
  for (int i = 0; i < 5; ++i) frames.push_back({{x, y0}, true});
  for (int i = 0; i < 6; ++i) frames.push_back({{x, y0}});

  auto view_of = [&](const Frame& f) {
    cv::Mat view = photo(cv::Rect(f.offset, cv::Size(kViewW, kViewH))).clone();
    if (f.finger) DrawFinger(view, centre - cv::Point2d(f.offset), 1.3 * half);
    return view;
  };
  ButtonDetectorOptions options;
  options.method = "multiscale";
  ButtonDetector detector(options);
  auto model = detector.Detect(view_of(frames[0]), centre - cv::Point2d(frames[0].offset));
  ASSERT_TRUE(model.ok()) << model.status().ToString();
  ASSERT_LT(cv::norm((*model)->center - (centre - cv::Point2d(frames[0].offset))), 0.5 * half);
  ButtonTracker tracker(*model);
  int whole_in_view_since = -1, found_frames = 0, lost_out_of_view = 0, out_of_view_frames = 0;
  bool reacquired_after_leaving = false, finger_seen = false;
  int after_finger_since = -1;
  for (size_t i = 1; i < frames.size(); ++i) {
    const Frame& f = frames[i];
    const cv::Point2d truth = centre - cv::Point2d(f.offset);
    const cv::Rect2d box = c.box - cv::Point2d(f.offset);
    const bool whole =
        box.x >= 0 && box.y >= 0 && box.x + box.width <= kViewW && box.y + box.height <= kViewH;
    const bool out = box.x + box.width < 0 || box.x >= kViewW;
    auto t = tracker.Track(view_of(f));
    ASSERT_TRUE(t.ok()) << t.status().ToString();
    std::printf("  %s frame %2zu view x %4d%s: %-10s %s\n", c.file, i, f.offset.x,
                f.finger ? " finger" : "", TrackStateName(t->state),
                t->found ? ("at " + std::to_string(int(t->center.x)) + "," +
                            std::to_string(int(t->center.y)) + " (truth " +
                            std::to_string(int(truth.x)) + "," + std::to_string(int(truth.y)) + ")")
                               .c_str()
                         : t->reason.c_str());
    if (t->found) {
      ++found_frames;
      // Never on another button: within half the button's size of its true centre.
      EXPECT_LT(cv::norm(t->center - truth), half) << "frame " << i;
    }
    if (out) {
      ++out_of_view_frames;
      lost_out_of_view += t->found ? 0 : 1;
      EXPECT_FALSE(t->found) << "frame " << i << ": reported while out of view";
      whole_in_view_since = -1;
    } else if (whole && !f.finger) {
      if (whole_in_view_since < 0) whole_in_view_since = int(i);
      if (int(i) - whole_in_view_since >= kReacquireWithin) {
        EXPECT_TRUE(t->found) << "frame " << i << ": not re-acquired " << kReacquireWithin
                              << " frames after the button came whole into view";
      }
    } else {
      whole_in_view_since = -1;
    }
    if (t->state == TrackState::kReacquired && out_of_view_frames > 0) {
      reacquired_after_leaving = true;
    }
    if (f.finger) finger_seen = true;
    if (finger_seen && !f.finger) {
      if (after_finger_since < 0) after_finger_since = int(i);
      if (int(i) - after_finger_since >= kReacquireWithin) {
        EXPECT_TRUE(t->found) << "frame " << i << ": not found after the finger left";
      }
    }
  }
  EXPECT_GT(out_of_view_frames, 0);
  EXPECT_TRUE(reacquired_after_leaving);
  EXPECT_GE(tracker.reacquisitions(), 1);
  std::printf(
      "%s: %d of %zu frames found, %d out-of-view frames all lost: %s, %d "
      "re-acquisitions\n",
      c.file, found_frames, frames.size() - 1, out_of_view_frames,
      lost_out_of_view == out_of_view_frames ? "yes" : "no", tracker.reacquisitions());
}

TEST(ButtonReacquire, LeavesViewAndFingerOnRealPanels) {
  SIGHTLINE_REQUIRE_DATA(dir, "button_panels/test_panels");
  for (const Case& c : {Case{"34.jpg", {342, 260, 99, 99}}, Case{"42.jpg", {791, 311, 31, 33}},
                        Case{"35.jpg", {554, 273, 49, 49}}, Case{"39.jpg", {647, 336, 56, 47}}}) {
    RunCase(dir, c);
  }
}

}  // namespace
}  // namespace sightline
