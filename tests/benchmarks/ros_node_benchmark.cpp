// sightline-node's latency on live topics: for each pipeline, the time from a frame's image stamp
// to the arrival of the results the node publishes for that frame. Each benchmark starts its own
// roscore and sightline-node on ros:// topics, plays a small simulated recording onto those
// topics at a fixed rate (every frame stamped with ros::Time::now() when it is published), and
// takes, for every result message received, the receive wall time minus its header stamp.
// Counters: latency_median_ms, latency_p95_ms, frames_published, frames_received (frames with
// at least one result) and messages; the reported time is the median latency (manual time, one
// iteration). The ROS client side runs in a forked process (roscpp initialises once per
// process and each benchmark has its own master).
#include <benchmark/benchmark.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <sensor_msgs/PointCloud2.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <map>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "core/io/dataset.h"
#include "core/ros/ros_image.h"
#include "tests/ros/ros_test_util.h"
#include "tests/ros/roscore_fixture.h"

namespace sightline {
namespace {

using testing::ChildProcess;
using testing::RoscoreFixture;

// One pipeline's live run.
struct LiveCase {
  std::string pipeline;
  SourceKind kind = SourceKind::kRgbd;
  std::string recording;  // A folder made by sightline-cli simulate; "" when that failed.
  double rate_hz = 10;    // The publishing rate.
  // The result topics and their message types ("grid", "scan", "odom", "cloud").
  std::vector<std::pair<std::string, std::string>> results;
};

// The input topics of each kind and the ros:// URI that reads them.
constexpr char kRgbImage[] = "/bench/rgb/image";
constexpr char kDepthImage[] = "/bench/depth/image";
constexpr char kLeftImage[] = "/bench/left/image_rect";
constexpr char kRightImage[] = "/bench/right/image_rect";
constexpr char kMonoImage[] = "/bench/mono/image";

std::string SourceUri(SourceKind kind) {
  switch (kind) {
    case SourceKind::kRgbd:
      return std::string("ros://?image=") + kRgbImage + "&depth=" + kDepthImage + "&sync=exact";
    case SourceKind::kStereo:
      return std::string("ros://?left=") + kLeftImage + "&right=" + kRightImage + "&sync=exact";
    default:
      return std::string("ros://?image=") + kMonoImage;
  }
}

// A recording made once per run by `sightline-cli simulate ARGS` (scene.yaml marks it done).
std::string Simulated(const std::string& name, const std::string& args) {
  static std::map<std::string, std::string> made;
  if (auto it = made.find(name); it != made.end()) return it->second;
  const std::string dir = testing::TempDir("bench_" + name) + "/rec";
  const auto r =
      testing::RunProcess(testing::CliPath() + " simulate " + args + " --out " + dir + " --quiet");
  return made[name] = r.exit_code == 0 ? dir : "";
}

// What the client process saw, written as lines to a file for the benchmark process.
struct ClientResult {
  std::string error;
  int published = 0, received_frames = 0;
  std::vector<double> latencies_ms;
};

void WriteResult(const std::string& path, const ClientResult& r) {
  std::ofstream out(path);
  if (!r.error.empty()) {
    out << "error " << r.error << "\n";
    return;
  }
  out << "published " << r.published << "\nreceived " << r.received_frames << "\n";
  for (double ms : r.latencies_ms) out << "latency " << ms << "\n";
}

ClientResult ReadResult(const std::string& path) {
  ClientResult r;
  std::ifstream in(path);
  std::string line;
  bool any = false;
  while (std::getline(in, line)) {
    any = true;
    std::istringstream row(line);
    std::string key;
    row >> key;
    if (key == "error") {
      r.error = line.substr(6);
    } else if (key == "published") {
      row >> r.published;
    } else if (key == "received") {
      row >> r.received_frames;
    } else if (key == "latency") {
      double ms = 0;
      row >> ms;
      r.latencies_ms.push_back(ms);
    }
  }
  if (!any) r.error = "the ROS client wrote no result to " + path;
  return r;
}

// Result messages as (topic, header stamp, receive time), guarded for the spinner's threads.
class Arrivals {
 public:
  void Add(const std::string& topic, const ros::Time& stamp, const ros::Time& received) {
    std::lock_guard<std::mutex> lock(mutex_);
    rows_.push_back({topic, stamp, received});
    last_ = std::chrono::steady_clock::now();
  }
  struct Row {
    std::string topic;
    ros::Time stamp, received;
  };
  std::vector<Row> rows() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return rows_;
  }
  std::chrono::steady_clock::time_point last() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return last_;
  }

