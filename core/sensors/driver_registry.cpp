#include "core/sensors/driver_registry.h"

#include <cctype>
#include <fstream>

#include "core/common/text_file.h"
#include "core/io/dataset.h"
#include "core/io/rosbag_options.h"
#include "core/sensors/aravis_options.h"
#include "core/sensors/openni2_options.h"
#include "core/sensors/replay_source.h"
#include "core/sensors/sensor_options.h"
#include "core/sensors/v4l2_source.h"

#ifdef SIGHTLINE_HAVE_OPENNI2
#include "core/sensors/openni2_source.h"
#endif
#ifdef SIGHTLINE_HAVE_ROS
#include "core/ros/bag_source.h"
#endif
#ifdef SIGHTLINE_HAVE_ARAVIS
#include "core/sensors/aravis_source.h"
#include "core/sensors/aravis_stereo_source.h"
#endif

namespace sightline {
namespace {

constexpr char kOpenNi2Scheme[] = "openni2://";
constexpr char kAravisScheme[] = "aravis://";
constexpr char kV4l2Scheme[] = "v4l2://";
constexpr char kReplayScheme[] = "replay://";
constexpr char kRosBagScheme[] = "rosbag://";

bool StartsWith(const std::string& text, const std::string& prefix) {
  return text.rfind(prefix, 0) == 0;
}

// The URI without its scheme, or the URI itself when it has another one.
std::string StripScheme(const std::string& uri, const std::string& scheme) {
  return StartsWith(uri, scheme) ? uri.substr(scheme.size()) : uri;
}

// Extracts a typed Options struct; InvalidArgument when it fails its own check.
template <typename T>
StatusOr<T> ExtractChecked(const OptionSet& set) {
  T options = set.Extract(T::Describe());
  std::string error;
  if (!options.IsValid(&error)) return InvalidArgument(error);
  return options;
}

// A path ending in ".oni", any case (as OpenNi2Source::IsRecordingPath, which may not be built).
bool OpenNi2IsRecording(const std::string& path) {
  if (path.size() < 4) return false;
  std::string ext = path.substr(path.size() - 4);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".oni";
}

// A path ending in ".bag", any case (as IsBagPath in core/ros, which may not be built).
bool IsRosBagPath(const std::string& path) {
  if (path.size() < 4) return false;
  std::string ext = path.substr(path.size() - 4);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".bag";
}

// Makes a driver that was configured out say so everywhere it is asked for.
[[maybe_unused]] void MarkNotBuilt(DriverInfo* d, const std::string& option,
                                   const std::string& package) {
  const Status off = Unavailable("not built: Sightline was configured with " + option +
                                 "=OFF (install " + package + " and reconfigure)");
  d->available = [off] { return off; };  // NOLINT(performance-no-automatic-move): called often
  d->enumerate = [](const OptionSet&) { return std::vector<DeviceInfo>(); };
  d->create = [off](const std::string&, const OptionSet&) -> StatusOr<std::unique_ptr<Source>> {
    return off;
  };
}

DriverInfo OpenNi2Driver() {
  DriverInfo d;
  d.name = "openni2";
  d.description = "OpenNI2 RGB-D cameras (Kinect, Xtion, Carmine) and .oni recordings";
  d.scheme = kOpenNi2Scheme;
  d.declare_options = DeclareOpenNi2Options;
#ifdef SIGHTLINE_HAVE_OPENNI2
  d.available = [] { return OpenNi2Source::Available(); };
  d.enumerate = [](const OptionSet&) { return OpenNi2Source::Enumerate(); };
  d.create = [](const std::string& uri, const OptionSet& set) -> StatusOr<std::unique_ptr<Source>> {
    StatusOr<OpenNi2Options> options = ExtractChecked<OpenNi2Options>(set);
    if (!options.ok()) return options.status();
    return std::unique_ptr<Source>(
        std::make_unique<OpenNi2Source>(StripScheme(uri, kOpenNi2Scheme), *options));
  };
#else
  MarkNotBuilt(&d, "SIGHTLINE_WITH_OPENNI2", "libopenni2-dev");
#endif
  return d;
}

DriverInfo AravisDriver() {
  DriverInfo d;
  d.name = "aravis";
  d.description =
      "GigE Vision / USB3 Vision cameras through Aravis: one camera, or a stereo pair as "
      "aravis://LEFT_ID,RIGHT_ID";
  d.scheme = kAravisScheme;
  d.declare_options = DeclareAravisOptions;
#ifdef SIGHTLINE_HAVE_ARAVIS
  d.available = [] { return AravisSource::Available(); };
  d.enumerate = [](const OptionSet& set) {
    return AravisSource::Enumerate(set.Extract(AravisOptions::Describe()).fake_interface);
  };
  d.create = [](const std::string& uri, const OptionSet& set) -> StatusOr<std::unique_ptr<Source>> {
    StatusOr<AravisOptions> options = ExtractChecked<AravisOptions>(set);
    if (!options.ok()) return options.status();
    std::string ids = StripScheme(uri, kAravisScheme);
    const size_t question = ids.find('?');
    const std::string query = question == std::string::npos ? "" : ids.substr(question + 1);
    ids = ids.substr(0, question);
    const size_t comma = ids.find(',');
    if (comma == std::string::npos) {
      if (!query.empty()) {
        return InvalidArgument("'" + uri +
                               "': only a stereo pair takes URI options "
                               "(aravis://LEFT,RIGHT?calibration_file=FILE)");
      }
      return std::unique_ptr<Source>(std::make_unique<AravisSource>(ids, *options));
    }
    StatusOr<AravisStereoOptions> stereo = ExtractChecked<AravisStereoOptions>(set);
    if (!stereo.ok()) return stereo.status();
    if (!query.empty()) {
      const size_t eq = query.find('=');
      if (query.substr(0, eq) != "calibration_file" || eq == std::string::npos ||
          eq + 1 == query.size()) {
        return InvalidArgument("'" + uri + "': unknown URI option '" + query +
                               "' (known: calibration_file=FILE)");
      }
      stereo->calibration_file = query.substr(eq + 1);
    }
    const std::string left = ids.substr(0, comma), right = ids.substr(comma + 1);
    if (left.empty() || right.empty() || right.find(',') != std::string::npos) {
      return InvalidArgument(
          "a stereo Aravis URI names two cameras, aravis://LEFT_ID,RIGHT_ID; "
          "got '" +
          uri + "'");
    }
    return std::unique_ptr<Source>(
        std::make_unique<AravisStereoSource>(left, right, *options, *stereo));
  };
#else
  MarkNotBuilt(&d, "SIGHTLINE_WITH_ARAVIS", "libaravis-dev");
#endif
  return d;
}

DriverInfo V4l2Driver() {
  DriverInfo d;
  d.name = "v4l2";
  d.description = "USB webcams through OpenCV's V4L2 backend";
  d.scheme = kV4l2Scheme;
  d.declare_options = DeclareV4l2Options;
  d.available = [] { return V4l2Source::Available(); };
  d.enumerate = [](const OptionSet&) { return V4l2Source::Enumerate(); };
  d.create = [](const std::string& uri, const OptionSet& set) -> StatusOr<std::unique_ptr<Source>> {
    StatusOr<V4l2Options> options = ExtractChecked<V4l2Options>(set);
    if (!options.ok()) return options.status();
    const std::string device = StripScheme(uri, kV4l2Scheme);
    if (device.empty())
      return InvalidArgument("a V4L2 URI names a device: v4l2://0 or v4l2:///dev/video0");
    return std::unique_ptr<Source>(std::make_unique<V4l2Source>(device, *options));
  };
  return d;
}

DriverInfo ReplayDriver() {
  DriverInfo d;
  d.name = "replay";
  d.description = "A recording played as a live camera (replay://PATH?fps=30&loop=1)";
  d.scheme = kReplayScheme;
  d.declare_options = DeclareReplayOptions;
  d.available = [] { return ReplaySource::Available(); };
  d.enumerate = [](const OptionSet&) { return std::vector<DeviceInfo>(); };
  d.create = [](const std::string& uri, const OptionSet& set) -> StatusOr<std::unique_ptr<Source>> {
    StatusOr<ReplayOptions> options = ExtractChecked<ReplayOptions>(set);
    if (!options.ok()) return options.status();
    auto parsed = ReplaySource::ParseUri(StripScheme(uri, kReplayScheme), *options);
    if (!parsed.ok()) return parsed.status();
    return std::unique_ptr<Source>(std::make_unique<ReplaySource>(parsed->first, parsed->second));
  };
  return d;
}

DriverInfo RosBagDriver() {
  DriverInfo d;
  d.name = "rosbag";
  d.description =
      "ROS 1 bag files (.bag): images, RGB-D, stereo and point clouds, with tf ground truth";
  d.scheme = kRosBagScheme;
  d.declare_options = DeclareRosBagOptions;
#ifdef SIGHTLINE_HAVE_ROS
  d.available = [] { return BagSource::Available(); };
  d.enumerate = [](const OptionSet&) { return std::vector<DeviceInfo>(); };
  d.create = [](const std::string& uri, const OptionSet& set) -> StatusOr<std::unique_ptr<Source>> {
    StatusOr<RosBagOptions> options = ExtractChecked<RosBagOptions>(set);
    if (!options.ok()) return options.status();
    return std::unique_ptr<Source>(
        std::make_unique<BagSource>(StripScheme(uri, kRosBagScheme), *options));
  };
#else
  MarkNotBuilt(&d, "SIGHTLINE_WITH_ROS", "librosbag-dev");
#endif
  return d;
}

// The driver that opens `uri`, or nullptr for a dataset path.
const DriverInfo* DriverFor(const std::vector<DriverInfo>& drivers, const std::string& uri) {
  const DriverInfo* driver = nullptr;
  for (const DriverInfo& d : drivers) {
    if (StartsWith(uri, d.scheme)) driver = &d;
  }
  if (driver == nullptr && OpenNi2IsRecording(uri)) driver = FindDriver(drivers, "openni2");
  if (driver == nullptr && IsRosBagPath(uri)) driver = FindDriver(drivers, "rosbag");
  return driver;
}

}  // namespace

std::vector<DriverInfo> BuiltinDrivers() {
  return {OpenNi2Driver(), AravisDriver(), V4l2Driver(), ReplayDriver(), RosBagDriver()};
}

const DriverInfo* FindDriver(const std::vector<DriverInfo>& drivers, const std::string& name) {
  for (const DriverInfo& d : drivers) {
    if (d.name == name) return &d;
  }
  return nullptr;
}

bool IsSensorUri(const std::string& uri) {
  return StartsWith(uri, kOpenNi2Scheme) || StartsWith(uri, kAravisScheme) ||
         StartsWith(uri, kV4l2Scheme) || StartsWith(uri, kReplayScheme) ||
         StartsWith(uri, kRosBagScheme) || OpenNi2IsRecording(uri) || IsRosBagPath(uri);
}

Status DeclareSourceOptions(const std::string& uri, OptionSet* options) {
  const std::vector<DriverInfo> drivers = BuiltinDrivers();
  const DriverInfo* driver = DriverFor(drivers, uri);
  if (driver == nullptr) return Status::Ok();
  OptionSet own;
  SIGHTLINE_RETURN_IF_ERROR(driver->declare_options(&own));
  for (const OptionSpec& spec : own.specs()) {
    if (!options->Has(spec.key)) SIGHTLINE_RETURN_IF_ERROR(options->Declare(spec));
  }
  return Status::Ok();
}

Status CheckOniFile(const std::string& path) {
  SIGHTLINE_RETURN_IF_ERROR(CheckRegularFile(path, path));
  std::ifstream in(path, std::ios::binary);
  char header[kOniHeaderBytes] = {};
  in.read(header, sizeof(header));
  const std::streamsize got = in.gcount();
  if (got < static_cast<std::streamsize>(kOniHeaderBytes)) {
    return ParseError(path + " is too short for an ONI recording (" + std::to_string(got) +
                      " bytes; its header alone is " + std::to_string(kOniHeaderBytes) + ")");
  }
  if (std::string(header, 4) != "NI10") {
    return ParseError(path +
                      " is not an ONI recording (it does not start with the ONI header 'NI10')");
  }
  return Status::Ok();
}

StatusOr<std::unique_ptr<Source>> OpenSource(const std::string& uri, const OptionSet& options) {
  const std::vector<DriverInfo> drivers = BuiltinDrivers();
  const DriverInfo* driver = DriverFor(drivers, uri);
  if (driver != nullptr && driver->name == "openni2" && !StartsWith(uri, kOpenNi2Scheme)) {
    SIGHTLINE_RETURN_IF_ERROR(CheckOniFile(uri));
  }
  if (driver == nullptr) {
    const size_t scheme_end = uri.find("://");
    if (scheme_end != std::string::npos && uri.find('/') > scheme_end) {
      return InvalidArgument(
          "unknown source scheme '" + uri.substr(0, scheme_end + 3) + "' in '" + uri +
          "' (known: openni2://, aravis://, v4l2://, replay://, rosbag://, an .oni or .bag "
          "file or a dataset path)");
    }
    return OpenDataset(uri);
  }
  StatusOr<std::unique_ptr<Source>> source = driver->create(uri, options);
  if (!source.ok()) return source.status();
  SIGHTLINE_RETURN_IF_ERROR((*source)->Open());
  return source;
}

}  // namespace sightline
