#include "core/common/pose_board.h"

#include <gtest/gtest.h>

#include <thread>
#include <vector>

namespace sightline {
namespace {

TEST(PoseBoard, KeepsTheNewestPosePerChannel) {
  PoseBoard board;
  EXPECT_FALSE(board.Latest("arm").has_value());
  board.Post("arm", 1.0, Eigen::Isometry3d(Eigen::Translation3d(1, 0, 0)));
  board.Post("arm", 2.0, Eigen::Isometry3d(Eigen::Translation3d(2, 0, 0)));
  board.Post("other", 5.0, Eigen::Isometry3d::Identity());
  std::optional<BoardPose> arm = board.Latest("arm");
  ASSERT_TRUE(arm.has_value());
  EXPECT_EQ(arm->stamp_s, 2.0);
  EXPECT_EQ(arm->pose.translation().x(), 2.0);
  EXPECT_EQ(arm->count, 2);
  board.Clear("arm");
  EXPECT_FALSE(board.Latest("arm").has_value());
  EXPECT_TRUE(board.Latest("other").has_value());
}

TEST(PoseBoard, ReadersSeeWholePosesWhileAWriterPosts) {
  PoseBoard board;
  std::thread writer([&] {
    for (int i = 1; i <= 20000; ++i) {
      board.Post("arm", i, Eigen::Isometry3d(Eigen::Translation3d(i, i, i)));
    }
  });
  int torn = 0;
  for (int i = 0; i < 20000; ++i) {
    std::optional<BoardPose> p = board.Latest("arm");
    if (!p) continue;
    const Eigen::Vector3d t = p->pose.translation();
    if (t.x() != p->stamp_s || t.y() != p->stamp_s || t.z() != p->stamp_s) ++torn;
  }
  writer.join();
  EXPECT_EQ(torn, 0);
  EXPECT_EQ(board.Latest("arm")->count, 20000);
}

}  // namespace
}  // namespace sightline
