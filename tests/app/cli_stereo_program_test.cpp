// sightline-cli-stereo, the light program the front binary hands `run stereo-vo` on recorded
// stereo datasets to: the same files, figures, messages and exit codes as sightline-cli-full,
// without PCL, ROS, Qt or the sensor drivers.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "tests/app/process.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

const std::string kBin = SIGHTLINE_BIN_DIR;
const std::string kFront = kBin + "/sightline-cli";
const std::string kFull = kBin + "/sightline-cli-full";
const std::string kStereo = kBin + "/sightline-cli-stereo";

std::string Quoted(const std::string& s) { return "'" + s + "'"; }

// The NEEDED entries of an ELF file, as readelf -d lists them.
std::vector<std::string> NeededLibraries(const std::string& elf) {
  const testing::ProcessResult r = testing::RunProcess("readelf -d " + Quoted(elf));
  EXPECT_EQ(r.exit_code, 0) << r.out;
  std::vector<std::string> needed;
  std::istringstream lines(r.out);
  for (std::string line; std::getline(lines, line);) {
    const size_t open = line.find('[');
    const size_t close = line.find(']', open);
    if (line.find("(NEEDED)") != std::string::npos && close != std::string::npos) {
      needed.push_back(line.substr(open + 1, close - open - 1));
    }
  }
  return needed;
}

std::vector<std::string> SplitLines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// frames.csv without its timing columns (header ending in "_ms"), which differ run to run.
std::string WithoutTimingColumns(const std::string& csv) {
  const std::vector<std::string> lines = SplitLines(csv);
  if (lines.empty()) return "";
  auto fields = [](const std::string& line) {
    // The last field (status) is quoted and may hold commas.
    std::vector<std::string> out;
    const size_t quote = line.find('"');
    std::istringstream head(line.substr(0, quote));
    for (std::string f; std::getline(head, f, ',');) out.push_back(f);
    if (quote != std::string::npos) out.push_back(line.substr(quote));
    return out;
  };
  const std::vector<std::string> header = fields(lines[0]);
  std::string kept;
  for (const std::string& line : lines) {
    const std::vector<std::string> row = fields(line);
    EXPECT_EQ(row.size(), header.size()) << line;
    for (size_t i = 0; i < row.size() && i < header.size(); ++i) {
      const std::string& name = header[i];
      if (name.size() > 3 && name.compare(name.size() - 3, 3, "_ms") == 0) continue;
      kept += row[i] + ",";
    }
    kept += "\n";
  }
  return kept;
}

// metrics.json without what a clock measures: the "timing_ms" object, wall_time_s and
// frames_per_second. Frames, accuracy, counts, options, failure and end stay.
std::string WithoutClockFigures(const std::string& json) {
  std::string text = json;
  const size_t timing = text.find("\"timing_ms\"");
  if (timing != std::string::npos) {
    size_t i = text.find('{', timing);
    int depth = 0;
    for (; i < text.size(); ++i) {
      depth += text[i] == '{' ? 1 : text[i] == '}' ? -1 : 0;
      if (depth == 0) break;
    }
    text.erase(timing, i + 1 - timing);
  }
  std::string kept;
  for (const std::string& line : SplitLines(text)) {
    if (line.find("\"wall_time_s\"") == std::string::npos &&
        line.find("\"frames_per_second\"") == std::string::npos) {
      kept += line + "\n";
    }
  }
  return kept;
}

// The printed lines without the timing table, whose rows are a stage and numbers only
// ("tracking   6.446   11.492   51").
std::string WithoutTimingTable(const std::string& out) {
  std::string kept;
  for (const std::string& line : SplitLines(out)) {
    std::istringstream words(line);
    std::string stage, word;
    words >> stage;
    bool numbers_only = true, any = false;
    while (words >> word) {
      any = true;
      numbers_only = numbers_only && word.find_first_not_of("0123456789.") == std::string::npos;
    }
    if (!(any && numbers_only)) kept += line + "\n";
  }
  return kept;
}

// The poses of a trajectory file (its lines but the "#" header).
size_t PoseCount(const std::string& path) {
  size_t poses = 0;
  for (const std::string& line : SplitLines(testing::ReadAll(path))) {
    poses += !line.empty() && line[0] != '#' ? 1 : 0;
  }
  return poses;
}

