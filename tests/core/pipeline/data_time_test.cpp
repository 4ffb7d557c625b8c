// Data time: every pipeline's decisions use the frames' timestamps, so the same recording and
// options give the same outputs on an idle machine and with both cores busy. Each pipeline of
// the registry runs a short simulated recording twice through RunPipeline, the second time
// with spinning threads on every core, and every output must be identical (timing excepted).
#include <gtest/gtest.h>

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <thread>

#include "core/pipeline/button_pipeline.h"
#include "core/pipeline/pipeline_registry.h"
#include "core/sim/simulate.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

namespace fs = std::filesystem;

// Busy threads on every core (and one more) while it lives.
class CpuHog {
 public:
  CpuHog() {
    const unsigned n = std::max(2u, std::thread::hardware_concurrency()) + 1;
    for (unsigned i = 0; i < n; ++i) {
      threads_.emplace_back([this] {
        volatile double x = 1;
        while (!stop_) x = x * 1.0000001 + 1e-9;
      });
    }
  }
  ~CpuHog() {
    stop_ = true;
    for (std::thread& t : threads_) t.join();
  }

 private:
  std::atomic<bool> stop_{false};
  std::vector<std::thread> threads_;
};

std::string ReadAll(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// A CSV without its timing columns (headers ending in "_ms").
std::string WithoutTimingColumns(const std::string& csv) {
  std::stringstream in(csv);
  std::string line, out;
  std::vector<bool> keep;
  while (std::getline(in, line)) {
    std::vector<std::string> fields;
    std::string field;
    std::stringstream cells(line);
    while (std::getline(cells, field, ',')) fields.push_back(field);
    if (keep.empty()) {
      for (const std::string& f : fields)
        keep.push_back(f.size() < 3 || f.substr(f.size() - 3) != "_ms");
    }
    for (size_t i = 0; i < fields.size(); ++i) {
      if (i >= keep.size() || keep[i]) out += fields[i] + ",";
    }
    out += "\n";
  }
  return out;
}

// metrics.json's accuracy block and the counts that do not measure time.
std::string Figures(const std::string& json) {
  const size_t accuracy = json.find("\"accuracy\"");
  const size_t options = json.find("\"options\"");
  if (accuracy == std::string::npos || options == std::string::npos) return json;
  std::string block = json.substr(accuracy, options - accuracy);
  std::stringstream in(block);
  std::string line, out;
  while (std::getline(in, line)) {
    if (line.find("wall_time_s") != std::string::npos ||
        line.find("frames_per_second") != std::string::npos ||
        line.find("_ms") != std::string::npos) {
      continue;
    }
    out += line + "\n";
  }
  return out;
}

// Every file of a run, as compared: byte for byte, but for timing.
std::map<std::string, std::string> Outputs(const std::string& dir) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (!entry.is_regular_file()) continue;
    const std::string name = fs::relative(entry.path(), dir).string();
    std::string text = ReadAll(entry.path());
    if (name == "metrics.json") {
      text = Figures(text);
    } else if (entry.path().extension() == ".csv") {
      text = WithoutTimingColumns(text);
    } else if (entry.path().extension() == ".log" || name.find("log") != std::string::npos) {
      continue;  // Logs may mention durations.
    }
    files[name] = text;
  }
  return files;
}

struct Case {
  std::string pipeline;
  std::string scene;
  std::vector<std::string> overrides;
};

class DataTime : public ::testing::TestWithParam<Case> {
 protected:
  static std::string Simulated(const std::string& scene) {
    static std::map<std::string, std::string>* made = new std::map<std::string, std::string>;
    auto it = made->find(scene);
    if (it != made->end()) return it->second;
    const std::string dir = testing::TempDir("data_time_" + scene);
    sim::SimulationOptions options = sim::SimulationOptions::ForScene(scene);
    options.frames = scene == "panel" ? 80 : 40;
    if (scene == "corridor") {
      options.sensors = "rgbd,stereo";
      options.rgbd.resolution = "320x240";
    }
    EXPECT_TRUE(sim::Simulate(options, dir).ok());
    (*made)[scene] = dir;
    return dir;
  }

  // The tap on the approached button's true centre in the first frame.
  static std::string PanelTap(const std::string& dir) {
    StatusOr<std::vector<TrueButton>> buttons = ReadTrueButtons(dir + "/buttons.csv");
    if (!buttons.ok()) return "0,0@0";
    for (const TrueButton& b : *buttons) {
      if (b.id != 5 || b.visible.empty() || !b.visible[0]) continue;
      char tap[64];
      std::snprintf(tap, sizeof(tap), "button.run.tap=%.1f,%.1f@0", b.pixel[0].x(), b.pixel[0].y());
      return tap;
    }
    return "0,0@0";
  }

  StatusOr<RunReport> Run(const Case& c, const std::string& data, const std::string& out) {
    RunRequest request;
    request.pipeline = c.pipeline;
    request.dataset_path = data;
    request.out_dir = out;
    request.overrides = c.overrides;
    if (c.pipeline == "button") request.overrides.push_back(PanelTap(data));
    return RunPipeline(BuiltinPipelines(), request);
  }
};

TEST_P(DataTime, SameOutputsOnAnIdleAndABusyMachine) {
  const Case& c = GetParam();
  ASSERT_NE(BuiltinPipelines().Find(c.pipeline), nullptr) << c.pipeline;
  const std::string data = Simulated(c.scene);
  const std::string idle = testing::TempDir("data_time_idle_" + c.pipeline);
  const std::string busy = testing::TempDir("data_time_busy_" + c.pipeline);
  StatusOr<RunReport> first = Run(c, data, idle);
  ASSERT_TRUE(first.ok()) << first.status().ToString();
  StatusOr<RunReport> second = Internal("not run");
  {
    CpuHog hog;
    second = Run(c, data, busy);
  }
  ASSERT_TRUE(second.ok()) << second.status().ToString();
  EXPECT_GT(first->result.frames, 0);
  EXPECT_EQ(first->result.frames, second->result.frames);
  const auto a = Outputs(idle), b = Outputs(busy);
  ASSERT_FALSE(a.empty());
  for (const auto& [name, text] : a) {
    ASSERT_TRUE(b.count(name)) << name << " missing from the busy run";
    EXPECT_EQ(text, b.at(name)) << name << " differs between the idle and the busy run";
  }
  EXPECT_EQ(a.size(), b.size());
}

// Every pipeline of the registry is listed here; CoversTheRegistry fails when one is added
// without a case.
const std::vector<Case>& Cases() {
  static const std::vector<Case> cases = {
      {"inspect", "corridor", {}}, {"mapping", "corridor", {}}, {"stereo-vo", "corridor", {}},
      {"mobility", "terrain", {}}, {"mono-slam", "panel", {}},  {"button", "panel", {}},
  };
  return cases;
}

INSTANTIATE_TEST_SUITE_P(EveryPipeline, DataTime, ::testing::ValuesIn(Cases()),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           std::string name = info.param.pipeline;
                           for (char& ch : name) {
                             if (ch == '-') ch = '_';
                           }
                           return name;
                         });

TEST(DataTimeCases, CoverTheRegistry) {
  const PipelineRegistry registry = BuiltinPipelines();
  for (const PipelineInfo& info : registry.pipelines()) {
    bool found = false;
    for (const Case& c : Cases()) found = found || c.pipeline == info.name;
    EXPECT_TRUE(found) << info.name << " has no data-time case";
  }
}

}  // namespace
}  // namespace sightline
