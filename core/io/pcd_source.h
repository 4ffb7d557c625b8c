// Reader for PCL .pcd point clouds: one file or a folder of them. PCL stays inside the .cpp.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/common/frame.h"
#include "core/io/recorded_source.h"

namespace sightline {

// Reads one .pcd file (ascii, binary or binary_compressed) with x y z and optional rgb/rgba
// fields. Organized clouds keep their width x height, invalid points stay NaN. ParseError naming
// the file for anything PCL cannot read (PCL also prints its own message to stderr).
StatusOr<PointCloud> ReadPcdFile(const std::string& path);

// A .pcd file (one frame) or a folder of .pcd files (natural name order) as point clouds.
//
// Timestamps come from the file names when every name holds one: a number of seconds
// ("1305031453.359684.pcd") or a PCL grabber stamp ("frame_20121214T142255.814212.pcd", UTC).
// Otherwise time = index / default_rate_hz, and info().notes says so. info().width/height is
// the first cloud's (columns x rows when organized). Points are in the file's frame; a
// non-identity VIEWPOINT is reported in the notes, not applied.
//
//   PcdSource source("../shared/data/pcl_clouds/office1.pcd");
//   if (Status s = source.Open(); !s.ok()) return s;
//   source.Grab();
//   auto frame = source.Retrieve();  // CloudFrame
class PcdSource : public RecordedSource {
 public:
  // `default_rate_hz` is used to synthesize times when file names hold none.
  explicit PcdSource(std::string path, double default_rate_hz = 30.0)
      : path_(std::move(path)), default_rate_hz_(default_rate_hz) {}

  // File readers need no driver: always Ok.
  static Status Available() { return Status::Ok(); }

  // Lists the files and reads every header (a corrupt file fails here).
  Status Open() override;

  // Full paths of the frames' files, in frame order.
  const std::vector<std::string>& files() const { return files_; }

 protected:
  // Decodes frame `index`.
  StatusOr<Frame> Load(int64_t index) override;

 private:
  std::string path_;
  double default_rate_hz_;
  std::vector<std::string> files_;
};

// A PcdSource for `path`, not yet opened; what OpenDataset() reads PCD datasets with. Defined in
// pcd_source.cpp (sightline_io); in sightline_io_readers, which lacks PCL, by
// pcd_source_elsewhere.cpp: a source whose Open() says sightline-cli-full reads PCD clouds.
std::unique_ptr<Source> MakePcdSource(const std::string& path);

// The time a file name encodes (see PcdSource), or nullopt. Exposed for tests.
std::optional<double> TimeFromFileName(const std::string& file_name);

}  // namespace sightline
