// sightline-node's run: the pipeline's one headless loop (RunPipeline), with a per-frame hook
// that publishes the result, paces a recording and watches the master.
#include "app/node/node_run.h"

#include <ros/master.h>
#include <ros/node_handle.h>
#include <ros/spinner.h>
#include <ros/this_node.h>

#include <chrono>
#include <cstdio>
#include <thread>

#include "app/node/node_button.h"
#include "app/node/node_master_watch.h"
#include "app/node/node_params.h"
#include "app/node/node_publishers.h"
#include "core/common/timing.h"
#include "core/pipeline/pipeline_registry.h"
#include "core/ros/ros_live_source.h"
#include "core/sensors/driver_registry.h"

namespace sightline::node {

namespace {

// Sleeps so that results go out at the recording's pace (sensor time against host time).
class FramePacer {
 public:
  explicit FramePacer(bool enabled) : enabled_(enabled) {}
  void Wait(double sensor_time_s, const std::atomic<bool>& cancel) {
    if (!enabled_) return;
    const double now = HostTimeS();
    if (!started_ || sensor_time_s < first_sensor_s_) {
      started_ = true;
      first_sensor_s_ = sensor_time_s;
      first_host_s_ = now;
      return;
    }
    const double due = first_host_s_ + (sensor_time_s - first_sensor_s_);
    while (HostTimeS() < due && !cancel.load()) {
      std::this_thread::sleep_for(std::chrono::duration<double>(std::min(0.05, due - HostTimeS())));
    }
  }

 private:
  bool enabled_;
  bool started_ = false;
  double first_sensor_s_ = 0, first_host_s_ = 0;
};

// Notices (at most twice a second) that the master stopped answering; says so once.
class MasterWatch {
 public:
  void Check(int64_t index) {
    const double now = HostTimeS();
    if (lost_ || now - last_check_s_ < 0.5) return;
    last_check_s_ = now;
    if (ros::master::check()) return;
    lost_ = true;
    std::fprintf(stderr,
                 "sightline-node: the ROS master at %s does not answer (frame %lld); the run goes "
                 "on: subscribers already connected keep receiving, the results are kept\n",
                 ros::master::getURI().c_str(), static_cast<long long>(index));
  }
  bool lost() const { return lost_; }

