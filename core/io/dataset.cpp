#include "core/io/dataset.h"

#include "core/common/text_file.h"
#include "core/io/euroc_source.h"
#include "core/io/file_listing.h"
#include "core/io/image_folder_source.h"
#include "core/io/kitti_source.h"
#include "core/io/pcd_source.h"
#include "core/io/tum_rgbd_source.h"

namespace sightline {
namespace {

constexpr const char* kLookedFor =
    "looked for rgb.txt + depth.txt (TUM RGB-D), mav0/cam0/ (EuRoC), calib.txt + image_0/ or "
    "image_l/ (KITTI), a .pcd file or a folder of .pcd files (PCD), a folder of .png/.jpg "
    "images (image folder), or sub-folders holding one of these (a recording)";

bool HasFilesWith(const std::string& dir, const std::vector<std::string>& extensions) {
  auto names = ListFiles(dir, extensions);
  return names.ok() && !names->empty();
}

std::string Describe(const DetectedDataset& d) {
  return BaseName(d.path) + " (" + DatasetFormatName(d.format) + ", " + SourceKindName(d.kind) +
         ")";
}

StatusOr<std::unique_ptr<Source>> OpenDetected(const DetectedDataset& dataset) {
  std::unique_ptr<Source> source = MakeDatasetSource(dataset);
  SIGHTLINE_RETURN_IF_ERROR(source->Open());
  return source;
}

}  // namespace

const char* DatasetFormatName(DatasetFormat format) {
  switch (format) {
    case DatasetFormat::kTumRgbd:
      return "TUM RGB-D";
    case DatasetFormat::kEuroc:
      return "EuRoC MAV";
    case DatasetFormat::kKitti:
      return "KITTI odometry";
    case DatasetFormat::kPcd:
      return "PCD";
    case DatasetFormat::kImageFolder:
      return "image folder";
  }
  return "unknown";
}

SourceKind DatasetKind(DatasetFormat format) {
  switch (format) {
    case DatasetFormat::kTumRgbd:
      return SourceKind::kRgbd;
    case DatasetFormat::kEuroc:
    case DatasetFormat::kKitti:
      return SourceKind::kStereo;
    case DatasetFormat::kPcd:
      return SourceKind::kCloud;
    case DatasetFormat::kImageFolder:
      return SourceKind::kMono;
  }
  return SourceKind::kMono;
}

std::optional<DetectedDataset> DetectDataset(const std::string& path) {
  auto found = [&](DatasetFormat format) {
    return DetectedDataset{path, format, DatasetKind(format)};
  };
  if (FileExists(path)) {
    if (HasExtension(path, {".pcd"})) return found(DatasetFormat::kPcd);
    return std::nullopt;
  }
  if (!DirectoryExists(path)) return std::nullopt;
  auto has = [&](const char* name) { return FileExists(JoinPath(path, name)); };
  auto has_dir = [&](const char* name) { return DirectoryExists(JoinPath(path, name)); };
  if ((has("rgb.txt") && has("depth.txt")) || has("associations.txt")) {
    return found(DatasetFormat::kTumRgbd);
  }
  if (DirectoryExists(JoinPath(path, "mav0/cam0")) || (has_dir("cam0") && has_dir("cam1"))) {
    return found(DatasetFormat::kEuroc);
  }
  if (has("calib.txt") && (has_dir("image_0") || has_dir("image_l"))) {
    return found(DatasetFormat::kKitti);
  }
  if (HasFilesWith(path, {".pcd"})) return found(DatasetFormat::kPcd);
  if (HasFilesWith(path, ImageExtensions())) return found(DatasetFormat::kImageFolder);
  return std::nullopt;
}

std::vector<DetectedDataset> FindRecordingSensors(const std::string& path) {
  std::vector<DetectedDataset> sensors;
  if (!DirectoryExists(path)) return sensors;
  for (const std::string& name : ListSubfolders(path)) {
    if (auto d = DetectDataset(JoinPath(path, name))) sensors.push_back(std::move(*d));
  }
  return sensors;
}

std::vector<std::string> ListRecordingSensors(const std::string& path) {
  std::vector<std::string> paths;
  for (const DetectedDataset& d : FindRecordingSensors(path)) paths.push_back(d.path);
  return paths;
}

std::unique_ptr<Source> MakeDatasetSource(const DetectedDataset& dataset) {
  switch (dataset.format) {
    case DatasetFormat::kTumRgbd:
      return std::make_unique<TumRgbdSource>(dataset.path);
    case DatasetFormat::kEuroc:
      return std::make_unique<EurocSource>(dataset.path);
    case DatasetFormat::kKitti:
      return std::make_unique<KittiSource>(dataset.path);
    case DatasetFormat::kPcd:
      return MakePcdSource(dataset.path);
    case DatasetFormat::kImageFolder:
      return std::make_unique<ImageFolderSource>(dataset.path);
  }
  return std::make_unique<ImageFolderSource>(dataset.path);
}

StatusOr<std::unique_ptr<Source>> OpenDataset(const std::string& path,
                                              std::optional<SourceKind> want) {
  if (!FileExists(path) && !DirectoryExists(path)) {
    return NotFound(path + ": no such file or folder");
  }
  if (std::optional<DetectedDataset> dataset = DetectDataset(path)) {
    if (want && dataset->kind != *want) {
      return InvalidArgument(path + " is a " + DatasetFormatName(dataset->format) + " dataset (" +
                             SourceKindName(dataset->kind) + "), not " + SourceKindName(*want));
    }
    return OpenDetected(*dataset);
  }
  if (FileExists(path)) return InvalidArgument(path + ": not a dataset file; " + kLookedFor);
  const std::vector<DetectedDataset> sensors = FindRecordingSensors(path);
  if (sensors.empty()) return InvalidArgument(path + ": not a dataset; " + kLookedFor);
  if (!want) {
    // Without a wish, the richest sensor: RGB-D, then stereo, mono, point clouds.
    for (SourceKind kind : {SourceKind::kRgbd, SourceKind::kStereo, SourceKind::kMono}) {
      for (const DetectedDataset& sensor : sensors) {
        if (sensor.kind == kind) return OpenDetected(sensor);
      }
    }
    return OpenDetected(sensors.front());
  }
  for (const DetectedDataset& sensor : sensors) {
    if (sensor.kind == *want) return OpenDetected(sensor);
  }
  std::string found;
  for (const DetectedDataset& sensor : sensors) {
    found += (found.empty() ? "" : ", ") + Describe(sensor);
  }
  return NotFound(path + ": the recording has no " + SourceKindName(*want) +
                  " sensor; its sub-folders hold " + found);
}

}  // namespace sightline
