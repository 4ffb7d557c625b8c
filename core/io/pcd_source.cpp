// The only Sightline translation unit that includes PCL headers in core/io.
#include "core/io/pcd_source.h"

#include <pcl/PCLPointCloud2.h>
#include <pcl/conversions.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

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

// PCL 1.13's PCDReader::read crashes on some garbage files (no FIELDS, no DATA line) instead of
// failing, so the header is checked here before PCL sees the file.
Status CheckHeaderText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return NotFound(path + ": cannot be opened for reading");
  std::set<std::string> seen;
  std::string line;
  for (int n = 0; n < 64 && std::getline(in, line, '\n'); ++n) {
    if (line.size() > 4096) break;  // Binary junk, not a header line.
    std::istringstream words(line);
    std::string key, value;
    words >> key >> value;
    if (key.empty() || key[0] == '#') continue;
    seen.insert(key);
    if (key == "DATA") {
      if (value != "ascii" && value != "binary" && value != "binary_compressed") {
        return ParseError(path + ": PCD header: unknown DATA type '" + value + "'");
      }
      for (const char* required : {"FIELDS", "SIZE", "TYPE", "WIDTH", "POINTS"}) {
        if (seen.count(required) == 0) {
          return ParseError(path + ": PCD header has no " + std::string(required) + " line");
        }
      }
      return Status::Ok();
    }
  }
  return ParseError(path +
                    ": not a PCD file (no 'DATA ascii|binary|binary_compressed' header "
                    "line)");
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

}  // namespace sightline
