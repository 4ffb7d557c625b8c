// `sightline-cli eval` as a user runs it: tables, JSON with the metrics.json accuracy keys,
// plots, and one-line failures.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests/app/process.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

const std::string kCli = std::string(SIGHTLINE_BIN_DIR) + "/sightline-cli";

testing::ProcessResult Cli(const std::string& args) {
  return testing::RunProcess(kCli + " " + args);
}

// Writes the KITTI poses file with every translation multiplied by `factor`.
std::string ScaledKittiCopy(const std::string& poses_path, double factor, const std::string& name) {
  const std::string out_path = testing::TempDir("eval_cli") + "/" + name;
  std::ifstream in(poses_path);
  std::ofstream out(out_path);
  std::string line;
  out.precision(12);
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    double v[12];
    int n = 0;
    while (n < 12 && fields >> v[n]) ++n;
    if (n != 12) continue;
    for (int i : {3, 7, 11}) v[i] *= factor;
    for (int i = 0; i < 12; ++i) out << (i ? " " : "") << v[i];
    out << "\n";
  }
  return out_path;
}

// The value after "key": in a JSON text, or -1 when absent.
double JsonNumber(const std::string& json, const std::string& key) {
  const size_t at = json.find("\"" + key + "\": ");
  if (at == std::string::npos) return -1;
  return std::stod(json.substr(at + key.size() + 4));
}

TEST(EvalCli, HelpDescribesTheCommand) {
  const auto r = Cli("eval --help");
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("usage: sightline-cli eval EST GT"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("--align"), std::string::npos);
  const auto top = Cli("--help");
  EXPECT_NE(top.out.find("eval EST GT"), std::string::npos) << top.out;
}

TEST(EvalCli, KittiPosesAgainstThemselvesPrintAZeroTable) {
  SIGHTLINE_REQUIRE_DATA(dir, "kitti_clip1");
  const std::string poses = dir + "/poses.txt";
  const auto r = Cli("eval " + poses + " " + poses + " --format kitti");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("ate_rmse_m"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("kitti_t_err_pct"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("ground truth 59.86"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("nan"), std::string::npos) << r.out;
}

TEST(EvalCli, JsonHasTheAccuracyKeysOfMetricsJson) {
  SIGHTLINE_REQUIRE_DATA(dir, "kitti_clip1");
  const std::string poses = dir + "/poses.txt";
  const std::string drift = ScaledKittiCopy(poses, 1.01, "drift.txt");
  const auto r = Cli("eval " + drift + " " + poses + " --align none --json");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  ASSERT_EQ(r.out.front(), '{') << r.out;
  for (const char* key :
       {"ate_rmse_m", "ate_mean_m", "ate_median_m", "ate_max_m", "rpe_trans_pct",
        "rpe_rot_deg_per_m", "rpe_trans_m", "rpe_rot_deg", "length_error_pct", "endpoint_error_pct",
        "kitti_t_err_pct", "kitti_r_err_deg_per_100m", "pairs"}) {
    EXPECT_GE(JsonNumber(r.out, key), 0) << key << "\n" << r.out;
  }
  EXPECT_EQ(r.out.find("\"scale\""), std::string::npos);
  EXPECT_NEAR(JsonNumber(r.out, "length_error_pct"), 1.0, 1e-6) << r.out;

  const auto sim3 = Cli("eval " + drift + " " + poses + " --align sim3 --json");
  ASSERT_EQ(sim3.exit_code, 0) << sim3.out;
  EXPECT_NEAR(JsonNumber(sim3.out, "scale"), 1 / 1.01, 1e-6) << sim3.out;
  EXPECT_LT(JsonNumber(sim3.out, "ate_rmse_m"), 1e-6) << sim3.out;
}

TEST(EvalCli, SetOverridesAnEvalOption) {
  SIGHTLINE_REQUIRE_DATA(dir, "kitti_clip1");
  const std::string poses = dir + "/poses.txt";
  const auto r = Cli("eval " + poses + " " + poses + " --set eval.segment_lengths_m=kitti");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("note: KITTI segment errors left out"), std::string::npos) << r.out;
  const auto bad = Cli("eval " + poses + " " + poses + " --set eval.rpe_delta_frames=0");
  EXPECT_NE(bad.exit_code, 0);
  EXPECT_NE(bad.out.find("eval.rpe_delta_frames"), std::string::npos) << bad.out;
}

TEST(EvalCli, TumGroundTruthWithPlots) {
  SIGHTLINE_REQUIRE_DATA(dir, "tum_fr1_desk");
  const std::string gt = dir + "/groundtruth.txt";
  const std::string plots = testing::TempDir("eval_cli") + "/plots";
  const auto r = Cli("eval " + gt + " " + gt + " --format tum --plot " + plots);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("wrote " + plots + "/top_view.png"), std::string::npos) << r.out;
  for (const char* name : {"/top_view.png", "/ate_over_time.png"}) {
    EXPECT_GT(std::filesystem::file_size(plots + name), 1000u) << name;
  }
}

TEST(EvalCli, FailuresAreOneLineNamingTheCause) {
  const auto missing = Cli("eval /nonexistent/est.txt /nonexistent/gt.txt");
  EXPECT_NE(missing.exit_code, 0);
  EXPECT_EQ(std::count(missing.out.begin(), missing.out.end(), '\n'), 1) << missing.out;
  EXPECT_NE(missing.out.find("/nonexistent/est.txt"), std::string::npos) << missing.out;

  const auto bad_align = Cli("eval a b --align affine");
  EXPECT_NE(bad_align.exit_code, 0);
  EXPECT_NE(bad_align.out.find("eval.align"), std::string::npos) << bad_align.out;

  const auto one_file = Cli("eval a");
  EXPECT_NE(one_file.exit_code, 0);
  EXPECT_NE(one_file.out.find("expected EST and GT"), std::string::npos);

  SIGHTLINE_REQUIRE_DATA(kitti, "kitti_clip1");
  SIGHTLINE_REQUIRE_DATA(tum, "tum_fr1_desk");
  // KITTI's synthetic 10 Hz clock and TUM's Unix times never meet.
  const auto apart = Cli("eval " + kitti + "/poses.txt " + tum + "/groundtruth.txt");
  EXPECT_NE(apart.exit_code, 0);
  EXPECT_EQ(std::count(apart.out.begin(), apart.out.end(), '\n'), 1) << apart.out;
  EXPECT_NE(apart.out.find("only 0 poses associate"), std::string::npos) << apart.out;
}

}  // namespace
}  // namespace sightline
