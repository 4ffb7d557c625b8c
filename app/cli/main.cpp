// sightline-cli-full: every sightline-cli command. The installed sightline-cli (front_main.cpp)
// answers --help, --version and `info` of recorded datasets itself and hands the rest to this
// program with execv, so that those start without loading PCL, VTK, ROS and the sensor drivers.
#include <string>
#include <vector>

#include "app/cli/commands.h"
#include "app/cli/top_level.h"

int main(int argc, char** argv) {
  if (std::optional<int> code = sightline::cli::RunTopLevel(argc, argv)) return *code;
  const std::string command = argv[1];
  const std::vector<std::string> args(argv + 2, argv + argc);
  if (command == "info") return sightline::cli::InfoCommand(args);
  if (command == "run") return sightline::cli::RunCommand(args);
  if (command == "options") return sightline::cli::OptionsCommand(args);
  if (command == "eval") return sightline::cli::EvalCommand(args);
  if (command == "simulate") return sightline::cli::SimulateCommand(args);
  if (command == "sweep") return sightline::cli::SweepCommand(args);
  if (command == "floor") return sightline::cli::FloorCommand(args);
  if (command == "calibrate") return sightline::cli::CalibrateCommand(args);
  if (command == "arm-listen") return sightline::cli::ArmListenCommand(args);
  if (command == "arm-sim") return sightline::cli::ArmSimCommand(args);
  if (command == "record") return sightline::cli::RecordCommand(args);
  if (command == "train-button-classifier") {
    return sightline::cli::TrainButtonClassifierCommand(args);
  }
  return sightline::cli::Fail("unknown command '" + command + "' (see sightline-cli --help)");
}
