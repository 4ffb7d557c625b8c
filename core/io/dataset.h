// Opening any recorded dataset by path: format detection, recordings with one sub-folder per
// sensor, and the `sightline-cli info` description (source_description.h).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/io/source.h"
#include "core/io/source_description.h"

namespace sightline {

// The dataset layouts Sightline reads.
enum class DatasetFormat { kTumRgbd, kEuroc, kKitti, kPcd, kImageFolder };

// "TUM RGB-D", "EuRoC MAV", "KITTI odometry", "PCD", "image folder" (as SourceInfo::format).
const char* DatasetFormatName(DatasetFormat format);
// The kind of frames a format yields.
SourceKind DatasetKind(DatasetFormat format);

// A dataset found at a path.
struct DetectedDataset {
  std::string path;
  DatasetFormat format = DatasetFormat::kImageFolder;
  SourceKind kind = SourceKind::kMono;
};

// What `path` itself holds, without looking into sub-folders, checked in this order:
// TUM (rgb.txt + depth.txt, or associations.txt), EuRoC (mav0/cam0, or path is mav0 with cam0/),
// KITTI (calib.txt + image_0/ or image_l/), PCD (a .pcd file, or a folder with .pcd files),
// image folder (a folder with .png/.jpg images). nullopt when none matches.
std::optional<DetectedDataset> DetectDataset(const std::string& path);

// The immediate sub-folders of a recording folder that are datasets, one per sensor (e.g.
// rec/rgbd TUM, rec/stereo KITTI, rec/mono image folder), in natural name order.
std::vector<DetectedDataset> FindRecordingSensors(const std::string& path);
// The paths of FindRecordingSensors(path).
std::vector<std::string> ListRecordingSensors(const std::string& path);

// A reader for a detected dataset, not yet opened.
std::unique_ptr<Source> MakeDatasetSource(const DetectedDataset& dataset);

// Detects the format of `path`, opens it and returns the open source. When `path` is no dataset
// itself but a recording with sensor sub-folders, opens the sub-folder whose kind is `want`, or
// the RGB-D one (else stereo, else mono, else the first) when `want` is unset. Errors: NotFound for
// a missing path or a recording without a sensor of kind `want`; InvalidArgument for a path that is
// not a dataset (the message lists what was looked for) or a dataset of another kind than `want`;
// else the reader's own error.
//
//   auto source = OpenDataset("rec", SourceKind::kStereo);
//   if (!source.ok()) return source.status();
//   std::cout << DescribeSourceText(**source);
StatusOr<std::unique_ptr<Source>> OpenDataset(const std::string& path,
                                              std::optional<SourceKind> want = std::nullopt);

}  // namespace sightline
