// Real Kinect data: lines from the TUM fr1_desk depth frames (an office desk seen from 1.5 m,
// camera pitched about 45 deg down: the floor, the desk's legs and cabinets, a wall).
#include <gtest/gtest.h>

#include "core/io/dataset.h"
#include "core/mapping/mapping_frame_processor.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

TEST(MappingRealData, LinesFromTumFr1DeskDepth) {
  SIGHTLINE_REQUIRE_DATA(path, "tum_fr1_desk");
  StatusOr<std::unique_ptr<Source>> source = OpenDataset(path, SourceKind::kRgbd);
  ASSERT_TRUE(source.ok()) << source.status().ToString();
  ASSERT_TRUE((*source)->info().rgbd.has_value());
  const PinholeCamera camera = (*source)->info().rgbd->color;
  std::vector<RgbdFrame> frames;
  while ((*source)->Grab().ok()) {
    StatusOr<Frame> frame = (*source)->Retrieve();
    ASSERT_TRUE(frame.ok());
    frames.push_back(std::get<RgbdFrame>(*frame));
  }
  ASSERT_EQ(frames.size(), 9u);
  // Floor from the first frame.
  std::vector<Eigen::Vector3f> points;
  AppendDepthPoints(frames[0].depth_m, camera, 6.0, 2, &points);
  StatusOr<FloorFitResult> floor = FloorPlaneEstimator().Fit(points);
  ASSERT_TRUE(floor.ok()) << floor.status().ToString();
  EXPECT_NEAR(floor->plane.CameraHeightM(), 1.5, 0.2);  // A standing person's hand-held Kinect.
  MappingOptions options;
  options.people.source = "none";  // No people in fr1_desk; keeps the test fast.
  MappingFrameProcessor processor(options);
  ASSERT_TRUE(processor.Configure(floor->plane, camera).ok());
  int frames_with_lines = 0;
  for (const RgbdFrame& frame : frames) {
    MappingInput input;
    input.stamp = frame.stamp;
    input.depth_m = frame.depth_m;
    StatusOr<std::shared_ptr<const MappingFrameResult>> r = processor.Process(input);
    ASSERT_TRUE(r.ok()) << r.status().ToString();
    EXPECT_TRUE((*r)->status == "ok" || (*r)->status == "no walls") << (*r)->status;
    // The floor was calibrated on frame 0; the hand-held camera then moves (0.1 m, 9 deg over
    // the 9 frames), so later frames find less of it. A robot-mounted camera does not move.
    if (frame.stamp.sequence_id == 0) EXPECT_GT((*r)->occupancy.floor_pixels, 1000);
    if (!(*r)->lines.lines.empty()) ++frames_with_lines;
    for (const WallSegment& line : (*r)->lines.lines) {
      EXPECT_GE(line.inliers, options.ransac.min_line_points);
      EXPECT_GT(line.length_m, 0.0);
    }
  }
  EXPECT_GE(frames_with_lines, 1);
  std::printf(
      "[ tum_fr1_desk ] camera %.3f m above the floor, pitched %.1f deg down; lines in "
      "%d of 9 frames\n",
      floor->plane.CameraHeightM(), floor->plane.PitchDownDeg(), frames_with_lines);
  EXPECT_TRUE(processor.reset_log().empty());
}

}  // namespace
}  // namespace sightline
