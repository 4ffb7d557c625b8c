#include "core/options/option_set.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "tests/support/test_data.h"

namespace sightline {
namespace {

struct RansacOptions {
  int max_iterations = 250;
  double min_inlier_ratio = 0.2;
  static OptionTable<RansacOptions> Describe() {
    return OptionTable<RansacOptions>("ransac")
        .Int("max_iterations", &RansacOptions::max_iterations, "", 1, 100000, 1, "Iterations.")
        .Double("min_inlier_ratio", &RansacOptions::min_inlier_ratio, "", 0, 1, 0.01, "Ratio.");
  }
};

struct MappingOptions {
  double cell_size_m = 0.025;
  bool exclude_people = true;
  std::string extractor = "ransac";
  RansacOptions ransac;
  static OptionTable<MappingOptions> Describe() {
    return OptionTable<MappingOptions>("mapping")
        .Double("cell_size_m", &MappingOptions::cell_size_m, "m", 0.001, 1, 0.005, "Cell size.")
        .Bool("exclude_people", &MappingOptions::exclude_people, "Skip people.")
        .Choice("extractor", &MappingOptions::extractor, {"ransac", "split_merge"}, "Extractor.")
        .Nested(&MappingOptions::ransac, RansacOptions::Describe());
  }
};

OptionSet MakeSet() {
  OptionSet set;
  EXPECT_TRUE(set.Declare(MappingOptions::Describe()).ok());
  return set;
}

TEST(OptionSet, DescribeTableGivesTypedSpecsWithDefaults) {
  const OptionSet set = MakeSet();
  ASSERT_EQ(set.specs().size(), 5u);
  const OptionSpec* spec = set.FindSpec("mapping.ransac.max_iterations");
  ASSERT_NE(spec, nullptr);
  EXPECT_EQ(spec->type, OptionType::kInt);
  EXPECT_EQ(std::get<int64_t>(spec->default_value), 250);
  EXPECT_EQ(set.FindSpec("mapping.cell_size_m")->unit, "m");
}

TEST(OptionSet, ExtractFillsTypedStruct) {
  OptionSet set = MakeSet();
  ASSERT_TRUE(set.ApplyOverride("mapping.ransac.max_iterations=500").ok());
  ASSERT_TRUE(set.ApplyOverride("mapping.extractor=split_merge").ok());
  ASSERT_TRUE(set.ApplyOverride("mapping.exclude_people=false").ok());
  const MappingOptions m = set.Extract(MappingOptions::Describe());
  EXPECT_EQ(m.ransac.max_iterations, 500);
  EXPECT_EQ(m.extractor, "split_merge");
  EXPECT_FALSE(m.exclude_people);
  EXPECT_DOUBLE_EQ(m.cell_size_m, 0.025);
}

TEST(OptionSet, YamlRoundTrip) {
  OptionSet set = MakeSet();
  ASSERT_TRUE(set.Set("mapping.cell_size_m", 0.05).ok());
  ASSERT_TRUE(set.Set("mapping.ransac.min_inlier_ratio", 0.35).ok());
  ASSERT_TRUE(set.Set("mapping.extractor", std::string("split_merge")).ok());
  const std::string path = testing::TempDir("options") + "/profile.yaml";
  ASSERT_TRUE(set.SaveYaml(path).ok());
  OptionSet loaded = MakeSet();
  Status s = loaded.LoadYaml(path);
  ASSERT_TRUE(s.ok()) << s.ToString();
  for (const OptionSpec& spec : set.specs()) {
    EXPECT_EQ(FormatOptionValue(*loaded.Get(spec.key)), FormatOptionValue(*set.Get(spec.key)))
        << spec.key;
  }
}

TEST(OptionSet, YamlCommentStandsOnItsOwnKeysLine) {
  OptionSet set = MakeSet();
  ASSERT_TRUE(set.Set("mapping.extractor", std::string("split_merge")).ok());
  const std::string yaml = set.ToYaml();
  EXPECT_NE(yaml.find("  cell_size_m: 0.025  # Cell size. [m]\n"), std::string::npos) << yaml;
  EXPECT_NE(yaml.find("  extractor: split_merge  # Extractor.\n"), std::string::npos) << yaml;
  EXPECT_NE(yaml.find("    max_iterations: 250  # Iterations.\n"), std::string::npos) << yaml;
  // No line holds a comment alone or a comment belonging to another key.
  std::stringstream lines(yaml);
  for (std::string line; std::getline(lines, line);) {
    const size_t hash = line.find('#');
    if (hash == std::string::npos) continue;
    EXPECT_NE(line.find(':'), std::string::npos) << "comment without a key: " << line;
    EXPECT_LT(line.find(':'), hash) << line;
  }
}

TEST(OptionSet, DottedKeysInYamlWork) {
  OptionSet set = MakeSet();
  ASSERT_TRUE(set.LoadYamlText("mapping.ransac.max_iterations: 42\n", "p.yaml").ok());
  EXPECT_EQ(std::get<int64_t>(*set.Get("mapping.ransac.max_iterations")), 42);
}

TEST(OptionSet, UnknownKeyInProfileNamesKeyFileAndLine) {
  OptionSet set = MakeSet();
  const std::string path = testing::TempDir("options") + "/bad.yaml";
  std::ofstream(path) << "mapping:\n  cell_size_m: 0.05\n  ransac:\n    max_iteratons: 10\n";
  Status s = set.LoadYaml(path);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.code(), StatusCode::kNotFound);
  EXPECT_NE(s.message().find(path + " line 4"), std::string::npos) << s.message();
  EXPECT_NE(s.message().find("mapping.ransac.max_iteratons"), std::string::npos) << s.message();
  // All or nothing: the valid line before the bad one was not applied.
  EXPECT_DOUBLE_EQ(std::get<double>(*set.Get("mapping.cell_size_m")), 0.025);
}

TEST(OptionSet, OutOfRangeValueIsRejectedWithRange) {
  OptionSet set = MakeSet();
  Status s = set.ApplyOverride("mapping.ransac.min_inlier_ratio=1.5");
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.code(), StatusCode::kInvalidArgument);
  EXPECT_NE(s.message().find("mapping.ransac.min_inlier_ratio"), std::string::npos);
  EXPECT_NE(s.message().find("[0, 1]"), std::string::npos) << s.message();
  EXPECT_DOUBLE_EQ(std::get<double>(*set.Get("mapping.ransac.min_inlier_ratio")), 0.2);
}

