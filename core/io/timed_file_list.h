// "timestamp filename" lists: TUM rgb.txt / depth.txt, and times.txt beside image folders.
#pragma once

#include <string>
#include <vector>

#include "core/common/status.h"

namespace sightline {

// One listed file and its timestamp.
struct TimedFile {
  double time_s = 0;
  std::string file;  // As written in the list, usually relative to the list's folder.
  int line = 0;      // 1-based line in the list, for messages.
};

// Reads lines "timestamp filename [more fields ignored]" ('#' comments, blank lines skipped).
// ParseError naming file and line for a truncated line or a timestamp that is not a number.
StatusOr<std::vector<TimedFile>> ReadTimedFileList(const std::string& path);

// Reads one timestamp per line (the first field of each line; extra fields are ignored).
StatusOr<std::vector<double>> ReadTimesFile(const std::string& path);

// Non-empty lines of `path` starting with '#', without the '#' (e.g. "file: 'x.bag'").
std::vector<std::string> ReadCommentLines(const std::string& path, int max_lines = 20);

}  // namespace sightline
