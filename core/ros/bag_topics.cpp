#include "core/ros/bag_topics.h"

#include <cstdio>
#include <optional>
#include <sstream>

#include "core/common/json_writer.h"

namespace sightline {
namespace {

std::string Normalized(const std::string& topic) {
  return !topic.empty() && topic[0] == '/' ? topic.substr(1) : topic;
}

std::string Join(const std::vector<const BagTopic*>& topics) {
  std::string text;
  for (const BagTopic* t : topics) text += (text.empty() ? "" : ", ") + t->name;
  return text.empty() ? "none" : text;
}

// "/cam/image_raw/compressed" -> "/cam": the namespace whose camera_info belongs to the image.
std::string CameraNamespace(std::string topic) {
  for (const char* transport : {"/compressed", "/compressedDepth", "/theora"}) {
    const std::string t = transport;
    if (topic.size() > t.size() && topic.compare(topic.size() - t.size(), t.size(), t) == 0) {
      topic.resize(topic.size() - t.size());
      break;
    }
  }
  const size_t slash = topic.rfind('/');
  return slash == std::string::npos ? "" : topic.substr(0, slash);
}

std::vector<const BagTopic*> Filter(const BagSummary& bag, bool (BagTopic::*test)() const) {
  std::vector<const BagTopic*> out;
  for (const BagTopic& t : bag.topics) {
    if ((t.*test)()) out.push_back(&t);
  }
  return out;
}

// The topic an option names, checked to exist and to pass `test` (what it must be: `what`).
StatusOr<std::string> NamedTopic(const BagSummary& bag, const std::string& name,
                                 const std::string& key, bool (BagTopic::*test)() const,
                                 const std::string& what) {
  const BagTopic* topic = bag.Find(name);
  const std::vector<const BagTopic*> fitting = Filter(bag, test);
  if (topic == nullptr) {
    return InvalidArgument(bag.path + ": io.rosbag." + key + " '" + name +
                           "' is not a topic of the bag (its " + what +
                           " topics: " + Join(fitting) + ")");
  }
  if (!(topic->*test)()) {
    return InvalidArgument(bag.path + ": io.rosbag." + key + " '" + name + "' is a " + topic->type +
                           (topic->encoding.empty() ? "" : " (" + topic->encoding + ")") +
                           " topic, not " + what + " (the bag's " + what +
                           " topics: " + Join(fitting) + ")");
  }
  return topic->name;
}

bool IsCameraInfo(const BagTopic& t) { return t.type == kRosCameraInfoType; }

// The CameraInfo topic of `image`: the option's, else "<namespace>/camera_info", else the only one.
StatusOr<std::string> CameraInfoFor(const BagSummary& bag, const std::string& image,
                                    const std::string& chosen, const std::string& key,
                                    std::vector<std::string>* notes) {
  const std::vector<const BagTopic*> infos = bag.OfType(kRosCameraInfoType);
  if (!chosen.empty()) {
    const BagTopic* t = bag.Find(chosen);
    if (t == nullptr || !IsCameraInfo(*t)) {
      return InvalidArgument(
          bag.path + ": io.rosbag." + key + " '" + chosen +
          "' is not a CameraInfo topic of the bag (its CameraInfo topics: " + Join(infos) + ")");
    }
    return t->name;
  }
  const std::string beside = CameraNamespace(image) + "/camera_info";
  if (const BagTopic* t = bag.Find(beside); t != nullptr && IsCameraInfo(*t)) return t->name;
  if (infos.size() == 1) {
    notes->push_back("camera of " + image + " from " + infos[0]->name +
                     " (the bag's only CameraInfo topic)");
    return infos[0]->name;
  }
  return InvalidArgument(bag.path + ": no CameraInfo for " + image + ": looked for " + beside +
                         "; the bag's CameraInfo topics: " + Join(infos) +
                         ". Choose one with --set io.rosbag." + key +
                         "=TOPIC (or another image "
                         "with io.rosbag.image_topic)");
}

// The one topic of `candidates`, or the option's; NotFound when there is none, InvalidArgument
// (`ambiguous_is_error`) or NotFound when several fit.
StatusOr<std::string> OneTopic(const BagSummary& bag, const std::string& chosen,
                               const std::string& key, bool (BagTopic::*test)() const,
                               const std::string& what, bool ambiguous_is_error) {
  if (!chosen.empty()) return NamedTopic(bag, chosen, key, test, what);
  const std::vector<const BagTopic*> fitting = Filter(bag, test);
  if (fitting.empty()) return NotFound(bag.path + " has no " + what + " topic");
  if (fitting.size() == 1) return fitting[0]->name;
  const std::string message =
      bag.path + ": " + std::to_string(fitting.size()) + " " + what + " topics (" + Join(fitting) +
      ") and no rule picks one: choose with --set io.rosbag." + key + "=TOPIC";
  return ambiguous_is_error ? InvalidArgument(message) : NotFound(message);
}

// Leading '/'-separated components `a` and `b` share.
int SharedComponents(const std::string& a, const std::string& b) {
  const std::string x = Normalized(a) + "/", y = Normalized(b) + "/";
  int shared = 0;
  for (size_t i = 0; i < x.size() && i < y.size() && x[i] == y[i]; ++i) shared += x[i] == '/';
  return shared;
}

// Among several colour topics, the one closest to the depth topic in the name tree
// ("/camera/rgb/image_color" for "/camera/depth/image"), when only one is that close.
std::optional<std::string> ColorBesideDepth(const BagSummary& bag, const std::string& depth) {
  int best = 0;
  std::vector<std::string> closest;
  for (const BagTopic* t : Filter(bag, &BagTopic::IsColorImage)) {
    const int shared = SharedComponents(t->name, depth);
    if (shared > best) closest.clear(), best = shared;
    if (shared == best && shared > 0) closest.push_back(t->name);
  }
  if (closest.size() != 1) return std::nullopt;
  return closest[0];
}

StatusOr<BagTopicChoice> ChooseRgbd(const BagSummary& bag, const RosBagOptions& o, bool strict) {
  BagTopicChoice c;
  c.kind = SourceKind::kRgbd;
  StatusOr<std::string> depth =
      OneTopic(bag, o.depth_topic, "depth_topic", &BagTopic::IsDepthImage, "depth image", strict);
  if (!depth.ok()) return depth.status();
  StatusOr<std::string> color =
      OneTopic(bag, o.image_topic, "image_topic", &BagTopic::IsColorImage, "colour image", strict);
  if (!color.ok() && o.image_topic.empty()) {
    if (std::optional<std::string> beside = ColorBesideDepth(bag, *depth)) {
      color = *beside;
      c.notes.push_back("colour topic " + *beside + ": the image topic beside " + *depth);
    }
  }
  if (!color.ok()) return color.status();
  c.depth = *depth;
  c.image = *color;
  StatusOr<std::string> info =
      CameraInfoFor(bag, c.image, o.camera_info_topic, "camera_info_topic", &c.notes);
  if (!info.ok()) return info.status();
  c.camera_info = *info;
  return c;
}

// Two colour topics whose names differ only in "left" / "right".
bool FindLeftRight(const BagSummary& bag, std::string* left, std::string* right) {
  for (const BagTopic* l : Filter(bag, &BagTopic::IsColorImage)) {
    for (const auto& [word, swap] :
         {std::pair{"left", "right"}, std::pair{"Left", "Right"}, std::pair{"LEFT", "RIGHT"}}) {
      const size_t at = l->name.find(word);
      if (at == std::string::npos) continue;
      std::string other = l->name;
      other.replace(at, 4, swap);
      if (const BagTopic* r = bag.Find(other); r != nullptr && r->IsColorImage()) {
        *left = l->name;
        *right = r->name;
        return true;
      }
    }
  }
  return false;
}

// Not `strict` (the automatic choice): an image topic given alone means not stereo.
StatusOr<BagTopicChoice> ChooseStereo(const BagSummary& bag, const RosBagOptions& o, bool strict) {
  BagTopicChoice c;
  c.kind = SourceKind::kStereo;
  if (!o.image_topic.empty() || !o.right_image_topic.empty()) {
    if (o.image_topic.empty() || o.right_image_topic.empty()) {
      const std::string message = bag.path +
                                  ": a stereo pair needs both io.rosbag.image_topic (left) and "
                                  "io.rosbag.right_image_topic";
      return strict ? InvalidArgument(message) : NotFound(message);
    }
    for (const auto& [name, key] : {std::pair{o.image_topic, "image_topic"},
                                    std::pair{o.right_image_topic, "right_image_topic"}}) {
      StatusOr<std::string> t = NamedTopic(bag, name, key, &BagTopic::IsColorImage, "image");
      if (!t.ok()) return t.status();
      (key == std::string("image_topic") ? c.image : c.right_image) = *t;
    }
  } else if (!FindLeftRight(bag, &c.image, &c.right_image)) {
    return NotFound(bag.path + " has no pair of image topics named left/right");
  }
  StatusOr<std::string> left =
      CameraInfoFor(bag, c.image, o.camera_info_topic, "camera_info_topic", &c.notes);
  if (!left.ok()) return left.status();
  StatusOr<std::string> right = CameraInfoFor(bag, c.right_image, o.right_camera_info_topic,
                                              "right_camera_info_topic", &c.notes);
  if (!right.ok()) return right.status();
  if (*left == *right) {
    return InvalidArgument(bag.path + ": the left and right images would share the CameraInfo " +
                           "topic " + *left + "; choose io.rosbag.camera_info_topic and " +
                           "right_camera_info_topic");
  }
  c.camera_info = *left;
  c.right_camera_info = *right;
  return c;
}

StatusOr<BagTopicChoice> ChooseMono(const BagSummary& bag, const RosBagOptions& o) {
  BagTopicChoice c;
  c.kind = SourceKind::kMono;
  StatusOr<std::string> image =
      OneTopic(bag, o.image_topic, "image_topic", &BagTopic::IsColorImage, "image", true);
  if (!image.ok()) return image.status();
  c.image = *image;
  StatusOr<std::string> info =
      CameraInfoFor(bag, c.image, o.camera_info_topic, "camera_info_topic", &c.notes);
  if (!info.ok()) return info.status();
  c.camera_info = *info;
  return c;
}

bool IsCloudTopic(const BagTopic& t) { return t.type == kRosPointCloud2Type; }

StatusOr<BagTopicChoice> ChooseCloud(const BagSummary& bag, const RosBagOptions& o) {
  BagTopicChoice c;
  c.kind = SourceKind::kCloud;
  std::vector<const BagTopic*> clouds = bag.OfType(kRosPointCloud2Type);
  if (!o.cloud_topic.empty()) {
    const BagTopic* t = bag.Find(o.cloud_topic);
    if (t == nullptr || !IsCloudTopic(*t)) {
      return InvalidArgument(
          bag.path + ": io.rosbag.cloud_topic '" + o.cloud_topic +
          "' is not a PointCloud2 topic of the bag (its PointCloud2 topics: " + Join(clouds) + ")");
    }
    c.cloud = t->name;
    return c;
  }
  if (clouds.empty()) return NotFound(bag.path + " has no PointCloud2 topic");
  if (clouds.size() > 1) {
    return InvalidArgument(bag.path + ": " + std::to_string(clouds.size()) +
                           " PointCloud2 topics (" + Join(clouds) +
                           "): choose with --set io.rosbag.cloud_topic=TOPIC");
  }
  c.cloud = clouds[0]->name;
  return c;
}

StatusOr<BagTopicChoice> ChooseKind(const BagSummary& bag, const RosBagOptions& o) {
  if (o.kind == "rgbd") return ChooseRgbd(bag, o, true);
  if (o.kind == "stereo") return ChooseStereo(bag, o, true);
  if (o.kind == "mono") return ChooseMono(bag, o);
  if (o.kind == "cloud") return ChooseCloud(bag, o);
  // Auto: a named depth, right or cloud topic says the kind; else the richest the bag allows.
  if (!o.depth_topic.empty()) return ChooseRgbd(bag, o, true);
  if (!o.right_image_topic.empty()) return ChooseStereo(bag, o, true);
  if (!o.cloud_topic.empty()) return ChooseCloud(bag, o);
  StatusOr<BagTopicChoice> rgbd = ChooseRgbd(bag, o, false);
  if (rgbd.ok() || rgbd.status().code() != StatusCode::kNotFound) return rgbd;
  StatusOr<BagTopicChoice> stereo = ChooseStereo(bag, o, false);
  if (stereo.ok() || stereo.status().code() != StatusCode::kNotFound) return stereo;
  StatusOr<BagTopicChoice> mono = ChooseMono(bag, o);
  if (mono.ok() || mono.status().code() != StatusCode::kNotFound) return mono;
  StatusOr<BagTopicChoice> cloud = ChooseCloud(bag, o);
  if (cloud.ok() || cloud.status().code() != StatusCode::kNotFound) return cloud;
  std::string topics;
  for (const BagTopic& t : bag.topics)
    topics += (topics.empty() ? "" : ", ") + t.name + " " + t.type;
  return NotFound(
      bag.path + " has no topic Sightline reads frames from (sensor_msgs/Image, " +
      "CompressedImage or PointCloud2); its topics: " + (topics.empty() ? "none" : topics));
}

}  // namespace

bool BagTopic::IsColorImage() const {
  if (type == kRosCompressedImageType) return encoding.find("compressedDepth") == std::string::npos;
  return type == kRosImageType && !IsDepthImage();
}

bool BagTopic::IsDepthImage() const {
  return type == kRosImageType &&
         (encoding == "16UC1" || encoding == "32FC1" || encoding == "mono16");
}

const BagTopic* BagSummary::Find(const std::string& name) const {
  for (const BagTopic& t : topics) {
    if (Normalized(t.name) == Normalized(name)) return &t;
  }
  return nullptr;
}

std::vector<const BagTopic*> BagSummary::OfType(const std::string& type) const {
  std::vector<const BagTopic*> out;
  for (const BagTopic& t : topics) {
    if (t.type == type) out.push_back(&t);
  }
  return out;
}

std::string BagTopicChoice::Describe() const {
  switch (kind) {
    case SourceKind::kRgbd:
      return "RGB-D frames from " + image + " (colour) + " + depth + " (depth)";
    case SourceKind::kStereo:
      return "stereo pairs from " + image + " (left) + " + right_image + " (right)";
    case SourceKind::kMono:
      return "mono images from " + image;
    case SourceKind::kCloud:
      return "point clouds from " + cloud;
  }
  return "";
}

StatusOr<BagTopicChoice> ChooseBagTopics(const BagSummary& bag, const RosBagOptions& options) {
  std::string error;
  if (!options.IsValid(&error)) return InvalidArgument(error);
  StatusOr<BagTopicChoice> choice = ChooseKind(bag, options);
  if (!choice.ok()) return choice;
  if (!options.odometry_topic.empty()) {
    const BagTopic* t = bag.Find(options.odometry_topic);
    if (t == nullptr || t->type != kRosOdometryType) {
      return InvalidArgument(bag.path + ": io.rosbag.odometry_topic '" + options.odometry_topic +
                             "' is not a nav_msgs/Odometry topic of the bag (its Odometry " +
                             "topics: " + Join(bag.OfType(kRosOdometryType)) + ")");
    }
    choice->odometry = t->name;
  } else if (bag.OfType(kRosOdometryType).size() == 1) {
    choice->odometry = bag.OfType(kRosOdometryType)[0]->name;
  }
  return choice;
}

std::vector<BagTopicChoice> PossibleBagChoices(const BagSummary& bag,
                                               const RosBagOptions& options) {
  std::vector<BagTopicChoice> out;
  for (const char* kind : {"rgbd", "stereo", "mono", "cloud"}) {
    RosBagOptions o = options;
    o.kind = kind;
    StatusOr<BagTopicChoice> choice = ChooseBagTopics(bag, o);
    if (choice.ok()) out.push_back(std::move(*choice));
  }
  return out;
}

std::string DescribeBagSummaryText(const BagSummary& bag) {
  std::ostringstream out;
  char line[64];
  std::snprintf(line, sizeof(line), "%.3f", bag.end_s - bag.start_s);
  out << "bag duration: " << line << " s (" << bag.messages << " messages)\n";
  out << "bag compression: " << bag.layout.CompressionText() << " (" << bag.layout.chunks
      << " chunks)\n";
  out << "topics:\n";
  for (const BagTopic& t : bag.topics) {
    out << "  " << t.name << "  " << t.type << "  " << t.messages
        << (t.messages == 1 ? " message" : " messages");
    if (!t.encoding.empty()) out << "  (" << t.encoding << ")";
    out << "\n";
  }
  return out.str();
}

std::string DescribeBagSummaryJson(const BagSummary& bag) {
  JsonWriter w;
  w.BeginObject();
  w.Key("duration_s").Double(bag.end_s - bag.start_s);
  w.Key("messages").Int(bag.messages);
  w.Key("compression").String(bag.layout.CompressionText());
  w.Key("chunks").Int(bag.layout.chunks);
  w.Key("topics").BeginArray();
  for (const BagTopic& t : bag.topics) {
    w.BeginObject();
    w.Key("name").String(t.name);
    w.Key("type").String(t.type);
    w.Key("messages").Int(t.messages);
    w.Key("encoding");
    if (t.encoding.empty()) {
      w.Null();
    } else {
      w.String(t.encoding);
    }
    w.EndObject();
  }
  w.EndArray();
  w.EndObject();
  return w.str();
}

}  // namespace sightline
