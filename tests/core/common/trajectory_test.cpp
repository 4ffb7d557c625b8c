#include "core/common/trajectory.h"

#include <gtest/gtest.h>

#include <fstream>

#include "tests/support/test_data.h"

namespace sightline {
namespace {

Trajectory MakeCircle(int n) {
  Trajectory t;
  for (int i = 0; i < n; ++i) {
    const double a = 0.1 * i;
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = Eigen::AngleAxisd(a, Eigen::Vector3d::UnitY()).toRotationMatrix();
    pose.translation() = Eigen::Vector3d(std::cos(a), 0.1 * i, std::sin(a));
    t.Add(100.0 + 0.1 * i, pose);
  }
  return t;
}

TEST(Trajectory, TumRoundTripKeepsPoses) {
  const std::string dir = testing::TempDir("traj");
  const Trajectory t = MakeCircle(20);
  ASSERT_TRUE(WriteTumTrajectory(t, dir + "/t.txt").ok());
  StatusOr<Trajectory> back = ReadTumTrajectory(dir + "/t.txt");
  ASSERT_TRUE(back.ok()) << back.status().ToString();
  ASSERT_EQ(back->size(), t.size());
  for (size_t i = 0; i < t.size(); ++i) {
    EXPECT_NEAR(back->poses()[i].time_s, t.poses()[i].time_s, 1e-6);
    EXPECT_TRUE(back->poses()[i].world_from_sensor.isApprox(t.poses()[i].world_from_sensor, 1e-7));
  }
}

TEST(Trajectory, KittiRoundTripIsExactToPrintedPrecision) {
  const std::string dir = testing::TempDir("traj");
  const Trajectory t = MakeCircle(15);
  ASSERT_TRUE(WriteKittiTrajectory(t, dir + "/p.txt").ok());
  StatusOr<Trajectory> back = ReadKittiTrajectory(dir + "/p.txt");
  ASSERT_TRUE(back.ok()) << back.status().ToString();
  ASSERT_EQ(back->size(), 15u);
  for (size_t i = 0; i < t.size(); ++i) {
    EXPECT_LT(
        (back->poses()[i].world_from_sensor.matrix() - t.poses()[i].world_from_sensor.matrix())
            .cwiseAbs()
            .maxCoeff(),
        1e-9);
    EXPECT_DOUBLE_EQ(back->poses()[i].time_s, 0.1 * i);  // Synthesized 10 Hz.
  }
}

TEST(Trajectory, NearestRespectsTolerance) {
  const Trajectory t = MakeCircle(10);  // Times 100.0 .. 100.9.
  EXPECT_EQ(t.Nearest(100.31, 0.02).value(), 3u);
  EXPECT_EQ(t.Nearest(100.36, 0.05).value(), 4u);
  EXPECT_FALSE(t.Nearest(100.35, 0.01).has_value());
  EXPECT_FALSE(t.Nearest(200, 1).has_value());
}

TEST(Trajectory, LengthOfStraightLine) {
  Trajectory t;
  for (int i = 0; i <= 10; ++i) {
    Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
    p.translation().x() = 0.5 * i;
    t.Add(i, p);
  }
  EXPECT_NEAR(t.LengthM(), 5.0, 1e-12);
  EXPECT_NEAR(t.DurationS(), 10.0, 1e-12);
}

TEST(Trajectory, NanPoseIsAnErrorNamingFileAndLine) {
  const std::string dir = testing::TempDir("traj");
  const std::string path = dir + "/gt.txt";
  std::ofstream(path) << "# header\n1.0 0 0 0 0 0 0 1\n2.0 nan 0 0 0 0 0 1\n";
  StatusOr<Trajectory> t = ReadTumTrajectory(path);
  ASSERT_FALSE(t.ok());
  EXPECT_EQ(t.status().code(), StatusCode::kParseError);
  EXPECT_NE(t.status().message().find(path + " line 3"), std::string::npos) << t.status().message();
}

TEST(Trajectory, TruncatedLineIsAnError) {
  const std::string dir = testing::TempDir("traj");
  const std::string path = dir + "/poses.txt";
  std::ofstream(path) << "1 0 0 0 0 1 0 0 0 0 1 0\n1 0 0 0 0 1";
  StatusOr<Trajectory> t = ReadKittiTrajectory(path);
  ASSERT_FALSE(t.ok());
  EXPECT_NE(t.status().message().find("line 2"), std::string::npos) << t.status().message();
  EXPECT_NE(t.status().message().find("expected 12"), std::string::npos);
}

TEST(Trajectory, ExtraFieldsAndMismatchedTimesAreErrors) {
  const std::string dir = testing::TempDir("traj");
  std::ofstream(dir + "/gt.txt") << "1.0 0 0 0 0 0 0 1 7\n";
  StatusOr<Trajectory> tum = ReadTumTrajectory(dir + "/gt.txt");
  ASSERT_FALSE(tum.ok());
  EXPECT_NE(tum.status().message().find("found 9"), std::string::npos) << tum.status().message();
  std::ofstream(dir + "/p.txt") << "1 0 0 0 0 1 0 0 0 0 1 0\n1 0 0 0 0 1 0 0 0 0 1 0\n";
  EXPECT_TRUE(ReadKittiTrajectory(dir + "/p.txt").ok());
  StatusOr<Trajectory> kitti = ReadKittiTrajectory(dir + "/p.txt", {0.0, 0.1, 0.2});
  ASSERT_FALSE(kitti.ok());
  EXPECT_EQ(kitti.status().code(), StatusCode::kInvalidArgument);
}

TEST(Trajectory, MissingFileIsNotFound) {
  StatusOr<Trajectory> t = ReadTumTrajectory("/nonexistent/gt.txt");
  ASSERT_FALSE(t.ok());
  EXPECT_EQ(t.status().code(), StatusCode::kNotFound);
  EXPECT_NE(t.status().message().find("/nonexistent/gt.txt"), std::string::npos);
}

TEST(Trajectory, ReadsRealTumGroundTruth) {
  SIGHTLINE_REQUIRE_DATA(dir, "tum_fr1_desk");
  StatusOr<Trajectory> t = ReadTumTrajectory(dir + "/groundtruth.txt");
  ASSERT_TRUE(t.ok()) << t.status().ToString();
  ASSERT_GT(t->size(), 100u);
  // First row of the file: 1305031449.7996 1.2334 -0.0113 1.6941 0.7907 0.4393 -0.1770 -0.3879.
  EXPECT_NEAR(t->poses()[0].time_s, 1305031449.7996, 1e-4);
  EXPECT_NEAR(t->poses()[0].world_from_sensor.translation().x(), 1.2334, 1e-9);
}

// A message of a failed read, or "" when the read succeeded.
template <typename T>
std::string ErrorOf(const StatusOr<T>& read) {
  return read.ok() ? std::string() : read.status().message();
}

TEST(Trajectory, KittiPoseThatIsNotARotationIsParseErrorNamingLine) {
  const std::string dir = testing::TempDir("traj_not_rotation");
  const std::string identity = "1 0 0 0 0 1 0 0 0 0 1 0\n";
  struct Case {
    const char* line;
    const char* says;
  };
  for (const Case& c : {
           Case{"2 0 0 1 0 2 0 2 0 0 2 3\n", "R^T R differs from the identity by 3"},  // Scaled.
           Case{"1 0 0 1 0 1 0 2 0 0 -1 3\n", "determinant is -1"},                    // Mirror.
           Case{"1 0.5 0 1 0 1 0 2 0 0 1 3\n", "is not a rotation"},                   // Sheared.
           Case{"1 0 0 1 0 1 0 2 0 0 inf 3\n", "not finite"},
       }) {
    std::ofstream(dir + "/p.txt") << identity << identity << c.line << identity;
    const std::string error = ErrorOf(ReadKittiTrajectory(dir + "/p.txt"));
    EXPECT_NE(error.find("p.txt line 3"), std::string::npos) << error;
    EXPECT_NE(error.find(c.says), std::string::npos) << error;
  }
  // Printed with 7 significant digits (KITTI's own files) a rotation is still one.
  std::ofstream(dir + "/p.txt") << "9.999995e-01 7.196824e-04 -6.870876e-04 -1.401751e-02 "
                                   "-7.197717e-04 9.999997e-01 -1.295633e-04 -2.820321e-02 "
                                   "6.869946e-04 1.300585e-04 9.999998e-01 1.198998e+00\n";
  EXPECT_EQ(ErrorOf(ReadKittiTrajectory(dir + "/p.txt")), "");
}

TEST(Trajectory, TumQuaternionThatIsZeroOrNotUnitIsParseErrorNamingLine) {
  const std::string dir = testing::TempDir("traj_quaternion");
  for (const char* q : {"0 0 0 0", "0 0 0 2", "nan 0 0 1"}) {
    std::ofstream(dir + "/t.txt") << "# t x y z qx qy qz qw\n1 0 0 0 0 0 0 1\n2 0 0 0 " << q
                                  << "\n";
    const std::string error = ErrorOf(ReadTumTrajectory(dir + "/t.txt"));
    EXPECT_NE(error.find("t.txt line 3"), std::string::npos) << q << ": " << error;
  }
  std::ofstream(dir + "/t.txt") << "1 0 0 0 0 0 0 1\n2 0 0 0 0 0 0 0\n";
  EXPECT_NE(ErrorOf(ReadTumTrajectory(dir + "/t.txt")).find("has length 0, not 1"),
            std::string::npos);
  // Four printed decimals (TUM's ground truth) normalise.
  std::ofstream(dir + "/t.txt") << "1 0 0 0 0.7907 0.4393 -0.1770 -0.3879\n";
  EXPECT_EQ(ErrorOf(ReadTumTrajectory(dir + "/t.txt")), "");
}

}  // namespace
}  // namespace sightline