TEST(OptionSet, OutOfRangeInProfileNamesLine) {
  OptionSet set = MakeSet();
  Status s = set.LoadYamlText("mapping:\n  ransac:\n    max_iterations: 0\n", "p.yaml");
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("p.yaml line 3"), std::string::npos) << s.message();
}

TEST(OptionSet, BadTypesAndChoicesAreRejected) {
  OptionSet set = MakeSet();
  EXPECT_FALSE(set.ApplyOverride("mapping.ransac.max_iterations=2.5").ok());
  EXPECT_FALSE(set.ApplyOverride("mapping.exclude_people=maybe").ok());
  EXPECT_FALSE(set.ApplyOverride("mapping.extractor=hough").ok());
  EXPECT_FALSE(set.ApplyOverride("mapping.cell_size_m").ok());
  EXPECT_FALSE(set.ApplyOverride("mapping.cell_size_m=nan").ok());
  EXPECT_FALSE(set.LoadYamlText("mapping: [1, 2\n", "broken.yaml").ok());
}

TEST(OptionSet, DuplicateDeclarationFails) {
  OptionSet set = MakeSet();
  EXPECT_FALSE(set.Declare(MappingOptions::Describe()).ok());
}

TEST(OptionSet, ResetRestoresDefaults) {
  OptionSet set = MakeSet();
  ASSERT_TRUE(set.ApplyOverride("mapping.cell_size_m=0.5").ok());
  set.ResetToDefaults();
  EXPECT_DOUBLE_EQ(std::get<double>(*set.Get("mapping.cell_size_m")), 0.025);
}

}  // namespace
}  // namespace sightline