// Runs `args` (after `run stereo-vo PATH`) with the front binary and with sightline-cli-full into
// two folders and expects equal exit codes, messages, trajectories, frames and metrics.
void ExpectSameRun(const std::string& path, const std::string& args, int expected_exit) {
  const std::string dir = testing::TempDir("cli_stereo_same");
  const std::string light_out = dir + "/light", full_out = dir + "/full";
  const testing::ProcessResult light = testing::RunProcess(
      kFront + " run stereo-vo " + Quoted(path) + " --out " + Quoted(light_out) + " " + args);
  const testing::ProcessResult full = testing::RunProcess(
      kFull + " run stereo-vo " + Quoted(path) + " --out " + Quoted(full_out) + " " + args);
  EXPECT_EQ(light.exit_code, expected_exit) << light.out;
  EXPECT_EQ(full.exit_code, expected_exit) << full.out;
  std::string light_text = light.out, full_text = full.out;
  // The output folders' names are the one difference in the printed paths.
  for (std::string* text : {&light_text}) {
    for (size_t at; (at = text->find(light_out)) != std::string::npos;) {
      text->replace(at, light_out.size(), full_out);
    }
  }
  EXPECT_EQ(WithoutTimingTable(light_text), WithoutTimingTable(full_text)) << args;
  if (expected_exit == 1) return;  // No files.
  EXPECT_EQ(testing::ReadAll(light_out + "/trajectory.txt"),
            testing::ReadAll(full_out + "/trajectory.txt"))
      << path << " " << args;
  EXPECT_FALSE(testing::ReadAll(full_out + "/trajectory.txt").empty());
  EXPECT_EQ(std::filesystem::exists(light_out + "/stereo_vo_notes.txt"),
            std::filesystem::exists(full_out + "/stereo_vo_notes.txt"));
  if (std::filesystem::exists(full_out + "/stereo_vo_notes.txt")) {
    EXPECT_EQ(testing::ReadAll(light_out + "/stereo_vo_notes.txt"),
              testing::ReadAll(full_out + "/stereo_vo_notes.txt"));
  }
  EXPECT_EQ(WithoutTimingColumns(testing::ReadAll(light_out + "/frames.csv")),
            WithoutTimingColumns(testing::ReadAll(full_out + "/frames.csv")));
  const std::string light_metrics = testing::ReadAll(light_out + "/metrics.json");
  EXPECT_EQ(WithoutClockFigures(light_metrics),
            WithoutClockFigures(testing::ReadAll(full_out + "/metrics.json")));
  // The light run times its stages as the full one does.
  for (const std::string stage : {"\"read\"", "\"tracking\"", "\"matching\"", "\"total\""}) {
    EXPECT_NE(light_metrics.find(stage), std::string::npos) << stage;
  }
}

TEST(CliStereoProgram, NeedsNoPclVtkVideoQtRosOrSensorDriver) {
  const std::vector<std::string> needed = NeededLibraries(kStereo);
  bool calib3d = false;
  for (const std::string& lib : needed) {
    calib3d = calib3d || lib.rfind("libopencv_calib3d", 0) == 0;
    for (const std::string heavy : {"libpcl", "libvtk", "libopencv_videoio", "libQt", "libroscpp",
                                    "librosbag", "libOpenNI2", "libaravis"}) {
      EXPECT_NE(lib.rfind(heavy, 0), 0u) << "sightline-cli-stereo needs " << lib;
    }
  }
  EXPECT_TRUE(calib3d) << "readelf -d gave no stereo library: " << needed.size() << " entries";
}

TEST(CliStereoProgram, KittiRunEqualsTheFullProgramsWithAccuracy) {
  SIGHTLINE_REQUIRE_DATA(kitti, "kitti_clip1");
  ExpectSameRun(kitti, "", 0);
  ExpectSameRun(kitti, "--subsample 2 --format kitti", 0);
  // Ground truth: the run's accuracy figures are there (and equal, above).
  const std::string out = testing::TempDir("cli_stereo_kitti") + "/run";
  const testing::ProcessResult run = testing::RunProcess(
      kFront + " run stereo-vo " + Quoted(kitti) + " --out " + Quoted(out) + " --quiet");
  ASSERT_EQ(run.exit_code, 0) << run.out;
  EXPECT_NE(testing::ReadAll(out + "/metrics.json").find("\"accuracy\""), std::string::npos);
  EXPECT_EQ(PoseCount(out + "/trajectory.txt"), 51u);
}

