// sightline-cli record: records any source (sensor URI, replayed recording, dataset) to the
// formats the readers read, and reports frames written and dropped.
#include <atomic>
#include <csignal>
#include <cstdio>
#include <mutex>

#include "app/cli/cli_args.h"
#include "app/cli/commands.h"
#include "app/cli/program_pipelines.h"
#include "core/options/option_set.h"
#include "core/record/record_session.h"
#include "core/sensors/driver_registry.h"

namespace sightline::cli {
namespace {

const char kHelp[] =
    "usage: sightline-cli record SOURCE --out DIR [--seconds S] [--frames N]\n"
    "                            [--set KEY=VALUE]... [--overwrite] [--ack] [--quiet]\n"
    "\n"
    "Records SOURCE into DIR in the formats Sightline reads, with the calibration beside it:\n"
    "  RGB-D   DIR/rgbd/    TUM RGB-D (rgb/, depth/, rgb.txt, depth.txt, associations.txt,\n"
    "                       camera.yaml)\n"
    "  stereo  DIR/stereo/  EuRoC MAV (mav0/cam0, mav0/cam1: data/, data.csv, sensor.yaml)\n"
    "  mono    DIR/mono/    image folder (NNNNNN.png, times.txt, camera.yaml)\n"
    "or, with --set record.format=bag, into one ROS 1 bag, DIR/recording.bag (lz4 chunks; the\n"
    "images and camera_info on the topics 'sightline-cli simulate --format bag' uses), indexed\n"
    "when the recording ends.\n"
    "SOURCE is a sensor URI (openni2://, aravis://ID, v4l2://0), a recording paced as a live\n"
    "camera (replay://PATH?fps=30), an .oni file or a dataset folder.\n"
    "\n"
    "Frames pass through a bounded queue to a writer thread; every frame is either written or\n"
    "counted as dropped. Index lines are appended (and fsynced) only after a frame's images are\n"
    "complete, so a recording cut by a crash, a pulled plug or a full disk stays readable up to\n"
    "its last complete frame. Ctrl-C (SIGINT) or SIGTERM finishes the queued frames and exits.\n"
    "\n"
    "  --seconds S   stop after S seconds\n"
    "  --frames N    stop after N frames taken from the source\n"
    "  --set K=V     a sensors.* or record.* option, e.g. record.queue_capacity=128,\n"
    "                record.png_compression=0, sensors.replay.fps=60\n"
    "  --overwrite   DIR may already hold files: its rgbd/, stereo/ or mono/ folder is replaced\n"
    "                (record.overwrite=true). Without it a DIR that holds anything is refused,\n"
    "                so that an earlier recording is never truncated.\n"
    "  --ack         print 'written N T' after every frame that is on disk\n"
    "  --quiet       print only the closing counts\n"
    "\n"
    "Exit code 0 when every frame was written, 3 when frames were dropped, 1 on an error (the\n"
    "message names the file; the partial recording stays readable).\n";

std::atomic<bool> g_stop{false};
void OnSignal(int) { g_stop = true; }

// Sensor and recorder options, with recording defaults: sources hand out every frame in order
// (not only the newest) through a deeper queue, unless --set says otherwise.
StatusOr<OptionSet> RecordOptions(const CliArgs& args) {
  OptionSet set;
  SIGHTLINE_RETURN_IF_ERROR(DeclareSensorOptions(&set));
  SIGHTLINE_RETURN_IF_ERROR(set.Declare(RecorderOptions::Describe()));
  for (const OptionSpec& spec : std::vector<OptionSpec>(set.specs())) {
    const std::string& key = spec.key;
    auto ends_with = [&key](const std::string& suffix) {
      return key.size() > suffix.size() &&
             key.compare(key.size() - suffix.size(), suffix.size(), suffix) == 0;
    };
    if (ends_with(".latest_only")) SIGHTLINE_RETURN_IF_ERROR(set.Set(key, OptionValue(false)));
    if (ends_with(".queue_capacity") && key.rfind("sensors.", 0) == 0) {
      SIGHTLINE_RETURN_IF_ERROR(set.Set(key, OptionValue(int64_t{16})));
    }
  }
  for (const std::string& assignment : args.Values("--set")) {
    SIGHTLINE_RETURN_IF_ERROR(set.ApplyOverride(assignment));
  }
  if (args.Has("--overwrite"))
    SIGHTLINE_RETURN_IF_ERROR(set.Set("record.overwrite", OptionValue(true)));
  return set;
}

StatusOr<double> ParseNumber(const CliArgs& args, const std::string& flag) {
  const std::string text = *args.Value(flag);
  try {
    size_t used = 0;
    const double value = std::stod(text, &used);
    if (used == text.size() && value > 0) return value;
  } catch (const std::exception&) {
  }
  return InvalidArgument(flag + " expects a positive number, got '" + text + "'");
}

void PrintSummary(const RecordSummary& s, bool quiet) {
  const RecorderStats& r = s.recorder;
  std::printf("recorded %s (%s): %llu frames written, %llu dropped (%s)\n", s.folder.c_str(),
              s.format.c_str(), static_cast<unsigned long long>(r.frames_written),
              static_cast<unsigned long long>(s.TotalDropped()), s.end_reason.c_str());
  if (quiet) return;
  std::printf("  recorder: %llu frames offered, %llu dropped (%llu out of order)\n",
              static_cast<unsigned long long>(r.frames_offered),
              static_cast<unsigned long long>(r.frames_dropped),
              static_cast<unsigned long long>(r.frames_out_of_order));
  if (s.sensor) {
    std::printf(
        "  source: %llu frames received, %llu dropped, %llu incomplete, mean latency "
        "%.1f ms, %.1f Hz\n",
        static_cast<unsigned long long>(s.sensor->frames_received),
        static_cast<unsigned long long>(s.sensor->frames_dropped),
        static_cast<unsigned long long>(s.sensor->incomplete_frames), s.sensor->mean_latency_ms,
        s.sensor->receive_rate_hz);
  }
  std::printf("  %.1f MB in %.2f s: %.1f MB/s\n", static_cast<double>(r.bytes_written) / 1e6,
              r.elapsed_s, r.write_mb_per_s);
  for (const std::string& note : s.notes) std::printf("  note: %s\n", note.c_str());
}

}  // namespace

int RecordCommand(const std::vector<std::string>& args) {
  StatusOr<CliArgs> parsed = CliArgs::Parse(args, {"--out", "--seconds", "--frames", "--set"},
                                            {"--help", "--ack", "--quiet", "--overwrite"});
  if (!parsed.ok()) return Fail("record: " + parsed.status().message());
  if (parsed->Has("--help")) {
    std::fputs(kHelp, stdout);
    return 0;
  }
  if (parsed->positionals().size() != 1) return Fail("record: expected one SOURCE (see --help)");
  if (!parsed->Value("--out")) return Fail("record: --out DIR is required");
  RecordLimits limits;
  for (const char* flag : {"--seconds", "--frames"}) {
    if (!parsed->Value(flag)) continue;
    StatusOr<double> value = ParseNumber(*parsed, flag);
    if (!value.ok()) return Fail("record: " + value.status().message());
    if (std::string(flag) == "--seconds")
      limits.max_seconds = *value;
    else
      limits.max_frames = static_cast<int64_t>(*value);
  }
  StatusOr<OptionSet> options = RecordOptions(*parsed);
  if (!options.ok()) return Fail("record: " + options.status().ToString());
  const RecorderOptions recorder_options = options->Extract(RecorderOptions::Describe());
  std::string error;
  if (!recorder_options.IsValid(&error)) return Fail("record: " + error);

  const std::string uri = parsed->positionals()[0];
  const SourceOpener live = ProgramSourceOpener(uri, &g_stop);
  StatusOr<std::unique_ptr<Source>> source = live ? live(uri) : OpenSource(uri, *options);
  if (!source.ok()) return Fail("record: " + source.status().ToString());

  std::signal(SIGINT, OnSignal);
  std::signal(SIGTERM, OnSignal);
  const bool quiet = parsed->Has("--quiet");
  std::mutex print_mutex;
  RecordCallbacks callbacks;
  callbacks.stop = &g_stop;
  if (parsed->Has("--ack")) {
    callbacks.written = [&print_mutex](const WrittenFrame& w) {
      std::lock_guard<std::mutex> lock(print_mutex);
      std::printf("written %lld %.6f\n", static_cast<long long>(w.index), w.stamp.sensor_time_s);
      std::fflush(stdout);
    };
  }
  callbacks.outage = [&print_mutex, quiet](const Status& s) {
    if (quiet) return;
    std::lock_guard<std::mutex> lock(print_mutex);
    std::fprintf(stderr, "sightline-cli: record: %s (waiting)\n", s.message().c_str());
  };
  if (!quiet) {
    std::printf("recording %s (%s) into %s\n", uri.c_str(), (*source)->info().format.c_str(),
                parsed->Value("--out")->c_str());
    std::fflush(stdout);
  }
  StatusOr<RecordSummary> summary =
      RecordSource(source->get(), *parsed->Value("--out"), recorder_options, limits, callbacks);
  (*source)->Close();
  if (!summary.ok()) return Fail("record: " + summary.status().ToString());
  PrintSummary(*summary, quiet);
  std::fflush(stdout);
  if (!summary->write_status.ok()) return Fail("record: " + summary->write_status.ToString());
  return summary->TotalDropped() > 0 ? 3 : 0;
}

}  // namespace sightline::cli
