// sightline-cli-stereo: `sightline-cli run stereo-vo PATH ...` on a recorded stereo dataset,
// with the same command code as sightline-cli-full (command_run.cpp) but a pipeline registry
// that holds stereo-vo alone (program_pipelines_stereo.cpp) and core/io's readers: no PCL, ROS,
// sensor drivers or the other pipelines' modules, so the run's memory is the odometry's. The
// front binary (front_main.cpp) hands it only such command lines (stereo_program.h); any other
// that reaches it is handed on to sightline-cli-full, so its answer is always the full one's.
#include <memory>
#include <string>
#include <vector>

#include "app/cli/commands.h"
#include "app/cli/full_program.h"
#include "app/cli/stereo_program.h"
#include "core/io/pcd_source.h"
#include "core/io/recorded_source.h"

namespace sightline {
namespace {

// Stands in for the PCD reader, which needs PCL; never reached, as a stereo run opens no cloud.
class PcdInFullProgram : public RecordedSource {
 public:
  explicit PcdInFullProgram(std::string path) : path_(std::move(path)) {}
  Status Open() override {
    return Unavailable(path_ + ": PCD clouds are read by sightline-cli-full");
  }

 protected:
  StatusOr<Frame> Load(int64_t) override { return Unavailable(path_ + ": not open"); }

 private:
  std::string path_;
};

}  // namespace

// sightline_io_readers leaves the PCD reader to the program (pcd_source.h).
std::unique_ptr<Source> MakePcdSource(const std::string& path) {
  return std::make_unique<PcdInFullProgram>(path);
}

}  // namespace sightline

int main(int argc, char** argv) {
  using namespace sightline::cli;
  if (argc < 2) return Fail("sightline-cli-stereo runs `run stereo-vo PATH --out DIR ...`");
  if (std::string(argv[1]) == "run" && std::string(argv[1]) == "run") {
    const std::vector<std::string> args(argv + 2, argv + argc);
    if (RunsInStereoProgram(args)) return RunCommand(args);
  }
  return HandOverToFullProgram(argv);
}
