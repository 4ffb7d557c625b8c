#include "core/io/timed_file_list.h"

#include <filesystem>
#include <fstream>

#include "core/common/text_file.h"

namespace sightline {

StatusOr<std::vector<TimedFile>> ReadTimedFileList(const std::string& path) {
  auto lines = ReadDataLines(path);
  if (!lines.ok()) return lines.status();
  std::vector<TimedFile> files;
  files.reserve(lines->size());
  for (const DataLine& line : *lines) {
    const std::vector<std::string> fields = SplitFields(line.text);
    const std::string where = path + " line " + std::to_string(line.number);
    if (fields.size() < 2) {
      return ParseError(where + ": expected 'timestamp filename', found " +
                        std::to_string(fields.size()) + " field(s) (truncated line?)");
    }
    StatusOr<std::vector<double>> time = ParseNumbers(DataLine{line.number, fields[0]}, 1, path);
    if (!time.ok()) return time.status();
    if (!files.empty()) {
      SIGHTLINE_RETURN_IF_ERROR(
          CheckTimeIncreases(files.back().time_s, (*time)[0], path, line.number));
    }
    SIGHTLINE_RETURN_IF_ERROR(CheckListedPath(fields[1], path, line.number));
    files.push_back({(*time)[0], fields[1], line.number});
  }
  return files;
}

StatusOr<std::vector<double>> ReadTimesFile(const std::string& path) {
  auto lines = ReadDataLines(path);
  if (!lines.ok()) return lines.status();
  std::vector<double> times;
  times.reserve(lines->size());
  for (const DataLine& line : *lines) {
    const std::vector<std::string> fields = SplitFields(line.text);
    StatusOr<std::vector<double>> time =
        ParseNumbers(DataLine{line.number, fields.empty() ? "" : fields[0]}, 1, path);
    if (!time.ok()) return time.status();
    if (!times.empty()) {
      SIGHTLINE_RETURN_IF_ERROR(CheckTimeIncreases(times.back(), (*time)[0], path, line.number));
    }
    times.push_back((*time)[0]);
  }
  return times;
}

Status CheckListedPath(const std::string& file, const std::string& list_path, int line) {
  const std::string where = list_path + " line " + std::to_string(line) + ": file '" + file + "'";
  if (file.empty()) return ParseError(list_path + " line " + std::to_string(line) + ": no file");
  const std::filesystem::path path(file);
  if (path.is_absolute() || path.has_root_name()) {
    return ParseError(where +
                      " is an absolute path; listed files must be relative to the dataset folder");
  }
  int depth = 0;
  for (const std::filesystem::path& part : path) {
    if (part == "..") {
      if (--depth < 0) {
        return ParseError(where + " leaves the dataset folder ('..' climbs out of it)");
      }
    } else if (part != "." && !part.empty()) {
      ++depth;
    }
  }
  return Status::Ok();
}

std::vector<std::string> ReadCommentLines(const std::string& path, int max_lines) {
  std::vector<std::string> comments;
  std::ifstream in(path);
  std::string text;
  for (int n = 0; n < max_lines && std::getline(in, text); ++n) {
    const size_t first = text.find_first_not_of(" \t\xEF\xBB\xBF");
    if (first == std::string::npos || text[first] != '#') continue;
    comments.push_back(text.substr(first + 1));
  }
  return comments;
}

}  // namespace sightline
