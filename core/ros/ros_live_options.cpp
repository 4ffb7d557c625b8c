// ros:// URIs (no ROS headers: testable and usable anywhere).
#include <cstdlib>
#include <sstream>

#include "core/ros/ros_live_source.h"

namespace sightline {

namespace {

constexpr char kScheme[] = "ros://";

// "/camera/rgb/image_color" -> "/camera/rgb/camera_info".
std::string InfoBeside(const std::string& image_topic) {
  const size_t slash = image_topic.rfind('/');
  return (slash == std::string::npos ? std::string() : image_topic.substr(0, slash)) +
         "/camera_info";
}

StatusOr<double> Number(const std::string& key, const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !(value >= 0)) {
    return InvalidArgument("ros:// key '" + key + "' takes a number >= 0, got '" + text + "'");
  }
  return value;
}

Status SetKey(const std::string& key, const std::string& value, RosLiveOptions* o) {
  if (key == "image")
    o->image = value;
  else if (key == "depth")
    o->depth = value;
  else if (key == "left")
    o->left = value;
  else if (key == "right")
    o->right = value;
  else if (key == "info")
    o->info = value;
  else if (key == "left_info")
    o->left_info = value;
  else if (key == "right_info")
    o->right_info = value;
  else if (key == "odom_frame" || key == "base_frame" || key == "arm_base_frame" ||
           key == "end_effector_frame") {
    if (value.empty()) return InvalidArgument("ros:// key '" + key + "' must name a tf frame");
    (key == "odom_frame"       ? o->odom_frame
     : key == "base_frame"     ? o->base_frame
     : key == "arm_base_frame" ? o->arm_base_frame
                               : o->end_effector_frame) = value;
  } else if (key == "sync") {
    if (value != "exact" && value != "approx") {
      return InvalidArgument("ros:// key 'sync' takes exact or approx, got '" + value + "'");
    }
    o->exact = value == "exact";
  } else if (key == "slop" || key == "wait" || key == "queue" || key == "tf_wait" ||
             key == "tf_gap") {
    StatusOr<double> n = Number(key, value);
    if (!n.ok()) return n.status();
    if (key == "slop") o->slop_s = *n;
    if (key == "wait") o->wait_s = *n;
    if (key == "tf_wait") o->tf_wait_s = *n;
    if (key == "tf_gap") {
      if (!(*n > 0)) return InvalidArgument("ros:// key 'tf_gap' takes a number > 0");
      o->tf_gap_s = *n;
    }
    if (key == "queue") {
      if (*n < 1 || *n > 1000) return InvalidArgument("ros:// key 'queue' takes 1..1000");
      o->queue = static_cast<int>(*n);
    }
  } else {
    return InvalidArgument("ros:// has no key '" + key +
                           "' (keys: image, depth, info, left, right, left_info, right_info, "
                           "sync, slop, queue, wait, odom_frame, base_frame, arm_base_frame, "
                           "end_effector_frame, tf_wait, tf_gap)");
  }
  return Status::Ok();
}

}  // namespace

SourceKind RosLiveOptions::kind() const {
  if (!left.empty()) return SourceKind::kStereo;
  return depth.empty() ? SourceKind::kMono : SourceKind::kRgbd;
}

bool IsRosLiveUri(const std::string& uri) { return uri.rfind(kScheme, 0) == 0; }

StatusOr<RosLiveOptions> ParseRosLiveUri(const std::string& uri) {
  if (!IsRosLiveUri(uri)) return InvalidArgument("'" + uri + "' is not a ros:// URI");
  RosLiveOptions o;
  const size_t query = uri.find('?');
  std::stringstream pairs(query == std::string::npos ? "" : uri.substr(query + 1));
  std::string pair;
  while (std::getline(pairs, pair, '&')) {
    if (pair.empty()) continue;
    const size_t eq = pair.find('=');
    if (eq == std::string::npos) return InvalidArgument("ros:// '" + pair + "' has no '='");
    SIGHTLINE_RETURN_IF_ERROR(SetKey(pair.substr(0, eq), pair.substr(eq + 1), &o));
  }
  const bool stereo = !o.left.empty() || !o.right.empty();
  if (stereo && (o.left.empty() || o.right.empty() || !o.image.empty() || !o.depth.empty())) {
    return InvalidArgument("ros:// stereo needs both left= and right= (and no image/depth): " +
                           uri);
  }
  if (!stereo && o.image.empty()) {
    return InvalidArgument("ros:// needs image= (with depth= for RGB-D) or left= and right=: " +
                           uri);
  }
  if (!o.image.empty() && o.info.empty()) o.info = InfoBeside(o.image);
  if (stereo && o.left_info.empty()) o.left_info = InfoBeside(o.left);
  if (stereo && o.right_info.empty()) o.right_info = InfoBeside(o.right);
  return o;
}

}  // namespace sightline
