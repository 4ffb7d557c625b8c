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

int main(int argc, char** argv) {
  using namespace sightline::cli;
  if (argc < 2) return Fail("sightline-cli-stereo runs `run stereo-vo PATH --out DIR ...`");
  if (std::string(argv[1]) == "run") {
    const std::vector<std::string> args(argv + 2, argv + argc);
    if (RunsInStereoProgram(args)) return RunCommand(args);
  }
  return HandOverToFullProgram(argv);
}