 private:
  mutable std::mutex mutex_;
  std::vector<Row> rows_;
  std::chrono::steady_clock::time_point last_{};
};

template <typename Msg>
ros::Subscriber Subscribe(ros::NodeHandle& nh, const std::string& topic, Arrivals* arrivals) {
  return nh.subscribe<Msg>(topic, 1000, [arrivals, topic](const boost::shared_ptr<const Msg>& msg) {
    arrivals->Add(topic, msg->header.stamp, ros::Time::now());
  });
}

ros::Subscriber SubscribeResult(ros::NodeHandle& nh, const std::string& topic,
                                const std::string& type, Arrivals* arrivals) {
  if (type == "grid") return Subscribe<nav_msgs::OccupancyGrid>(nh, topic, arrivals);
  if (type == "scan") return Subscribe<sensor_msgs::LaserScan>(nh, topic, arrivals);
  if (type == "odom") return Subscribe<nav_msgs::Odometry>(nh, topic, arrivals);
  return Subscribe<sensor_msgs::PointCloud2>(nh, topic, arrivals);
}

template <typename Pred>
bool WaitFor(Pred ready, double timeout_s) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (std::chrono::steady_clock::now() < end) {
    if (ready()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return ready();
}

double Percentile(std::vector<double> values, double q) {
  std::sort(values.begin(), values.end());
  const double at = q * (values.size() - 1);
  const size_t lo = static_cast<size_t>(std::floor(at));
  const size_t hi = std::min(lo + 1, values.size() - 1);
  return values[lo] + (at - lo) * (values[hi] - values[lo]);
}

// The ROS side of one run, in the forked process: publishes the frames on the input topics,
// receives the results and matches each to the frame whose stamp it carries.
ClientResult RunClient(const LiveCase& c, const SourceInfo& info,
                       const std::vector<Frame>& frames) {
  ClientResult out;
  int argc = 0;
  ros::init(argc, nullptr, "sightline_bench",
            ros::init_options::AnonymousName | ros::init_options::NoSigintHandler);
  ros::NodeHandle nh;
  ros::AsyncSpinner spinner(2);
  spinner.start();

  // Inputs: image topics and their latched camera info.
  std::vector<std::pair<std::string, ros::Publisher>> inputs;
  std::vector<ros::Publisher> infos;
  auto add_input = [&](const std::string& topic, const std::string& info_topic,
                       const sensor_msgs::CameraInfo* camera) {
    inputs.emplace_back(topic, nh.advertise<sensor_msgs::Image>(topic, 10));
    if (camera == nullptr) return;
    infos.push_back(nh.advertise<sensor_msgs::CameraInfo>(info_topic, 1, /*latch=*/true));
    infos.back().publish(*camera);
  };
  if (c.kind == SourceKind::kRgbd) {
    const sensor_msgs::CameraInfo camera = RosInfoFromCamera(info.rgbd->color, 0, "camera");
    add_input(kRgbImage, "/bench/rgb/camera_info", &camera);
    add_input(kDepthImage, "", nullptr);
  } else if (c.kind == SourceKind::kStereo) {
    const StereoRig& rig = *info.stereo;
    const sensor_msgs::CameraInfo left = RosInfoFromCamera(rig.left, 0, "left");
    sensor_msgs::CameraInfo right = RosInfoFromCamera(rig.right, 0, "right");
    right.P[3] = rig.right.fx * rig.right_from_left.translation().x();  // -fx * baseline.
    add_input(kLeftImage, "/bench/left/camera_info", &left);
    add_input(kRightImage, "/bench/right/camera_info", &right);
  } else {
    const sensor_msgs::CameraInfo camera = RosInfoFromCamera(*info.camera, 0, "camera");
    add_input(kMonoImage, "/bench/mono/camera_info", &camera);
  }

  Arrivals arrivals;
  std::vector<ros::Subscriber> subs;
  for (const auto& [topic, type] : c.results) {
    subs.push_back(SubscribeResult(nh, topic, type, &arrivals));
  }
  for (const auto& [topic, pub] : inputs) {
    if (!WaitFor([&pub = pub] { return pub.getNumSubscribers() > 0; }, 60)) {
      out.error = "sightline-node never subscribed to " + topic + " within 60 s";
      return out;
    }
  }
  for (size_t i = 0; i < subs.size(); ++i) {
    if (!WaitFor([&] { return subs[i].getNumPublishers() > 0; }, 60)) {
      out.error = "sightline-node never advertised " + c.results[i].first + " within 60 s";
      return out;
    }
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(500));

  // Frames at the fixed rate, stamped now; the stamps as the messages carry them.
  std::vector<ros::Time> stamps;
  const auto period = std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double>(1.0 / c.rate_hz));
  auto next = std::chrono::steady_clock::now();
  for (const Frame& frame : frames) {
    std::this_thread::sleep_until(next);
    next += period;
    const double now = RosSeconds(ros::Time::now());
    std::vector<cv::Mat> images;
    if (const auto* rgbd = std::get_if<RgbdFrame>(&frame)) images = {rgbd->color, rgbd->depth_m};
    if (const auto* stereo = std::get_if<StereoFrame>(&frame)) {
      images = {stereo->left, stereo->right};
    }
    if (const auto* mono = std::get_if<MonoFrame>(&frame)) images = {mono->image};
    for (size_t i = 0; i < images.size(); ++i) {
      StatusOr<sensor_msgs::Image> msg = EncodeRosImage(images[i], now, "camera");
      if (!msg.ok()) {
        out.error = inputs[i].first + ": " + msg.status().ToString();
        return out;
      }
      if (i == 0) stamps.push_back(msg->header.stamp);
      inputs[i].second.publish(*msg);
    }
  }
  out.published = static_cast<int>(stamps.size());
  // Results until every frame has one or none came for 3 s (at most 60 s).
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (std::chrono::steady_clock::now() < end) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    const auto quiet = std::chrono::steady_clock::now() - std::max(arrivals.last(), next);
    if (quiet > std::chrono::seconds(3)) break;
  }

  // Each result matches the published frame of its stamp (the node's stamps round-trip
  // through double seconds: within a microsecond).
  std::map<double, int> by_time;
  for (size_t k = 0; k < stamps.size(); ++k) by_time[RosSeconds(stamps[k])] = static_cast<int>(k);
  std::vector<bool> answered(stamps.size(), false);
  for (const auto& row : arrivals.rows()) {
    const double t = RosSeconds(row.stamp);
    auto it = by_time.lower_bound(t - 1e-5);
    if (it == by_time.end() || std::abs(it->first - t) > 1e-5) {
      char stamp[64];
      std::snprintf(stamp, sizeof(stamp), "%.6f", t);
      out.error = "a message on " + row.topic + " stamped " + stamp +
                  " matches no published frame (" + std::to_string(stamps.size()) + " published)";
      return out;
    }
    answered[it->second] = true;
    out.latencies_ms.push_back(1e3 * (RosSeconds(row.received) - it->first));
  }
  out.received_frames = static_cast<int>(std::count(answered.begin(), answered.end(), true));
  if (out.latencies_ms.empty()) out.error = "no result message arrived";
  return out;
}

