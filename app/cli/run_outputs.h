// What `sightline-cli run PIPELINE` writes into --out, for `run PIPELINE --help`, and the list
// of files a finished run prints.
#pragma once

#include <string>
#include <vector>

namespace sightline::cli {

// Lines naming each file the pipeline writes and what it holds ("" for an unknown pipeline).
std::string RunOutputsHelp(const std::string& pipeline);

// Prints "wrote DIR/FILE" for every file of `outputs` (relative to `out_dir`); a run with many
// per-frame files prints the first ones and how many more there are.
void PrintWrittenFiles(const std::string& out_dir, const std::vector<std::string>& outputs);

}  // namespace sightline::cli