 private:
  bool lost_ = false;
  double last_check_s_ = -1;
};

// The overrides in force: the node's defaults, then the private parameters, then --set.
StatusOr<std::vector<std::string>> NodeOverrides(const PipelineInfo& info, const NodeArgs& args,
                                                 const ros::NodeHandle& private_nh) {
  OptionSet declared;
  if (info.declare_options) SIGHTLINE_RETURN_IF_ERROR(info.declare_options(&declared));
  // A source file's driver options too (a .bag's io.rosbag.*), as RunPipeline declares them.
  if (!IsRosLiveUri(args.source)) {
    SIGHTLINE_RETURN_IF_ERROR(DeclareSourceOptions(args.source, &declared));
  }
  std::vector<std::string> overrides;
  // The mapping frames carry the global map (for the `map` topic) every frame.
  if (declared.Has("mapping.stitch.render_every_n")) {
    overrides.push_back("mapping.stitch.render_every_n=1");
  }
  ParamOverrides params = ReadParamOverrides(declared, private_nh);
  for (const std::string& warning : params.warnings) {
    std::fprintf(stderr, "sightline-node: %s\n", warning.c_str());
  }
  for (const std::string& o : params.overrides) {
    std::fprintf(stderr, "sightline-node: parameter sets %s\n", o.c_str());
    overrides.push_back(o);
  }
  overrides.insert(overrides.end(), args.sets.begin(), args.sets.end());
  return overrides;
}

// Serves the latched topics after the source ended, until shutdown or `linger_s`.
void Linger(double linger_s, const std::atomic<bool>& cancel) {
  const double end = HostTimeS() + linger_s;
  while (!cancel.load() && ros::ok() && (linger_s < 0 || HostTimeS() < end)) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
}

// The built-in pipelines, the button's driven by the operator's topics (`commands`) instead of
// button.run.tap.
PipelineRegistry NodeRegistry(const std::shared_ptr<ButtonCommands>& commands) {
  PipelineRegistry registry;
  const PipelineRegistry builtin = BuiltinPipelines();
  for (const PipelineInfo& p : builtin.pipelines()) {
    (void)registry.Register(p.name == "button" ? ButtonPipelineInfo(commands) : p);
  }
  return registry;
}

std::unique_ptr<ResultPublisher> MakePublisher(const PipelineInfo& info, ros::NodeHandle& nh,
                                               const std::shared_ptr<ButtonCommands>& commands) {
  const StatisticTable table = info.create()->Statistics();  // A copy: the object goes.
  if (info.name == "button") return MakeButtonPublisher(table, nh, RosFrames(), commands);
  return MakeResultPublisher(info.name, table, nh, RosFrames());
}

// Turns Ctrl-C / SIGTERM into a ROS shutdown, so that a Grab waiting on live topics returns.
class CancelWatcher {
 public:
  explicit CancelWatcher(const std::atomic<bool>& cancel)
      : thread_([this, &cancel] {
          while (!done_.load()) {
            if (cancel.load()) {
              ros::requestShutdown();
              return;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
          }
        }) {}
  ~CancelWatcher() {
    done_.store(true);
    thread_.join();
  }

 private:
  std::atomic<bool> done_{false};
  std::thread thread_;
};

int ExitCode(const StatusOr<RunReport>& report, bool master_lost) {
  if (!report.ok()) {
    return report.status().code() == StatusCode::kCancelled ? kExitCancelled : kExitError;
  }
  const Status& stop = report->result.ended_early;
  if (!stop.ok()) return stop.code() == StatusCode::kCancelled ? kExitCancelled : kExitError;
  if (master_lost) return kExitMasterLost;
  return report->result.nothing_achieved.empty() ? 0 : kExitNothingAchieved;
}

void PrintReport(const StatusOr<RunReport>& report, const std::string& pipeline) {
  if (!report.ok()) {
    std::fprintf(stderr, "sightline-node: %s: %s\n", pipeline.c_str(),
                 report.status().ToString().c_str());
    return;
  }
  const RunResult& r = report->result;
  std::printf("sightline-node: %s: %lld frames published; results in %s\n", pipeline.c_str(),
              static_cast<long long>(r.frames), report->metrics_path.c_str());
  if (!r.ended_early.ok()) std::printf("ended early: %s\n", r.ended_early.ToString().c_str());
  if (!r.nothing_achieved.empty())
    std::printf("achieved nothing: %s\n", r.nothing_achieved.c_str());
  std::fflush(stdout);
}

}  // namespace

int RunNode(const NodeArgs& args, std::atomic<bool>& cancel) {
  const auto commands = std::make_shared<ButtonCommands>();
  const PipelineRegistry registry = NodeRegistry(commands);
  const PipelineInfo* info = registry.Find(args.pipeline);
  if (info == nullptr || !info->create) {
    std::string names;
    for (const auto& p : registry.pipelines()) names += (names.empty() ? "" : ", ") + p.name;
    std::fprintf(stderr, "sightline-node: unknown pipeline '%s' (known: %s)\n",
                 args.pipeline.c_str(), names.c_str());
    return kExitError;
  }
  if (!ros::master::check()) {
    std::fprintf(stderr,
                 "sightline-node: no ROS master answers at %s (start roscore, or set "
                 "ROS_MASTER_URI)\n",
                 ros::master::getURI().c_str());
    return kExitError;
  }
  ros::NodeHandle nh;
  ros::NodeHandle private_nh("~");
  ros::AsyncSpinner spinner(1);
  spinner.start();
  StatusOr<std::vector<std::string>> overrides = NodeOverrides(*info, args, private_nh);
  if (!overrides.ok()) {
    std::fprintf(stderr, "sightline-node: %s\n", overrides.status().ToString().c_str());
    return kExitError;
  }
  std::unique_ptr<ResultPublisher> publisher = MakePublisher(*info, nh, commands);
  MasterReregistration reregistration;  // A restarted master learns of the node again.
  FramePacer pacer(args.recorded_rate);
  MasterWatch watch;
  RunRequest request;
  request.pipeline = info->name;
  request.dataset_path = args.source;
  request.out_dir = args.out_dir;
  request.profile_path = args.profile;
  request.overrides = *overrides;
  request.cancel = &cancel;
  if (IsRosLiveUri(args.source)) request.open_source = OpenRosLiveSource;
  request.on_result = [&](const std::shared_ptr<const PipelineResult>& result, int64_t index) {
    publisher->Publish(*result);
    watch.Check(index);
    pacer.Wait(result->stamp.sensor_time_s, cancel);
    // A shutdown through ROS (rosnode kill) stops the run as Ctrl-C does.
    if (!ros::ok()) cancel.store(true);
  };
  std::printf("sightline-node %s: running on %s\n", ros::this_node::getName().c_str(),
              args.source.c_str());
  std::fflush(stdout);
  CancelWatcher watcher(cancel);
  const StatusOr<RunReport> report = RunPipeline(registry, request);
  PrintReport(report, info->name);
  if (report.ok() && report->result.ended_early.ok()) Linger(args.linger_s, cancel);
  spinner.stop();
  ros::shutdown();
  return ExitCode(report, watch.lost());
}

}  // namespace sightline::node