std::string LogTail(const std::string& path) {
  const std::string text = testing::ReadTextFile(path);
  return text.size() > 1500 ? text.substr(text.size() - 1500) : text;
}

void RunLive(benchmark::State& state, const LiveCase& c) {
  if (c.recording.empty()) {
    state.SkipWithError((c.pipeline + ": sightline-cli simulate failed").c_str());
    return;
  }
  StatusOr<std::unique_ptr<Source>> dataset = OpenDataset(c.recording, c.kind);
  if (!dataset.ok()) {
    state.SkipWithError((c.recording + ": " + dataset.status().ToString()).c_str());
    return;
  }
  const SourceInfo info = (*dataset)->info();
  if ((c.kind == SourceKind::kRgbd && !info.rgbd) ||
      (c.kind == SourceKind::kStereo && !info.stereo) ||
      (c.kind == SourceKind::kMono && !info.camera)) {
    state.SkipWithError((c.recording + ": the recording has no camera calibration").c_str());
    return;
  }
  std::vector<Frame> frames;
  while ((*dataset)->Grab().ok()) {
    StatusOr<Frame> frame = (*dataset)->Retrieve();
    if (!frame.ok()) {
      state.SkipWithError((c.recording + ": " + frame.status().ToString()).c_str());
      return;
    }
    frames.push_back(std::move(*frame));
  }

  RoscoreFixture master;
  if (const std::string error = master.Start(); !error.empty()) {
    state.SkipWithError(error.c_str());
    return;
  }
  const std::string dir = testing::TempDir("bench_node_" + c.pipeline);
  const std::string log = dir + "/node.log", result_path = dir + "/client.txt";
  ChildProcess node;
  if (!node.Start(master.Env() + testing::NodePath() + " --pipeline " + c.pipeline + " --out " +
                      dir + "/out --source '" + SourceUri(c.kind) + "'",
                  log)) {
    state.SkipWithError("cannot start sightline-node");
    return;
  }

  for (auto _ : state) {
    const pid_t client = fork();
    if (client < 0) {
      state.SkipWithError("cannot fork the ROS client");
      break;
    }
    if (client == 0) {
      master.ExportEnv();
      WriteResult(result_path, RunClient(c, info, frames));
      ros::shutdown();
      _exit(0);  // Not exit(): the benchmark process owns the temporary folders.
    }
    // The node must stay up while the client runs.
    std::string failure;
    int status = 0;
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(300);
    while (waitpid(client, &status, WNOHANG) != client) {
      const int code = node.Wait(0.1);
      if (node.pid() <= 0) {
        failure =
            "sightline-node " +
            (code < 0 ? std::string("was killed") : "exited with code " + std::to_string(code)) +
            " while the frames were published: " + LogTail(log);
      } else if (std::chrono::steady_clock::now() > end) {
        failure = "the ROS client did not finish within 300 s";
      }
      if (!failure.empty()) {
        kill(client, SIGKILL);
        waitpid(client, &status, 0);
        break;
      }
    }
    if (!failure.empty()) {
      state.SkipWithError(failure.c_str());
      break;
    }
    const ClientResult r = ReadResult(result_path);
    if (!r.error.empty()) {
      state.SkipWithError((c.pipeline + ": " + r.error + "\nnode log: " + LogTail(log)).c_str());
      break;
    }
    const double median = Percentile(r.latencies_ms, 0.5);
    state.SetIterationTime(median / 1e3);
    state.counters["latency_median_ms"] = median;
    state.counters["latency_p95_ms"] = Percentile(r.latencies_ms, 0.95);
    state.counters["frames_published"] = r.published;
    state.counters["frames_received"] = r.received_frames;
    state.counters["messages"] = static_cast<double>(r.latencies_ms.size());
  }
  node.Interrupt();
  if (node.Wait(30) < 0) node.Kill();
  node.Kill();
}

