// `sightline-cli run stereo-vo` and `sightline-cli sweep stereo-vo` as a user runs them.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tests/app/process.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

const std::string kCli = std::string(SIGHTLINE_BIN_DIR) + "/sightline-cli";

testing::ProcessResult Cli(const std::string& args) {
  return testing::RunProcess(kCli + " " + args);
}

// The fields of one frames.csv line; the last field (status) is quoted and may hold commas.
std::vector<std::string> CsvFields(const std::string& line) {
  std::vector<std::string> fields;
  const size_t quote = line.find('"');
  std::istringstream head(line.substr(0, quote));
  for (std::string field; std::getline(head, field, ',');) fields.push_back(field);
  if (quote != std::string::npos) fields.push_back(line.substr(quote));
  return fields;
}

// frames.csv has the `retracked` column right after `tracked`, and every row a 0 or 1 there;
// then `anchored`, tracks aligned against their anchors, which most frames of real data have.
void ExpectRetrackedAndAnchoredColumns(const std::string& frames) {
  std::istringstream lines(frames);
  std::string line;
  ASSERT_TRUE(std::getline(lines, line));
  const std::vector<std::string> header = CsvFields(line);
  const auto tracked = std::find(header.begin(), header.end(), "tracked");
  ASSERT_NE(tracked, header.end()) << line;
  ASSERT_NE(tracked + 1, header.end()) << line;
  EXPECT_EQ(*(tracked + 1), "retracked") << line;
  ASSERT_NE(tracked + 2, header.end()) << line;
  EXPECT_EQ(*(tracked + 2), "anchored") << line;
  const size_t column = static_cast<size_t>(tracked - header.begin()) + 1;
  int rows = 0, anchored_rows = 0;
  while (std::getline(lines, line)) {
    const std::vector<std::string> row = CsvFields(line);
    ASSERT_EQ(row.size(), header.size()) << line;
    EXPECT_TRUE(row[column] == "0" || row[column] == "1") << line;
    EXPECT_LE(std::stoi(row[column + 1]), std::stoi(row[column - 1])) << line;
    anchored_rows += std::stoi(row[column + 1]) > 0 ? 1 : 0;
    ++rows;
  }
  EXPECT_GT(rows, 0);
  EXPECT_GT(anchored_rows, rows / 2);
}

TEST(StereoVoCli, RunWritesTrajectoryFramesAndAccuracy) {
  SIGHTLINE_REQUIRE_DATA(kitti, "kitti_clip1");
  const std::string out = testing::TempDir("stereo_vo_cli_run");
  const testing::ProcessResult r = Cli("run stereo-vo " + kitti + " --out " + out + " --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const std::string metrics = testing::ReadTextFile(out + "/metrics.json");
  for (const char* key :
       {"\"length_error_pct\"", "\"endpoint_error_pct\"", "\"ate_rmse_m\"", "\"rpe_trans_pct\"",
        "\"rpe_rot_deg_per_m\"", "\"kitti_t_err_pct\"", "\"kitti_r_err_deg_per_100m\"",
        "\"tracking\"", "\"matching\"", "\"ransac\"", "\"refine\""}) {
    EXPECT_NE(metrics.find(key), std::string::npos) << key;
  }
  const std::string frames = testing::ReadTextFile(out + "/frames.csv");
  EXPECT_EQ(std::count(frames.begin(), frames.end(), '\n'), 52);  // Header + 51 frames.
  ExpectRetrackedAndAnchoredColumns(frames);
  std::istringstream trajectory(testing::ReadTextFile(out + "/trajectory.txt"));
  std::string line;
  while (std::getline(trajectory, line) && (line.empty() || line[0] == '#')) {
  }
  std::istringstream values(line);
  int fields = 0;
  for (double v; values >> v;) ++fields;
  EXPECT_EQ(fields, 8);  // TUM: time, position, quaternion.
}

TEST(StereoVoCli, SubsampleAndKittiFormatFlags) {
  SIGHTLINE_REQUIRE_DATA(kitti, "kitti_clip1");
  const std::string out = testing::TempDir("stereo_vo_cli_flags");
  const testing::ProcessResult r =
      Cli("run stereo-vo " + kitti + " --out " + out + " --subsample 5 --format kitti --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const std::string trajectory = testing::ReadTextFile(out + "/trajectory.txt");
  EXPECT_EQ(std::count(trajectory.begin(), trajectory.end(), '\n'), 11);  // Frames 0, 5, ..., 50.
  std::istringstream values(trajectory.substr(0, trajectory.find('\n')));
  int fields = 0;
  for (double v; values >> v;) ++fields;
  EXPECT_EQ(fields, 12);  // KITTI: 3x4 matrix.
  EXPECT_NE(testing::ReadTextFile(out + "/metrics.json").find("\"stereo.subsample\": 5"),
            std::string::npos);
}

TEST(StereoVoCli, SweepPrintsTheTableAndWritesAPlot) {
  SIGHTLINE_REQUIRE_DATA(kitti, "kitti_clip1");
  const std::string out = testing::TempDir("stereo_vo_cli_sweep");
  const testing::ProcessResult r =
      Cli("sweep stereo-vo " + kitti + " --subsample 1..3 --out " + out);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("factor"), std::string::npos) << r.out;
  EXPECT_TRUE(std::filesystem::exists(out + "/sweep.png"));
  const std::string csv = testing::ReadTextFile(out + "/sweep.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 4);  // Header + k = 1, 2, 3.
}

TEST(StereoVoCli, FailuresAreOneLine) {
  testing::ProcessResult r = Cli("sweep stereo-vo /nonexistent --subsample 1..2");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.out.find("sightline-cli: sweep"), std::string::npos) << r.out;
  r = Cli("sweep stereo-vo /nonexistent --subsample 3..1");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.out.find("--subsample expects"), std::string::npos) << r.out;
  r = Cli("run stereo-vo /nonexistent --out /tmp/x --format bogus");
  EXPECT_NE(r.exit_code, 0);
}

}  // namespace
}  // namespace sightline
