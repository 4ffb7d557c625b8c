// Where the front binary (sightline-cli) finds the programs it hands command lines to
// (sightline-cli-full, sightline-cli-stereo) and how it hands a command line over.
#pragma once

#include <string>
#include <vector>

namespace sightline::cli {

// The places sightline-cli-full is looked for, in order: beside this executable (the build
// tree's bin/) and in its libexec folder relative to the installed bin/
// (../libexec/sightline/). Found through /proc/self/exe, so symlinks and PATH do not matter.
std::vector<std::string> FullProgramCandidates();

// The same places for the program called `name` (e.g. "sightline-cli-stereo").
std::vector<std::string> ProgramCandidates(const std::string& name);

// Replaces this process by the first of ProgramCandidates(name) that exists, with the same
// arguments (argv[0] kept). Returns false, printing nothing, when none exists or execv fails.
bool HandOverToProgram(const std::string& name, char** argv);

// Replaces this process by sightline-cli-full with the same arguments (argv[0] kept) and does
// not return when that works. Otherwise prints why, naming the paths looked at
// ("sightline-cli: 'run' needs sightline-cli-full, which is missing: ...") and returns 1.
int HandOverToFullProgram(char** argv);

}  // namespace sightline::cli
