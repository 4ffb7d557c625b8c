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
// ParseError naming file and line for a truncated line, a timestamp that is not a number, a
// timestamp not after the previous line's (CheckTimeIncreases), or a file name that leaves the
// list's folder (CheckListedPath).
StatusOr<std::vector<TimedFile>> ReadTimedFileList(const std::string& path);

// Reads one timestamp per line (the first field of each line; extra fields are ignored). The
// times must increase strictly: a repeated or backwards time is a ParseError naming the line.
StatusOr<std::vector<double>> ReadTimesFile(const std::string& path);

// A file named by line `line` of index file `list_path` must stay inside the folder it is
// relative to: ParseError naming list and line for an absolute path, an empty name, or one
// whose '..' components climb out of that folder ("../x.png", "a/../../x.png").
// "rgb/../rgb/1.png" stays inside and is accepted.
Status CheckListedPath(const std::string& file, const std::string& list_path, int line);

// Non-empty lines of `path` starting with '#', without the '#' (e.g. "file: 'x.bag'").
std::vector<std::string> ReadCommentLines(const std::string& path, int max_lines = 20);

}  // namespace sightline
