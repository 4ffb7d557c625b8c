// The run loop's sources in sightline_pipeline_stereo: recorded datasets through core/io's
// readers. A sensor URI, an .oni or .bag file or sim:// fails with a message saying which program
// opens it (front ends hand those to sightline-cli-full before they get here).
#include <cctype>

#include "core/io/dataset.h"
#include "core/pipeline/run_sources.h"

namespace sightline {
namespace {

bool EndsWithNoCase(const std::string& text, const std::string& suffix) {
  if (text.size() < suffix.size()) return false;
  for (size_t i = 0; i < suffix.size(); ++i) {
    const char c = text[text.size() - suffix.size() + i];
    if (std::tolower(static_cast<unsigned char>(c)) != suffix[i]) return false;
  }
  return true;
}

}  // namespace

bool IsRunSourceLive(const std::string& uri) {
  return uri.find("://") != std::string::npos || EndsWithNoCase(uri, ".bag") ||
         EndsWithNoCase(uri, ".oni");
}

StatusOr<std::unique_ptr<Source>> OpenLiveRunSource(const std::string& uri, const OptionSet&) {
  return Unavailable(uri +
                     ": sensors, ROS bags and sim:// sources are run by sightline-cli-full; "
                     "this program reads recorded datasets only");
}

StatusOr<std::unique_ptr<Source>> OpenAnyRunSource(const std::string& uri,
                                                   const OptionSet& options) {
  if (IsRunSourceLive(uri)) return OpenLiveRunSource(uri, options);
  return OpenDataset(uri);
}

Status DeclareRunSourceOptions(const std::string&, OptionSet*) { return Status::Ok(); }

Status PrepareRunSource(const std::string&, const std::string&, OptionSet*) { return Status::Ok(); }

}  // namespace sightline
