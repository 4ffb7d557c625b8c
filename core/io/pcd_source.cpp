// The only Sightline translation unit that includes PCL headers in core/io.
#include "core/io/pcd_source.h"

#include <pcl/PCLPointCloud2.h>
#include <pcl/conversions.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "core/common/input_limits.h"
#include "core/common/text_file.h"
#include "core/io/file_listing.h"

namespace sightline {
namespace {

bool HasField(const pcl::PCLPointCloud2& blob, const std::string& name) {
  for (const pcl::PCLPointField& f : blob.fields) {
    if (f.name == name) return true;
  }
  return false;
}

// The header's numbers as written, before PCL sees them.
struct HeaderNumbers {
  double width = 0, height = 0, points = 0, point_bytes = 0;
  std::string data;
  std::streamoff data_end = 0;  // File offset just after the DATA line.
};

// Parses "KEY n n n" words as numbers; ParseError naming the line when one is not a count.
StatusOr<std::vector<double>> HeaderCounts(std::istringstream& words, const std::string& key,
                                           const std::string& path) {
  std::vector<double> values;
  for (std::string w; words >> w;) {
    char* end = nullptr;
    const double v = std::strtod(w.c_str(), &end);
    if (end == w.c_str() || *end != '\0' || !(v >= 0) || v != std::floor(v) || v > 4e9) {
      return ParseError(path + ": PCD header " + key + " has '" + w + "', not a count");
    }
    values.push_back(v);
  }
  if (values.empty()) return ParseError(path + ": PCD header " + key + " has no value");
  return values;
}

// Bounds what the header asks PCL to allocate by the file's real size: raw binary stores every
// byte, LZF expands at most ~90x, ascii needs at least two characters per point.
Status CheckDeclaredSize(const HeaderNumbers& h, const std::string& path) {
  if (h.width * h.height != h.points) {
    return ParseError(path + ": PCD header's WIDTH x HEIGHT (" +
                      std::to_string(static_cast<long long>(h.width)) + " x " +
                      std::to_string(static_cast<long long>(h.height)) + ") is not POINTS (" +
                      std::to_string(static_cast<long long>(h.points)) + ")");
  }
  if (h.points > kMaxPcdPoints) {
    return ParseError(path + ": PCD header declares " +
                      std::to_string(static_cast<long long>(h.points)) + " points; at most " +
                      std::to_string(static_cast<long long>(kMaxPcdPoints)) + " are read");
  }
  std::error_code ec;
  const double file_bytes = static_cast<double>(std::filesystem::file_size(path, ec));
  const double available = file_bytes - static_cast<double>(h.data_end);
  const double data_bytes = h.points * h.point_bytes;
  const bool fits = h.data == "binary"              ? data_bytes <= available
                    : h.data == "binary_compressed" ? data_bytes <= 128.0 * available
                                                    : 2.0 * h.points <= available;
  if (ec || !fits) {
    return ParseError(path + ": PCD file is truncated or its header is corrupt: " +
                      std::to_string(static_cast<long long>(h.points)) + " points of " +
                      std::to_string(static_cast<long long>(h.point_bytes)) +
                      " bytes cannot fit in " + std::to_string(static_cast<long long>(available)) +
                      " bytes of data");
  }
  return Status::Ok();
}

// Each field's TYPE and SIZE must name a real type: F of 4 or 8 bytes, I or U of 1, 2, 4 or 8.
// A SIZE value as written (any magnitude; a cast to int overflows for a hostile header).
std::string FormatSize(double size) {
  std::ostringstream out;
  out.precision(15);
  out << size;
  return out.str();
}

Status CheckFieldTypes(const std::vector<std::string>& names, const std::vector<std::string>& types,
                       const std::vector<double>& sizes, const std::string& path) {
  for (size_t i = 0; i < names.size(); ++i) {
    const double size = sizes[i];
    const bool ok = types[i] == "F" ? (size == 4 || size == 8)
                    : (types[i] == "I" || types[i] == "U")
                        ? (size == 1 || size == 2 || size == 4 || size == 8)
                        : false;
    if (!ok) {
      return ParseError(path + ": PCD field '" + names[i] + "' has TYPE " + types[i] +
                        " with SIZE " + FormatSize(size) +
                        " (F is 4 or 8 bytes, I and U 1, 2, 4 or 8)");
    }
  }
  return Status::Ok();
}

// PCL 1.13's PCDReader takes a header line by the prefix of its first word ("WIDTHX" is a
// WIDTH line), stops the header at the first word it does not know, sizes its buffer at POINTS
// with the point size known then (a later SIZE or COUNT line makes the ASCII reader write past
// it), and goes on reading header lines after DATA. The header must therefore be one
// unambiguous list: known keys, each once, in plain text, the field layout before POINTS, and
// no header line where the data begins.
constexpr const char* kPcdKeys[] = {"VERSION", "FIELDS", "COLUMNS",   "SIZE",   "TYPE", "COUNT",
                                    "WIDTH",   "HEIGHT", "VIEWPOINT", "POINTS", "DATA"};

// The header key PCL takes `word` for (by prefix), or "" for none.
std::string PclKeyOf(const std::string& word) {
  for (const char* key : kPcdKeys) {
    if (word.rfind(key, 0) == 0) return key;
  }
  return "";
}

// Printable ASCII, tabs and carriage returns only (PCL and this check split words alike).
bool IsPlainHeaderText(const std::string& line) {
  for (const unsigned char c : line) {
    if (c != '\t' && c != '\r' && (c < 0x20 || c >= 0x7f)) return false;
  }
  return true;
}

// One header line before DATA: ParseError naming the line for what PCL would read otherwise.
Status CheckHeaderKey(const std::string& line, const std::string& key, int line_number,
                      const std::set<std::string>& seen, const std::string& path) {
  const std::string where = path + ": PCD header line " + std::to_string(line_number) + ": ";
  if (!IsPlainHeaderText(line)) return ParseError(where + "holds control or non-ASCII bytes");
  if (key.empty()) return ParseError(where + "is blank but not empty (ends the header early)");
  const std::string pcl_key = PclKeyOf(key);
  if (pcl_key.empty()) return ParseError(where + "unknown key '" + key + "'");
  if (pcl_key != key) {
    return ParseError(where + "'" + key + "' is not a header key (PCL would take it for " +
                      pcl_key + ")");
  }
  if (key == "COLUMNS") return ParseError(where + "COLUMNS (PCD 0.5) is not read; use FIELDS");
  if (seen.count(key)) return ParseError(where + "repeats the " + key + " line");
  const bool layout = key == "FIELDS" || key == "SIZE" || key == "TYPE" || key == "COUNT";
  if (layout && seen.count("POINTS")) {
    return ParseError(where + key + " must come before POINTS (the point size is fixed there)");
  }
  return Status::Ok();
}

// The lines PCL still reads as header after DATA: empty lines are skipped, a '#' line is skipped
// by the header but read as a point by the ASCII body, and a line whose first word starts like a
// key would be taken as one. Reads at most 64 KiB.
Status CheckDataStart(std::ifstream& in, const std::string& path) {
  std::string chunk(64 * 1024, '\0');
  in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
  chunk.resize(static_cast<size_t>(in.gcount()));
  size_t begin = 0;
  while (begin < chunk.size()) {
    const size_t end = std::min(chunk.find('\n', begin), chunk.size());
    const std::string line = chunk.substr(begin, end - begin);
    begin = end + 1;
    if (line.empty()) continue;
    std::istringstream words(line);
    std::string first;
    words >> first;
    if (!first.empty() && first[0] == '#') {
      // PCL's header skips it, but its ASCII body reads it as a malformed point.
      return ParseError(path + ": PCD data begins with a '#' line, which PCL would read as a " +
                        "malformed point");
    }
    if (!PclKeyOf(first).empty()) {
      return ParseError(path + ": PCD data begins with a header line ('" + first.substr(0, 16) +
                        "'), which PCL would read as part of the header");
    }
    return Status::Ok();
  }
  return in.eof() ? Status::Ok()
                  : ParseError(path + ": PCD data begins with over 64 KiB of empty lines");
}

// PCL 1.13's PCDReader crashes on some garbage files (no FIELDS, no DATA line) and allocates
// what a header declares before checking it, so the header is read and bounded here first.
Status CheckHeaderText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return NotFound(path + ": cannot be opened for reading");
  std::set<std::string> seen;
  HeaderNumbers h;
  std::vector<double> sizes, counts;
  std::vector<std::string> names, types;
  std::string line;
  for (int n = 0; n < 64 && std::getline(in, line, '\n'); ++n) {
    if (line.size() > 4096) break;  // Binary junk, not a header line.
    if (line.empty()) continue;
    std::istringstream words(line);
    std::string key;
    words >> key;
    if (!key.empty() && key[0] == '#') continue;
    SIGHTLINE_RETURN_IF_ERROR(CheckHeaderKey(line, key, n + 1, seen, path));
    seen.insert(key);
    if (key == "WIDTH" || key == "HEIGHT" || key == "POINTS" || key == "SIZE" || key == "COUNT") {
      StatusOr<std::vector<double>> values = HeaderCounts(words, key, path);
      if (!values.ok()) return values.status();
      if (key == "SIZE") sizes = *values;
      if (key == "COUNT") counts = *values;
      if (key == "WIDTH") h.width = values->front();
      if (key == "HEIGHT") h.height = values->front();
      if (key == "POINTS") h.points = values->front();
      continue;
    }
    if (key == "FIELDS" || key == "TYPE") {
      for (std::string w; words >> w;) (key == "FIELDS" ? names : types).push_back(w);
      continue;
    }
    if (key != "DATA") continue;
    words >> h.data;
    if (h.data != "ascii" && h.data != "binary" && h.data != "binary_compressed") {
      return ParseError(path + ": PCD header: unknown DATA type '" + h.data + "'");
    }
    for (const char* required : {"FIELDS", "SIZE", "TYPE", "WIDTH", "POINTS"}) {
      if (seen.count(required) == 0) {
        return ParseError(path + ": PCD header has no " + std::string(required) + " line");
      }
    }
    if (seen.count("HEIGHT") == 0) h.height = 1;
    if ((!counts.empty() && counts.size() != sizes.size()) || types.size() != sizes.size() ||
        names.size() != sizes.size()) {
      return ParseError(path +
                        ": PCD header's FIELDS, SIZE, TYPE and COUNT list different "
                        "numbers of fields");
    }
    SIGHTLINE_RETURN_IF_ERROR(CheckFieldTypes(names, types, sizes, path));
    for (size_t i = 0; i < sizes.size(); ++i)
      h.point_bytes += sizes[i] * (counts.empty() ? 1 : counts[i]);
    h.data_end = in.tellg();
    SIGHTLINE_RETURN_IF_ERROR(CheckDataStart(in, path));
    return CheckDeclaredSize(h, path);
  }
  return ParseError(path +
                    ": not a PCD file (no 'DATA ascii|binary|binary_compressed' header "
                    "line)");
}

// Checks what PCL takes on trust: each field's type and size agree (F is 4 or 8 bytes, I and U
// 1, 2, 4 or 8), x y z are 4-byte floats and rgb/rgba 4 bytes (the point conversions assume
// both), COUNT >= 1, and the point's size is the sum of its fields.
Status CheckFields(const pcl::PCLPointCloud2& header, const std::string& path) {
  size_t step = 0;
  for (const pcl::PCLPointField& f : header.fields) {
    const size_t size = pcl::getFieldSize(f.datatype);
    if (size == 0) {
      return ParseError(path + ": PCD field '" + f.name + "' has an unknown TYPE/SIZE pair");
    }
    if (f.count < 1) return ParseError(path + ": PCD field '" + f.name + "' has COUNT 0");
    const bool xyz = f.name == "x" || f.name == "y" || f.name == "z";
    if (xyz && (f.datatype != pcl::PCLPointField::FLOAT32 || f.count != 1)) {
      return ParseError(path + ": PCD field '" + f.name +
                        "' must be one 4-byte float (TYPE F, SIZE 4, COUNT 1)");
    }
    if ((f.name == "rgb" || f.name == "rgba") && size != 4) {
      return ParseError(path + ": PCD field '" + f.name + "' must be 4 bytes");
    }
    if (f.offset != step) {
      return ParseError(path + ": PCD field '" + f.name + "' does not follow the one before it");
    }
    step += size * f.count;
  }
  if (step != header.point_step) {
    return ParseError(path + ": PCD fields add up to " + std::to_string(step) +
                      " bytes but the point size is " + std::to_string(header.point_step));
  }
  return Status::Ok();
}

// For DATA binary_compressed: the two sizes in front of the LZF block must describe exactly the
// declared points and a block that the file holds.
Status CheckCompressedSizes(const std::string& path, unsigned int data_index, double file_bytes,
                            double data_bytes) {
  std::ifstream in(path, std::ios::binary);
  in.seekg(data_index);
  uint32_t sizes[2] = {0, 0};
  in.read(reinterpret_cast<char*>(sizes), sizeof(sizes));
  if (!in) return ParseError(path + ": PCD binary_compressed data is cut off before its sizes");
  const double compressed = sizes[0], uncompressed = sizes[1];
  if (compressed == 0 || compressed > file_bytes - data_index - 8) {
    return ParseError(path + ": PCD binary_compressed block of " + std::to_string(sizes[0]) +
                      " bytes does not fit in the file (" +
                      std::to_string(static_cast<long long>(file_bytes - data_index - 8)) +
                      " bytes after the header)");
  }
  if (uncompressed != data_bytes) {
    return ParseError(path + ": PCD binary_compressed block expands to " +
                      std::to_string(sizes[1]) + " bytes but the header's points need " +
                      std::to_string(static_cast<long long>(data_bytes)));
  }
  return Status::Ok();
}

// Reads only the header: size, fields and viewpoint. ParseError naming the file.
StatusOr<pcl::PCLPointCloud2> ReadHeader(const std::string& path, Eigen::Vector4f* origin,
                                         Eigen::Quaternionf* orientation) {
  SIGHTLINE_RETURN_IF_ERROR(CheckHeaderText(path));
  pcl::PCLPointCloud2 header;
  int data_type = 0;
  unsigned int data_index = 0;
  try {
    pcl::PCDReader reader;
    int version = 0;
    if (reader.readHeader(path, header, *origin, *orientation, version, data_type, data_index) <
        0) {
      return ParseError(path + ": not a readable PCD file (bad or missing header)");
    }
  } catch (const std::exception& e) {
    return ParseError(path + ": not a readable PCD file (" + e.what() + ")");
  } catch (...) {
    return ParseError(path + ": not a readable PCD file");
  }
  if (!HasField(header, "x") || !HasField(header, "y") || !HasField(header, "z")) {
    return ParseError(path + ": PCD file has no x y z fields");
  }
  if (header.point_step == 0 || header.width == 0 || header.height == 0) {
    return ParseError(path + ": PCD header declares no points or no point size");
  }
  SIGHTLINE_RETURN_IF_ERROR(CheckFields(header, path));
  if (static_cast<double>(header.width) * header.height > kMaxPcdPoints) {
    return ParseError(path + ": PCD header declares " + std::to_string(header.width) + " x " +
                      std::to_string(header.height) + " points; at most " +
                      std::to_string(static_cast<long long>(kMaxPcdPoints)) + " are read");
  }
  // Bound what PCL will allocate by what the file can hold, so a corrupt POINTS or WIDTH
  // fails here instead of exhausting memory: raw binary stores every byte, LZF expands at most
  // ~90x, ascii needs at least two characters per point.
  std::error_code ec;
  const double file_bytes = static_cast<double>(std::filesystem::file_size(path, ec));
  const double points = static_cast<double>(header.width) * header.height;
  const double data_bytes = points * header.point_step;
  const double available = file_bytes - data_index;
  const bool fits = data_type == 1   ? data_bytes <= available
                    : data_type == 2 ? data_bytes <= 128.0 * available
                                     : 2.0 * points <= available;
  if (ec || !fits) {
    return ParseError(path + ": PCD file is truncated or its header is corrupt: " +
                      std::to_string(static_cast<long long>(points)) + " points of " +
                      std::to_string(header.point_step) + " bytes cannot fit in " +
                      std::to_string(static_cast<long long>(available)) + " bytes of data");
  }
  if (data_type == 2) {
    SIGHTLINE_RETURN_IF_ERROR(CheckCompressedSizes(path, data_index, file_bytes, data_bytes));
  }
  return header;
}

template <typename PointT>
void CopyPoints(const pcl::PointCloud<PointT>& in, PointCloud* out) {
  out->points.reserve(in.size());
  for (const PointT& p : in.points) out->points.emplace_back(p.x, p.y, p.z);
}

}  // namespace

