// The sightline-cli commands. Each returns the process exit code and prints a one-line reason
// on failure.
#pragma once

#include <string>
#include <vector>

namespace sightline::cli {

int InfoCommand(const std::vector<std::string>& args);
int RunCommand(const std::vector<std::string>& args);
int OptionsCommand(const std::vector<std::string>& args);
int EvalCommand(const std::vector<std::string>& args);
int SimulateCommand(const std::vector<std::string>& args);
int SweepCommand(const std::vector<std::string>& args);
int FloorCommand(const std::vector<std::string>& args);
int CalibrateCommand(const std::vector<std::string>& args);
int ArmListenCommand(const std::vector<std::string>& args);
int ArmSimCommand(const std::vector<std::string>& args);
int RecordCommand(const std::vector<std::string>& args);
int TrainButtonClassifierCommand(const std::vector<std::string>& args);

// Prints "sightline-cli: <message>" to stderr and returns 1.
int Fail(const std::string& message);

}  // namespace sightline::cli
