#include "core/io/image_folder_source.h"

#include <cstdio>
#include <cstdlib>

#include "core/common/text_file.h"
#include "core/io/camera_yaml.h"
#include "core/io/file_listing.h"
#include "core/io/image_loading.h"
#include "core/io/timed_file_list.h"

namespace sightline {
namespace {

// True when the list's first data line reads "time filename" rather than just "time".
StatusOr<bool> ListsFileNames(const std::string& path) {
  auto lines = ReadDataLines(path);
  if (!lines.ok()) return lines.status();
  if (lines->empty()) return false;
  const std::vector<std::string> fields = SplitFields(lines->front().text);
  if (fields.size() < 2) return false;
  char* end = nullptr;
  std::strtod(fields[1].c_str(), &end);
  return end == fields[1].c_str() || *end != '\0';  // Second field is not a number.
}

}  // namespace

Status ImageFolderSource::Open() {
  if (!DirectoryExists(folder_)) return NotFound(folder_ + ": no such folder");
  SourceInfo info;
  info.format = "image folder";
  info.path = folder_;
  info.kind = SourceKind::kMono;

  std::optional<CameraFile> camera_file;
  if (const std::string yaml = JoinPath(folder_, kCameraYamlName); PathExists(yaml)) {
    auto read = ReadCameraYaml(yaml);
    if (!read.ok()) return read.status();
    camera_file = std::move(*read);
  }

  std::string times_path;
  for (const char* name : {"times.txt", "timestamps.txt"}) {
    if (PathExists(JoinPath(folder_, name))) {
      times_path = JoinPath(folder_, name);
      break;
    }
  }
  std::vector<std::string> files;
  std::vector<double> times;
  auto names = ListFiles(folder_, ImageExtensions());
  if (!names.ok()) return names.status();
  auto lists_files = times_path.empty() ? StatusOr<bool>(false) : ListsFileNames(times_path);
  if (!lists_files.ok()) return lists_files.status();
  if (*lists_files) {
    auto list = ReadTimedFileList(times_path);
    if (!list.ok()) return list.status();
    for (const TimedFile& entry : *list) {
      files.push_back(JoinPath(folder_, entry.file));
      times.push_back(entry.time_s);
      if (!FileExists(files.back())) {
        return NotFound(files.back() + ": no such file (listed in " + times_path + " line " +
                        std::to_string(entry.line) + ")");
      }
    }
    info.notes.push_back("frames and timestamps from " + BaseName(times_path));
  } else {
    for (const std::string& name : *names) files.push_back(JoinPath(folder_, name));
    if (!times_path.empty()) {
      auto read = ReadTimesFile(times_path);
      if (!read.ok()) return read.status();
      if (read->size() != files.size()) {
        return ParseError(times_path + ": " + std::to_string(read->size()) + " times for " +
                          std::to_string(files.size()) + " images");
      }
      times = std::move(*read);
      info.notes.push_back("timestamps from " + BaseName(times_path));
    } else {
      const double rate =
          camera_file && camera_file->rate_hz ? *camera_file->rate_hz : default_rate_hz_;
      if (!(rate > 0))
        return InvalidArgument("image folder rate " + std::to_string(rate) +
                               " Hz must be positive");
      for (size_t i = 0; i < files.size(); ++i) times.push_back(static_cast<double>(i) / rate);
      info.rate_hz = rate;
      char note[120];
      std::snprintf(note, sizeof(note),
                    "no times.txt: timestamps synthesized at %g Hz (t = index / rate)", rate);
      info.notes.push_back(note);
    }
  }
  if (files.empty()) {
    return NotFound(folder_ + ": no images (.png .jpg .jpeg .bmp .pgm .ppm)");
  }
  // The times' readers checked that they increase (synthesized ones do).

  auto first = LoadImage8(files.front());
  if (!first.ok()) return first.status();
  info.width = first->cols;
  info.height = first->rows;
  if (camera_file) {
    const PinholeCamera& c = camera_file->camera;
    if (c.width != info.width || c.height != info.height) {
      return ParseError(JoinPath(folder_, kCameraYamlName) + ": camera is " +
                        std::to_string(c.width) + "x" + std::to_string(c.height) + " but " +
                        files.front() + " is " + std::to_string(info.width) + "x" +
                        std::to_string(info.height));
    }
    info.camera = c;
    if (camera_file->rate_hz) info.rate_hz = *camera_file->rate_hz;
    info.notes.push_back("intrinsics from camera.yaml");
  } else {
    info.notes.push_back("no camera.yaml: intrinsics unknown");
  }
  files_ = std::move(files);
  return Commit(std::move(info), std::move(times), std::nullopt);
}

StatusOr<Frame> ImageFolderSource::Load(int64_t index) {
  auto image = LoadImage8(files_[static_cast<size_t>(index)]);
  if (!image.ok()) return image.status();
  MonoFrame frame;
  frame.image = std::move(*image);
  frame.stamp = MakeStamp(index);
  return Frame(std::move(frame));
}

std::string ImageFolderSource::FrameFile(int64_t index) const {
  return files_[static_cast<size_t>(index)];
}

}  // namespace sightline