StatusOr<PointCloud> ReadPcdFile(const std::string& path) {
  if (!FileExists(path)) return NotFound(path + ": no such file");
  pcl::PCLPointCloud2 blob;
  Eigen::Vector4f origin = Eigen::Vector4f::Zero();
  Eigen::Quaternionf orientation = Eigen::Quaternionf::Identity();
  auto header = ReadHeader(path, &origin, &orientation);
  if (!header.ok()) return header.status();
  int version = 0;
  PointCloud cloud;
  try {
    pcl::PCDReader reader;
    if (reader.read(path, blob, origin, orientation, version) < 0) {
      return ParseError(path + ": not a readable PCD file (bad header or truncated data)");
    }
    if (!HasField(blob, "x") || !HasField(blob, "y") || !HasField(blob, "z")) {
      return ParseError(path + ": PCD file has no x y z fields");
    }
    const size_t expected = static_cast<size_t>(blob.width) * blob.height * blob.point_step;
    if (blob.data.size() < expected) {
      return ParseError(path + ": PCD data holds " + std::to_string(blob.data.size()) +
                        " bytes, the header promises " + std::to_string(expected));
    }
    if (HasField(blob, "rgb") || HasField(blob, "rgba")) {
      pcl::PointCloud<pcl::PointXYZRGBA> points;
      pcl::fromPCLPointCloud2(blob, points);
      CopyPoints(points, &cloud);
      cloud.colors.reserve(points.size());
      for (const pcl::PointXYZRGBA& p : points.points) cloud.colors.emplace_back(p.r, p.g, p.b);
    } else {
      pcl::PointCloud<pcl::PointXYZ> points;
      pcl::fromPCLPointCloud2(blob, points);
      CopyPoints(points, &cloud);
    }
  } catch (const std::exception& e) {
    return ParseError(path + ": not a readable PCD file (" + e.what() + ")");
  } catch (...) {
    return ParseError(path + ": not a readable PCD file");
  }
  if (blob.height > 1) {
    cloud.width = static_cast<int>(blob.width);
    cloud.height = static_cast<int>(blob.height);
  } else {
    cloud.width = static_cast<int>(cloud.size());
    cloud.height = 1;
  }
  return cloud;
}

