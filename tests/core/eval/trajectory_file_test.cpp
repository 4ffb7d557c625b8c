#include "core/eval/trajectory_file.h"

#include <gtest/gtest.h>

#include <fstream>

#include "tests/core/eval/eval_test_util.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

TEST(TrajectoryFile, DetectsTumAndKittiByFieldCount) {
  const std::string dir = testing::TempDir("eval_file");
  const Trajectory t = testing::Helix(12);
  ASSERT_TRUE(WriteTumTrajectory(t, dir + "/tum.txt").ok());
  ASSERT_TRUE(WriteKittiTrajectory(t, dir + "/kitti.txt").ok());
  EXPECT_EQ(*DetectTrajectoryFormat(dir + "/tum.txt"), TrajectoryFormat::kTum);
  EXPECT_EQ(*DetectTrajectoryFormat(dir + "/kitti.txt"), TrajectoryFormat::kKitti);
  StatusOr<Trajectory> kitti = ReadTrajectoryFile(dir + "/kitti.txt");
  ASSERT_TRUE(kitti.ok());
  EXPECT_EQ(kitti->size(), 12u);
  EXPECT_DOUBLE_EQ(kitti->poses()[3].time_s, 0.1 * 3);  // Synthetic 10 Hz.
  StatusOr<Trajectory> tum = ReadTrajectoryFile(dir + "/tum.txt", TrajectoryFormat::kTum);
  ASSERT_TRUE(tum.ok());
  EXPECT_NEAR(tum->poses()[3].time_s, 100.3, 1e-6);
}

TEST(TrajectoryFile, ForcedFormatThatDoesNotFitFailsNamingTheLine) {
  const std::string dir = testing::TempDir("eval_file");
  ASSERT_TRUE(WriteTumTrajectory(testing::Helix(3), dir + "/tum.txt").ok());
  StatusOr<Trajectory> t = ReadTrajectoryFile(dir + "/tum.txt", TrajectoryFormat::kKitti);
  ASSERT_FALSE(t.ok());
  EXPECT_NE(t.status().message().find("tum.txt line 2"), std::string::npos) << t.status().message();
}

TEST(TrajectoryFile, UnknownLayoutAndMissingFilesFail) {
  const std::string dir = testing::TempDir("eval_file");
  std::ofstream(dir + "/odd.txt") << "# comment\n1 2 3 4 5\n";
  StatusOr<Trajectory> t = ReadTrajectoryFile(dir + "/odd.txt");
  ASSERT_FALSE(t.ok());
  EXPECT_NE(t.status().message().find("odd.txt line 2: 5 fields"), std::string::npos)
      << t.status().message();
  std::ofstream(dir + "/empty.txt") << "# nothing\n";
  EXPECT_NE(ReadTrajectoryFile(dir + "/empty.txt").status().message().find("no poses"),
            std::string::npos);
  t = ReadTrajectoryFile(dir + "/absent.txt");
  ASSERT_FALSE(t.ok());
  EXPECT_NE(t.status().message().find("absent.txt"), std::string::npos);
  EXPECT_FALSE(ParseTrajectoryFormat("csv").ok());
}

}  // namespace
}  // namespace sightline
