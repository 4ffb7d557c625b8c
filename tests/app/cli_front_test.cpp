// sightline-cli's front binary and sightline-cli-full, which it hands commands to: the same
// words from both, no heavy library in the front, a clear error when the full program is gone.
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

// The NEEDED entries of an ELF file's dynamic section, as readelf -d lists them.
std::vector<std::string> NeededLibraries(const std::string& elf) {
  const testing::ProcessResult r = testing::RunProcess("readelf -d '" + elf + "'");
  EXPECT_EQ(r.exit_code, 0) << r.out;
  std::vector<std::string> needed;
  std::istringstream lines(r.out);
  for (std::string line; std::getline(lines, line);) {
    if (line.find("(NEEDED)") == std::string::npos) continue;
    const size_t open = line.find('[');
    const size_t close = line.find(']', open);
    if (open != std::string::npos && close != std::string::npos) {
      needed.push_back(line.substr(open + 1, close - open - 1));
    }
  }
  return needed;
}

// The libraries of `needed` whose names start with one of `prefixes`.
std::vector<std::string> WithPrefix(const std::vector<std::string>& needed,
                                    const std::vector<std::string>& prefixes) {
  std::vector<std::string> hits;
  for (const std::string& lib : needed) {
    for (const std::string& prefix : prefixes) {
      if (lib.rfind(prefix, 0) == 0) hits.push_back(lib);
    }
  }
  return hits;
}

const std::vector<std::string> kHeavy = {"libpcl",     "libvtk",    "libopencv_videoio",
                                         "libQt",      "libroscpp", "librosbag",
                                         "libOpenNI2", "libaravis"};

TEST(CliFront, HelpAndVersionEqualTheFullPrograms) {
  for (const std::string args : {"--help", "-h", "--version", ""}) {
    const testing::ProcessResult front = testing::RunProcess(kFront + " " + args);
    const testing::ProcessResult full = testing::RunProcess(kFull + " " + args);
    EXPECT_EQ(front.exit_code, full.exit_code) << "'" << args << "'";
    EXPECT_EQ(front.out, full.out) << "'" << args << "'";
  }
  EXPECT_EQ(testing::RunProcess(kFront + " --help").out.rfind("usage: sightline-cli COMMAND", 0),
            0u);
}

TEST(CliFront, FrontBinaryNeedsNoPclVtkVideoQtRosOrSensorDriver) {
  const std::vector<std::string> front = NeededLibraries(kFront);
  ASSERT_FALSE(WithPrefix(front, {"libopencv_core"}).empty()) << "readelf -d gave no NEEDED list";
  for (const std::string& lib : WithPrefix(front, kHeavy)) {
    ADD_FAILURE() << "sightline-cli needs " << lib;
  }
  // The check sees these libraries where they are: the full program links PCL and videoio.
  const std::vector<std::string> full = NeededLibraries(kFull);
  EXPECT_FALSE(WithPrefix(full, {"libpcl"}).empty());
  EXPECT_FALSE(WithPrefix(full, {"libopencv_videoio"}).empty());
}

TEST(CliFront, RunHelpWorksThroughTheHandOver) {
  const testing::ProcessResult front = testing::RunProcess(kFront + " run --help");
  EXPECT_EQ(front.exit_code, 0) << front.out;
  EXPECT_EQ(front.out.rfind("usage: sightline-cli run PIPELINE", 0), 0u) << front.out;
  EXPECT_EQ(front.out, testing::RunProcess(kFull + " run --help").out);
  // Errors of handed-over commands keep their exit code and message.
  const testing::ProcessResult unknown = testing::RunProcess(kFront + " frobnicate");
  EXPECT_EQ(unknown.exit_code, 1);
  EXPECT_EQ(unknown.out,
            "sightline-cli: unknown command 'frobnicate' (see sightline-cli --help)\n");
}

TEST(CliFront, InfoOfDatasetsAndCloudsEqualsTheFullPrograms) {
  SIGHTLINE_REQUIRE_DATA(tum, "tum_fr1_desk");
  SIGHTLINE_REQUIRE_DATA(cloud, "pcl_clouds/office1.pcd");
  const std::string missing = testing::TempDir("cli_front_info") + "/absent";
  for (const std::string args : {"info '" + tum + "'", "info '" + tum + "' --json",
                                 "info '" + cloud + "'", "info '" + missing + "'"}) {
    const testing::ProcessResult front = testing::RunProcess(kFront + " " + args);
    const testing::ProcessResult full = testing::RunProcess(kFull + " " + args);
    EXPECT_EQ(front.exit_code, full.exit_code) << args;
    EXPECT_EQ(front.out, full.out) << args;
  }
  EXPECT_NE(testing::RunProcess(kFront + " info '" + tum + "'").out.find("format: TUM RGB-D"),
            std::string::npos);
  EXPECT_NE(testing::RunProcess(kFront + " info '" + cloud + "'").out.find("format: PCD"),
            std::string::npos);
}

TEST(CliFront, WithoutTheFullProgramHandedOverCommandsSaySoAndFail) {
  const std::string dir = testing::TempDir("cli_front_alone");
  const std::string alone = dir + "/sightline-cli";
  std::filesystem::copy_file(kFront, alone);
  const testing::ProcessResult run = testing::RunProcess("'" + alone + "' run --help");
  EXPECT_EQ(run.exit_code, 1) << run.out;
  EXPECT_EQ(run.out.rfind("sightline-cli: 'run' needs sightline-cli-full", 0), 0u) << run.out;
  EXPECT_NE(run.out.find("missing (looked for " + dir + "/sightline-cli-full"), std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("/libexec/sightline/sightline-cli-full"), std::string::npos) << run.out;
  // What the front answers itself still works.
  const testing::ProcessResult help = testing::RunProcess("'" + alone + "' --help");
  EXPECT_EQ(help.exit_code, 0) << help.out;
  EXPECT_EQ(help.out, testing::RunProcess(kFull + " --help").out);
}

}  // namespace
}  // namespace sightline