std::optional<double> TimeFromFileName(const std::string& file_name) {
  std::string stem = file_name;
  if (HasExtension(stem, {".pcd"})) stem.resize(stem.size() - 4);
  static const std::regex kSeconds(R"(^\d+(\.\d+)?$)");
  static const std::regex kGrabber(R"((\d{4})(\d{2})(\d{2})T(\d{2})(\d{2})(\d{2})(\.\d+)?)");
  std::smatch m;
  if (std::regex_match(stem, kSeconds)) return std::stod(stem);
  if (std::regex_search(stem, m, kGrabber)) {
    std::tm tm{};
    tm.tm_year = std::stoi(m[1]) - 1900;
    tm.tm_mon = std::stoi(m[2]) - 1;
    tm.tm_mday = std::stoi(m[3]);
    tm.tm_hour = std::stoi(m[4]);
    tm.tm_min = std::stoi(m[5]);
    tm.tm_sec = std::stoi(m[6]);
    const double fraction = m[7].matched ? std::stod("0" + m[7].str()) : 0.0;
    return static_cast<double>(timegm(&tm)) + fraction;
  }
  return std::nullopt;
}

Status PcdSource::Open() {
  SourceInfo info;
  info.format = "PCD";
  info.path = path_;
  info.kind = SourceKind::kCloud;
  std::vector<std::string> files;
  if (FileExists(path_)) {
    files.push_back(path_);
  } else if (DirectoryExists(path_)) {
    auto names = ListFiles(path_, {".pcd"});
    if (!names.ok()) return names.status();
    if (names->empty()) return NotFound(path_ + ": no .pcd files in this folder");
    for (const std::string& name : *names) files.push_back(JoinPath(path_, name));
  } else {
    return NotFound(path_ + ": no such file or folder");
  }

  // Headers are cheap: read them all so a broken file fails here, not mid-run.
  for (size_t i = 0; i < files.size(); ++i) {
    Eigen::Vector4f origin = Eigen::Vector4f::Zero();
    Eigen::Quaternionf orientation = Eigen::Quaternionf::Identity();
    auto header = ReadHeader(files[i], &origin, &orientation);
    if (!header.ok()) return header.status();
    if (i > 0) continue;
    info.width = static_cast<int>(header->width);
    info.height = static_cast<int>(header->height);
    if (!HasField(*header, "rgb") && !HasField(*header, "rgba")) {
      info.notes.push_back("no colour fields (x y z only)");
    }
    if (origin.head<3>().norm() > 1e-9 ||
        orientation.angularDistance(Eigen::Quaternionf::Identity()) > 1e-6) {
      info.notes.push_back("PCD VIEWPOINT is not identity; points are kept in the file's frame");
    }
  }

  std::vector<double> times;
  for (const std::string& file : files) {
    const std::optional<double> t = TimeFromFileName(BaseName(file));
    if (!t || (!times.empty() && *t <= times.back())) {
      times.clear();
      break;
    }
    times.push_back(*t);
  }
  if (times.size() == files.size() && files.size() > 1) {
    info.notes.push_back("timestamps from the file names");
  } else if (files.size() == 1) {
    times.assign(1, TimeFromFileName(BaseName(files.front())).value_or(0.0));
  } else {
    if (!(default_rate_hz_ > 0)) {
      return InvalidArgument("PCD rate " + std::to_string(default_rate_hz_) +
                             " Hz must be positive");
    }
    times.clear();
    for (size_t i = 0; i < files.size(); ++i) {
      times.push_back(static_cast<double>(i) / default_rate_hz_);
    }
    info.rate_hz = default_rate_hz_;
    char note[120];
    std::snprintf(note, sizeof(note),
                  "no timestamps in the file names: synthesized at %g Hz (t = index / rate)",
                  default_rate_hz_);
    info.notes.push_back(note);
  }
  files_ = std::move(files);
  return Commit(std::move(info), std::move(times), std::nullopt);
}

StatusOr<Frame> PcdSource::Load(int64_t index) {
  auto cloud = ReadPcdFile(files_[static_cast<size_t>(index)]);
  if (!cloud.ok()) return cloud.status();
  CloudFrame frame;
  frame.cloud = std::make_shared<const PointCloud>(std::move(*cloud));
  frame.stamp = MakeStamp(index);
  return Frame(std::move(frame));
}

std::unique_ptr<Source> MakePcdSource(const std::string& path) {
  return std::make_unique<PcdSource>(path);
}

}  // namespace sightline
