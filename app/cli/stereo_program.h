// Which `run` command lines sightline-cli-stereo runs. That program links the run loop, the
// stereo-vo pipeline and core/io's readers only (stereo_main.cpp), so a stereo odometry run on a
// recorded dataset loads a few dozen shared libraries instead of sightline-cli-full's ~330.
#pragma once

#include <string>
#include <vector>

namespace sightline::cli {

// The --flags `sightline-cli run` takes: with a value, and switches (command_run.cpp).
const std::vector<std::string>& RunValueFlags();
const std::vector<std::string>& RunSwitches();

// True when `run_args` (the arguments after `run`) run stereo-vo on a recorded dataset that
// core/io's readers open: no --help, two positionals "stereo-vo" and PATH, PATH no sensor URI
// (scheme://), .bag or .oni, and a stereo dataset (KITTI, EuRoC, an image-folder stereo pair) or
// a recording with a stereo sensor. Everything else, errors included, is sightline-cli-full's.
bool RunsInStereoProgram(const std::vector<std::string>& run_args);

// Replaces this process by sightline-cli-stereo with the same arguments (argv[0] kept), or by
// sightline-cli-full when sightline-cli-stereo is not there (full_program.h). Returns 1 with a
// message only when neither can be run.
int HandOverToStereoProgram(char** argv);

}  // namespace sightline::cli