namespace sightline {
namespace {

// Hostile profiles: each is refused with a message naming the file and the cause, quickly and
// without allocating more than the file's size.
class HostileProfile : public ::testing::Test {
 protected:
  Status Load(const std::string& text) {
    const std::string path = testing::TempDir("options") + "/hostile.yaml";
    std::ofstream(path, std::ios::binary) << text;
    path_ = path;
    return set_.LoadYaml(path);
  }
  OptionSet set_ = MakeSet();
  std::string path_;
};

TEST_F(HostileProfile, SequenceOrMapAsKeyIsRefused) {
  Status s = Load("[a, b]: 1\n");
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("line 1"), std::string::npos) << s.message();
  EXPECT_NE(s.message().find("key must be a word"), std::string::npos) << s.message();
  s = Load("mapping:\n  {x: 1}: 2\n");
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("line 2"), std::string::npos) << s.message();
}

TEST_F(HostileProfile, NestedAliasesDoNotExpand) {
  // Nine levels of maps holding ten aliases of the level below would be 10^10 values.
  auto level = [](int i) {
    std::string map = "a" + std::to_string(i) + ": &a" + std::to_string(i) + " {";
    for (int k = 0; k < 10; ++k) {
      map += (k ? ", k" : "k") + std::to_string(k) + ": " +
             (i == 0 ? std::string("1") : "*a" + std::to_string(i - 1));
    }
    return map + "}\n";
  };
  std::string text;
  for (int i = 0; i <= 9; ++i) text += level(i);
  const Status s = Load(text);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.code(), StatusCode::kParseError) << s.ToString();
  EXPECT_NE(s.message().find("more than 10000 values"), std::string::npos) << s.message();
}

TEST_F(HostileProfile, DeepNestingIsRefusedBeforeParsing) {
  const Status s = Load("mapping: " + std::string(100000, '[') + "\n");
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("nest deeper"), std::string::npos) << s.message();
}

TEST_F(HostileProfile, DuplicateKeysAreRefusedNamingBothLines) {
  Status s = Load("mapping:\n  cell_size_m: 0.05\n  cell_size_m: 0.07\n");
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("given twice"), std::string::npos) << s.message();
  EXPECT_NE(s.message().find("line 2"), std::string::npos) << s.message();
  s = Load("mapping:\n  cell_size_m: 0.05\nmapping.cell_size_m: 0.07\n");
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("mapping.cell_size_m"), std::string::npos) << s.message();
  EXPECT_DOUBLE_EQ(std::get<double>(*set_.Get("mapping.cell_size_m")), 0.025);
}

TEST_F(HostileProfile, FolderDeviceAndHugeFilesSayWhatTheyAre) {
  Status s = set_.LoadYaml(testing::TempDir("options"));
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("is a folder"), std::string::npos) << s.message();
  s = set_.LoadYaml("/dev/zero");
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("not a regular file"), std::string::npos) << s.message();
  s = set_.LoadYaml(testing::TempDir("options") + "/missing.yaml");
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("no such file"), std::string::npos) << s.message();
  s = Load("# " + std::string(2 << 20, 'x') + "\n");
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("bytes"), std::string::npos) << s.message();
}

TEST_F(HostileProfile, AProfileOneByteAboveTheSizeLimitIsRefusedNamingItsSize) {
  const std::string valid = "mapping:\n  cell_size_m: 0.05\n#";
  EXPECT_TRUE(Load(valid + std::string(kMaxProfileBytes - valid.size() - 1, 'x') + "\n").ok());
  const Status s = Load(valid + std::string(kMaxProfileBytes - valid.size(), 'x') + "\n");
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find(path_ + " is 1048577 bytes"), std::string::npos) << s.message();
  EXPECT_NE(s.message().find("at most 1048576"), std::string::npos) << s.message();
}

}  // namespace
}  // namespace sightline
