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
// Files larger than kMaxIndexFileBytes (core/common/input_limits.h) are refused unread.
// Fails naming the path when it is not a regular, readable file (CheckRegularFile): a folder or
// a device such as /dev/zero given as a list says so instead of being read.
StatusOr<std::vector<DataLine>> ReadDataLines(const std::string& path);

// Checks that `path` names a regular file that can be opened for reading. `name` is how
// messages name it (e.g. "profile /x.yaml" or just the path). NotFound "<name>: no such file";
// InvalidArgument "<name> is a folder, not a file" / "<name> is not a regular file (a device,
// pipe or socket)"; Unavailable "<name> cannot be read: <the system's reason, e.g. permission
// denied>".
Status CheckRegularFile(const std::string& path, const std::string& name);

// The system's reason for an errno, lower-case first: "permission denied".
std::string SystemReason(int error);

// Timestamps of a list must increase strictly. ParseError "<path> line <line>: timestamp
// <time> is not after the previous one (<previous>): timestamps must increase (a repeated or
// backwards time)" when time_s <= previous_s.
Status CheckTimeIncreases(double previous_s, double time_s, const std::string& path, int line);

// Splits on white space and commas.
std::vector<std::string> SplitFields(const std::string& text);

// Parses every field of the line as a finite number. Fails, naming path and line, when there are
// fewer than `min_count` fields, when a field is not a number, or when a number is NaN or infinite.
StatusOr<std::vector<double>> ParseNumbers(const DataLine& line, size_t min_count,
                                           const std::string& path);

// Checks that the file at `path` holds at most `max_bytes`: InvalidArgument "<path> is N bytes;
// a <what> file holds at most M bytes" otherwise (nothing is read).
Status CheckFileSize(const std::string& path, size_t max_bytes, const std::string& what);

// Checks that `path` is a regular, readable file of at most `max_bytes` and reads it whole.
// Errors name the path and the cause: no such file, a folder, not a regular file (a device or
// pipe such as /dev/zero), cannot be read (the system's reason, e.g. permission denied), or larger
// than the limit (nothing is read then). `what` names the file's role, e.g. "profile".
StatusOr<std::string> ReadWholeTextFile(const std::string& path, size_t max_bytes,
                                        const std::string& what);

// Whole-file helpers.
bool FileExists(const std::string& path);
// True when anything (a file, a folder, a device, a dangling link) is at `path`: readers use it
// for optional files, so that a folder or device where a file belongs is an error rather than
// silently ignored.
bool PathExists(const std::string& path);
bool DirectoryExists(const std::string& path);
// Joins two path pieces with one '/'.
std::string JoinPath(const std::string& a, const std::string& b);

}  // namespace sightline