TEST(CliStereoProgram, EurocAndSimulatedRunsEqualTheFullPrograms) {
  SIGHTLINE_REQUIRE_DATA(euroc, "euroc_v1_01_static");
  ExpectSameRun(euroc, "--set stereo.max_frames=40", 0);
  const std::string sim = testing::TempDir("cli_stereo_sim") + "/corridor";
  const testing::ProcessResult made = testing::RunProcess(
      kFull + " simulate corridor --out " + Quoted(sim) + " --frames 30 --sensors stereo --quiet");
  ASSERT_EQ(made.exit_code, 0) << made.out;
  ExpectSameRun(sim, "", 0);  // A recording folder: its stereo/ sensor.
  ExpectSameRun(sim + "/stereo", "", 0);
}

TEST(CliStereoProgram, ErrorsAndNothingAchievedKeepMessagesAndExitCodes) {
  SIGHTLINE_REQUIRE_DATA(kitti, "kitti_clip1");
  ExpectSameRun(kitti, "--set stereo.no_such_key=1", 1);
  ExpectSameRun(kitti, "--format tum2", 1);
  // A KITTI folder whose right images are its left ones: no depth, no frame tracked (exit 3).
  const std::string flat = testing::TempDir("cli_stereo_flat") + "/kitti";
  std::filesystem::create_directories(flat + "/image_l");
  std::filesystem::create_directories(flat + "/image_r");
  std::filesystem::copy_file(kitti + "/calib.txt", flat + "/calib.txt");
  for (const std::string name : {"000000.png", "000001.png", "000002.png"}) {
    std::filesystem::copy_file(kitti + "/image_l/000000.png", flat + "/image_l/" + name);
    std::filesystem::copy_file(kitti + "/image_l/000000.png", flat + "/image_r/" + name);
  }
  ExpectSameRun(flat, "", 3);
}

TEST(CliStereoProgram, FrontHandsOnlyRecordedStereoRunsToIt) {
  SIGHTLINE_REQUIRE_DATA(kitti, "kitti_clip1");
  SIGHTLINE_REQUIRE_DATA(tum, "tum_fr1_desk");
  // A folder with the front and the light program but no full program: what runs there ran in
  // the light program; what needs the full one says so.
  const std::string dir = testing::TempDir("cli_stereo_alone");
  std::filesystem::copy_file(kFront, dir + "/sightline-cli");
  std::filesystem::copy_file(kStereo, dir + "/sightline-cli-stereo");
  const std::string front = Quoted(dir + "/sightline-cli");
  const testing::ProcessResult stereo = testing::RunProcess(
      front + " run stereo-vo " + Quoted(kitti) + " --out " + Quoted(dir + "/out") + " --quiet");
  EXPECT_EQ(stereo.exit_code, 0) << stereo.out;
  EXPECT_EQ(PoseCount(dir + "/out/trajectory.txt"), 51u);
  for (const std::string args : {"run mapping " + Quoted(tum) + " --out " + Quoted(dir + "/m"),
                                 "run stereo-vo " + Quoted(tum) + " --out " + Quoted(dir + "/t"),
                                 "run stereo-vo aravis://a,b --out " + Quoted(dir + "/a"),
                                 std::string("run stereo-vo --help")}) {
    const testing::ProcessResult r = testing::RunProcess(front + " " + args);
    EXPECT_EQ(r.exit_code, 1) << args << ": " << r.out;
    EXPECT_EQ(r.out.rfind("sightline-cli: 'run' needs sightline-cli-full", 0), 0u) << r.out;
  }
  // The light program itself hands on any other command line.
  const testing::ProcessResult other =
      testing::RunProcess(Quoted(dir + "/sightline-cli-stereo") + " run mapping " + Quoted(tum));
  EXPECT_EQ(other.exit_code, 1) << other.out;
  EXPECT_EQ(other.out.rfind("sightline-cli: 'run' needs sightline-cli-full", 0), 0u) << other.out;
}

}  // namespace
}  // namespace sightline
