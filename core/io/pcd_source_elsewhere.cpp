// MakePcdSource for sightline_io_readers, the readers without PCL: a source whose Open() says
// that sightline-cli-full reads PCD clouds. The programs that link these readers (the CLI's front
// binary, sightline-cli-stereo) hand PCD paths to the full program before opening anything, so
// this is reached only if that check misses one, and then fails with a message.
#include <memory>
#include <string>

#include "core/io/pcd_source.h"
#include "core/io/recorded_source.h"

namespace sightline {
namespace {

class PcdInFullProgram : public RecordedSource {
 public:
  explicit PcdInFullProgram(std::string path) : path_(std::move(path)) {}
  Status Open() override {
    return Unavailable(path_ + ": PCD clouds are read by sightline-cli-full");
  }

 protected:
  StatusOr<Frame> Load(int64_t) override { return Unavailable(path_ + ": not open"); }

 private:
  std::string path_;
};

}  // namespace

std::unique_ptr<Source> MakePcdSource(const std::string& path) {
  return std::make_unique<PcdInFullProgram>(path);
}

}  // namespace sightline
