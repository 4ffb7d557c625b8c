// Line-oriented text files (TUM lists, KITTI calib/poses, EuRoC CSV) with errors naming the line.
#pragma once

#include <string>
#include <vector>

#include "core/common/status.h"

namespace sightline {

// One non-empty, non-comment line of a text file and its 1-based line number.
struct DataLine {
  int number = 0;
  std::string text;
};

// Reads a text file, dropping blank lines and lines starting with '#' (after a UTF-8 BOM).
StatusOr<std::vector<DataLine>> ReadDataLines(const std::string& path);

// Splits on white space and commas.
std::vector<std::string> SplitFields(const std::string& text);

// Parses every field of the line as a finite number. Fails, naming path and line, when there are
// fewer than `min_count` fields, when a field is not a number, or when a number is NaN or infinite.
StatusOr<std::vector<double>> ParseNumbers(const DataLine& line, size_t min_count,
                                           const std::string& path);

// Checks that `path` is a regular, readable file of at most `max_bytes` and reads it whole.
// Errors name the path and the cause: no such file, a folder, not a regular file (a device or
// pipe such as /dev/zero), cannot be read (the system's reason, e.g. permission denied), or larger
// than the limit (nothing is read then). `what` names the file's role, e.g. "profile".
StatusOr<std::string> ReadWholeTextFile(const std::string& path, size_t max_bytes,
                                        const std::string& what);

// Whole-file helpers.
bool FileExists(const std::string& path);
bool DirectoryExists(const std::string& path);
// Joins two path pieces with one '/'.
std::string JoinPath(const std::string& a, const std::string& b);

}  // namespace sightline