// Mapping on the RGB-D corridor (30 frames, 320x240): the map, scan.
void BM_NodeLatencyMapping(benchmark::State& state) {
  RunLive(state, {"mapping",
                  SourceKind::kRgbd,
                  testing::CorridorRgbd(),
                  10,
                  {{"/map", "grid"}, {"/scan", "scan"}}});
}
// Stereo VO on the stereo corridor (30 frames, 376x240): odometry.
void BM_NodeLatencyStereoVo(benchmark::State& state) {
  RunLive(state,
          {"stereo-vo", SourceKind::kStereo, testing::CorridorStereo(), 10, {{"/odom", "odom"}}});
}
// Mono SLAM on the simulated arm's panel approach (60 frames): odometry and map points.
void BM_NodeLatencyMonoSlam(benchmark::State& state) {
  RunLive(state, {"mono-slam",
                  SourceKind::kMono,
                  Simulated("panel", "panel --frames 60"),
                  10,
                  {{"/odom", "odom"}, {"/map_points", "cloud"}}});
}
// Mobility on the RGB-D terrain (20 frames) at 5 Hz: the scored cloud and grid.
void BM_NodeLatencyMobility(benchmark::State& state) {
  RunLive(state, {"mobility",
                  SourceKind::kRgbd,
                  Simulated("terrain", "terrain --frames 20"),
                  5,
                  {{"/mobility_cloud", "cloud"}, {"/mobility_grid", "grid"}}});
}

BENCHMARK(BM_NodeLatencyMapping)->Iterations(1)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_NodeLatencyStereoVo)->Iterations(1)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_NodeLatencyMonoSlam)->Iterations(1)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_NodeLatencyMobility)->Iterations(1)->UseManualTime()->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace sightline
