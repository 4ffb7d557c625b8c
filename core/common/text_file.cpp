#include "core/common/text_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/common/input_limits.h"

namespace sightline {

std::string SystemReason(int error) {
  std::string text = std::strerror(error);
  if (!text.empty()) text[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(text[0])));
  return text;
}

Status CheckRegularFile(const std::string& path, const std::string& name) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) {
    if (errno == ENOENT || errno == ENOTDIR) return NotFound(name + ": no such file");
    return Unavailable(name + " cannot be read: " + SystemReason(errno));
  }
  if (S_ISDIR(info.st_mode)) return InvalidArgument(name + " is a folder, not a file");
  if (!S_ISREG(info.st_mode)) {
    return InvalidArgument(name + " is not a regular file (a device, pipe or socket)");
  }
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return Unavailable(name + " cannot be read: " + SystemReason(errno));
  ::close(fd);
  return Status::Ok();
}

Status CheckTimeIncreases(double previous_s, double time_s, const std::string& path, int line) {
  if (time_s > previous_s) return Status::Ok();
  char text[160];
  std::snprintf(text, sizeof(text),
                ": timestamp %.9g is %s the previous one (%.9g): timestamps must increase", time_s,
                time_s == previous_s ? "equal to" : "before", previous_s);
  return ParseError(path + " line " + std::to_string(line) + text);
}

StatusOr<std::vector<DataLine>> ReadDataLines(const std::string& path) {
  SIGHTLINE_RETURN_IF_ERROR(CheckRegularFile(path, path));
  SIGHTLINE_RETURN_IF_ERROR(CheckFileSize(path, kMaxIndexFileBytes, "list"));
  std::ifstream in(path);
  if (!in) return Unavailable(path + " cannot be read: " + SystemReason(errno));
  std::vector<DataLine> lines;
  std::string text;
  int number = 0;
  while (std::getline(in, text)) {
    ++number;
    if (number == 1 && text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);
    if (!text.empty() && text.back() == '\r') text.pop_back();
    const size_t first = text.find_first_not_of(" \t");
    if (first == std::string::npos || text[first] == '#') continue;
    lines.push_back({number, text.substr(first)});
  }
  if (in.bad()) return Unavailable(path + ": read error after line " + std::to_string(number));
  return lines;
}

Status CheckFileSize(const std::string& path, size_t max_bytes, const std::string& what) {
  std::error_code ec;
  const uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) return Unavailable(path + ": cannot read its size: " + ec.message());
  if (size > max_bytes) {
    return InvalidArgument(path + " is " + std::to_string(size) + " bytes; a " + what +
                           " file holds at most " + std::to_string(max_bytes) + " bytes");
  }
  return Status::Ok();
}

StatusOr<std::string> ReadWholeTextFile(const std::string& path, size_t max_bytes,
                                        const std::string& what) {
  namespace fs = std::filesystem;
  const std::string name = what + " " + path;
  SIGHTLINE_RETURN_IF_ERROR(CheckRegularFile(path, name));
  std::error_code ec;
  const uintmax_t size = fs::file_size(path, ec);
  if (ec) return Unavailable(name + ": cannot read its size: " + ec.message());
  if (size > max_bytes) {
    return InvalidArgument(name + " is " + std::to_string(size) + " bytes; a " + what +
                           " holds at most " + std::to_string(max_bytes));
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) return Unavailable(name + " cannot be read: " + std::strerror(errno));
  std::string text(static_cast<size_t>(size), '\0');
  in.read(text.data(), static_cast<std::streamsize>(size));
  if (in.gcount() != static_cast<std::streamsize>(size)) {
    return Unavailable(name + ": read error (" + std::to_string(in.gcount()) + " of " +
                       std::to_string(size) + " bytes)");
  }
  return text;
}

std::vector<std::string> SplitFields(const std::string& text) {
  std::vector<std::string> fields;
  std::string current;
  for (char c : text) {
    if (c == ' ' || c == '\t' || c == ',' || c == '\r') {
      if (!current.empty()) fields.push_back(std::move(current));
      current.clear();
    } else {
      current.push_back(c);
    }
  }
  if (!current.empty()) fields.push_back(std::move(current));
  return fields;
}

StatusOr<std::vector<double>> ParseNumbers(const DataLine& line, size_t min_count,
                                           const std::string& path) {
  const std::vector<std::string> fields = SplitFields(line.text);
  const std::string where = path + " line " + std::to_string(line.number);
  if (fields.size() < min_count) {
    return ParseError(where + ": expected " + std::to_string(min_count) + " numbers, found " +
                      std::to_string(fields.size()) + " (truncated line?)");
  }
  std::vector<double> values;
  values.reserve(fields.size());
  for (size_t i = 0; i < fields.size(); ++i) {
    const char* begin = fields[i].c_str();
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(begin, &end);
    if (end == begin || *end != '\0') {
      return ParseError(where + ": field " + std::to_string(i + 1) + " '" + fields[i] +
                        "' is not a number");
    }
    if (!std::isfinite(v)) {
      return ParseError(where + ": field " + std::to_string(i + 1) + " is " + fields[i] +
                        " (not finite)");
    }
    values.push_back(v);
  }
  return values;
}

bool FileExists(const std::string& path) {
  std::error_code ec;
  return std::filesystem::is_regular_file(path, ec);
}

bool PathExists(const std::string& path) {
  std::error_code ec;
  return std::filesystem::exists(std::filesystem::symlink_status(path, ec));
}

bool DirectoryExists(const std::string& path) {
  std::error_code ec;
  return std::filesystem::is_directory(path, ec);
}

std::string JoinPath(const std::string& a, const std::string& b) {
  if (a.empty()) return b;
  if (a.back() == '/') return a + b;
  return a + "/" + b;
}

}  // namespace sightline
