#include "app/sightline/playback_controller.h"

#include <pthread.h>

#include <QPointer>
#include <QTimer>
#include <QtConcurrent/QtConcurrentRun>
#include <algorithm>
#include <cmath>
#include <ctime>
#include <filesystem>

#include "core/common/depth_cloud.h"
#include "core/common/timing.h"
#include "core/io/dataset.h"
#include "core/pipeline/pipeline_registry.h"
#include "core/pipeline/player.h"
#include "core/pipeline/sim_panel_source.h"
#include "core/sensors/driver_registry.h"
#include "core/sensors/live_source.h"

namespace sightline {

PlaybackController::PlaybackController(QObject* parent) : QObject(parent) {
  qRegisterMetaType<std::shared_ptr<const PlaybackResult>>();
}

PlaybackController::~PlaybackController() {
  for (QFuture<void>& f : background_) f.waitForFinished();
  StopWorker();
  AbortProcessor("shutdown");
}

void PlaybackController::Open(const QString& path) {
  const uint64_t generation = ++open_generation_;
  QPointer<PlaybackController> self(this);
  const std::string path_utf8 = path.toStdString();
  // Opening reads index files and the first images: keep it off the GUI thread. The destructor
  // waits for background tasks, so `this` outlives them.
  Track(QtConcurrent::run([this, self, generation, path, path_utf8] {
    auto opened = std::make_shared<StatusOr<std::unique_ptr<Source>>>(OpenRunSource(path_utf8));
    std::shared_ptr<const Frame> first = opened->ok() ? ReadFirstFrame(***opened) : nullptr;
    QMetaObject::invokeMethod(
        this,
        [self, generation, path, opened, first] {
          if (!self || generation != self->open_generation_) return;  // A newer Open won.
          if (!opened->ok()) {
            emit self->OpenFailed(path, QString::fromStdString(opened->status().ToString()));
            return;
          }
          self->StopWorker();
          self->SetFrameTap(nullptr);  // A tap belongs to the source it was set for.
          {
            std::lock_guard<std::mutex> lock(self->mutex_);
            self->info_ = std::make_shared<SourceInfo>((**opened)->info());
          }
          // The pipeline is made before the player takes the source: keep what it carries
          // beside its frames (ground truth, odometry), as the CLI's runs get it.
          self->source_extras_ = PipelineSource::From(***opened);
          self->RebuildProcessor("source changed");
          self->SetPlayState(false, false);
          self->live_ = dynamic_cast<const LiveSource*>(opened->value().get());
          self->StartWorker(std::make_unique<Player>(std::move(**opened)));
          emit self->Opened(path);
          if (first) self->PublishPreview(first, generation);
        },
        Qt::QueuedConnection);
  }));
}

std::shared_ptr<const Frame> PlaybackController::ReadFirstFrame(Source& source) {
  // Only a recording that can go back: the first frame is read, then the source rewinds so
  // that playing still starts with it. A camera's frames are not to be skipped.
  if (!source.info().seekable || source.info().live || !source.Grab().ok()) return nullptr;
  StatusOr<Frame> frame = source.Retrieve();
  const Status rewound = source.Seek(0);
  if (!frame.ok() || !rewound.ok()) return nullptr;  // Playing reports a reading error itself.
  return std::make_shared<const Frame>(std::move(*frame));
}

void PlaybackController::PublishPreview(std::shared_ptr<const Frame> frame, uint64_t generation) {
  ViewOptions options;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    options = view_options_;
  }
  QPointer<PlaybackController> self(this);
  Track(QtConcurrent::run([this, self, frame, options, generation] {
    std::shared_ptr<const PlaybackResult> preview = Prepare(*frame, options);
    QMetaObject::invokeMethod(
        this,
        [self, preview, generation] {
          // Not when another source was opened since, or the frame itself is already shown.
          if (self && generation == self->open_generation_) emit self->FirstFrame(preview);
        },
        Qt::QueuedConnection);
  }));
}

void PlaybackController::Track(QFuture<void> future) {
  background_.erase(std::remove_if(background_.begin(), background_.end(),
                                   [](const QFuture<void>& f) { return f.isFinished(); }),
                    background_.end());
  background_.push_back(std::move(future));
}

void PlaybackController::Close(const std::string& reason) {
  ++open_generation_;
  StopWorker();
  {
    std::lock_guard<std::mutex> lock(mutex_);
    info_.reset();
  }
  source_extras_ = PipelineSource();
  RebuildProcessor(reason);
  SetPlayState(false, false);
}

void PlaybackController::SetPlayState(bool playing, bool ended) {
  if (playing == playing_ && ended == ended_) return;
  playing_ = playing;
  ended_ = ended;
  emit PlayStateChanged(playing, ended);
}

const Trajectory* PlaybackController::ground_truth() const {
  return player_ ? player_->ground_truth() : nullptr;
}

void PlaybackController::SetFrameTap(FrameTap tap) {
  std::lock_guard<std::mutex> lock(mutex_);
  tap_ = std::move(tap);
}

std::optional<SensorStats> PlaybackController::live_stats() const {
  if (live_ == nullptr) return std::nullopt;
  return live_->stats();
}

void PlaybackController::Play() {
  if (!player_) return;
  RestartDrawingPace();
  // Play at the end of a recording starts it again from the first frame (the pipeline starts
  // over, as on a seek back).
  if (ended_ && info_ && info_->seekable && !info_->live) player_->Seek(0);
  player_->Play();
  SetPlayState(true, false);
}
void PlaybackController::Pause() {
  if (!player_) return;
  player_->Pause();
  SetPlayState(false, ended_);
}
void PlaybackController::Step() {
  if (!player_) return;
  RestartDrawingPace();
  player_->Step();
  SetPlayState(false, false);
}
void PlaybackController::Seek(int64_t index) {
  if (!player_) return;
  RestartDrawingPace();
  player_->Seek(index);
  SetPlayState(playing_, false);
}
void PlaybackController::SetSpeed(double factor) {
  speed_ = factor;
  if (player_) player_->SetSpeed(factor);
}
void PlaybackController::SetLoop(bool loop) {
  loop_ = loop;
  if (player_) player_->SetLoop(loop);
}

void PlaybackController::SetViewOptions(const ViewOptions& options) {
  std::shared_ptr<const Frame> frame;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    view_options_ = options;
    frame = last_frame_;
  }
  if (!frame) return;
  // Redraw the current frame with the new options at once, also while paused.
  Track(QtConcurrent::run([this, frame, options] { Publish(Prepare(*frame, options)); }));
}

void PlaybackController::SetProcessorFactory(ProcessorFactory factory, const OptionSet& options) {
  processor_factory_ = std::move(factory);
  {
    std::lock_guard<std::mutex> lock(processor_mutex_);
    processor_options_ = options;
    processor_options_dirty_ = true;
  }
  RebuildProcessor("pipeline switched");
}

void PlaybackController::AbortProcessor(const std::string& reason) {
  std::lock_guard<std::mutex> lock(processor_mutex_);
  if (processor_ && processor_opened_) processor_->Abort(reason);
}

void PlaybackController::RebuildProcessor(const std::string& reason) {
  std::unique_ptr<Pipeline> processor;
  PipelineSource source;
  if (info_) {
    source = source_extras_;
    source.info = *info_;
  }
  if (processor_factory_ && info_) processor = processor_factory_(source);
  std::unique_ptr<Pipeline> previous;
  std::lock_guard<std::mutex> lock(processor_mutex_);
  // Explicitly, not by the destructor, and before the next one may open: e.g. every arm client
  // gets a stop line naming `reason` before the server's port is free again.
  if (processor_ && processor_opened_) processor_->Abort(reason);
  previous = std::move(processor_);
  processor_ = std::move(processor);
  processor_source_ = std::move(source);
  processor_opened_ = false;
  processor_timing_.Clear();
  processor_started_s_ = 0;
  processor_options_dirty_ = true;
  last_processed_id_ = -1;
}

void PlaybackController::SetPipelineOptions(const OptionSet& options) {
  {
    std::lock_guard<std::mutex> lock(processor_mutex_);
    processor_options_ = options;
    processor_options_dirty_ = true;
  }
  std::shared_ptr<const Frame> frame;
  ViewOptions view;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    frame = last_frame_;
    view = view_options_;
  }
  if (!frame) return;
  // Tuning while paused: show the current frame with the new thresholds at once.
  Track(QtConcurrent::run([this, frame, view] {
    auto result = std::const_pointer_cast<PlaybackResult>(Prepare(*frame, view));
    result->pipeline = RunProcessor(*frame, /*replay=*/true);
    Publish(std::move(result));
  }));
}

std::shared_ptr<const PipelineFrameResult> PlaybackController::RunProcessor(const Frame& frame,
                                                                            bool replay,
                                                                            bool* restarted) {
  std::lock_guard<std::mutex> lock(processor_mutex_);
  if (!processor_) return nullptr;
  if (processor_options_dirty_) {
    processor_options_dirty_ = false;
    // A live simulated camera: "button:K" taps and the scene's true hand-eye (sim_panel_source.h).
    OptionSet options = processor_options_;
    const std::string sim_dir = (std::filesystem::temp_directory_path() / "sightline-sim").string();
    const Status prepared = PrepareSimRun(processor_source_.info.path, sim_dir, &options);
    const Status configured = prepared.ok() ? processor_->Configure(options) : prepared;
    if (!configured.ok()) return FailedResult(frame, configured);
  }
  if (!processor_opened_) {
    const Status opened = processor_->Open(processor_source_);
    if (!opened.ok()) return FailedResult(frame, opened);
    processor_opened_ = true;
  }
  const int64_t id = StampOf(frame).sequence_id;
  StatusOr<std::shared_ptr<const PipelineResult>> result = Internal("not run");
  if (replay) {
    result = processor_->Reprocess(frame);
  } else {
    // A seek or a loop breaks a recording's sequence: the pipeline starts over. A live source
    // hands out its newest frame and skips older ones while the pipeline is slower than the
    // camera (a loaded machine): a gap there is dropped frames, not a seek, and must not wipe
    // the run (a SLAM reset on every gap never initialises). Only a restart goes back.
    if (last_processed_id_ >= 0) {
      const bool broken =
          processor_source_.info.live ? id <= last_processed_id_ : id != last_processed_id_ + 1;
      if (broken) processor_->Reset();
      if (restarted != nullptr) *restarted = broken;
    } else if (restarted != nullptr) {
      *restarted = true;
    }
    last_processed_id_ = id;
    const double start = HostTimeS();
    if (processor_started_s_ == 0) processor_started_s_ = start;
    result = processor_->Process(frame);
    if (result.ok()) {
      ++frames_processed_;
      AddFrameTiming(processor_->Statistics(), **result, (HostTimeS() - start) * 1000.0,
                     &processor_timing_);
    }
  }
  if (!result.ok()) return FailedResult(frame, result.status());
  return *result;
}

void PlaybackController::SaveResults(const QString& folder, const QString& pipeline_name) {
  QPointer<PlaybackController> self(this);
  const std::string out_dir = folder.toStdString();
  const std::string name = pipeline_name.toStdString();
  Track(QtConcurrent::run([this, self, folder, out_dir, name] {
    StatusOr<RunReport> report = FailedPrecondition("no pipeline is running: nothing to save");
    {
      std::lock_guard<std::mutex> lock(processor_mutex_);
      if (processor_ && processor_opened_) {
        const double wall_s = processor_started_s_ > 0 ? HostTimeS() - processor_started_s_ : 0;
        report = SaveRun(*processor_, name, processor_source_.info.path, processor_timing_, wall_s,
                         processor_options_, out_dir);
      }
    }
    QStringList files;
    if (report.ok()) {
      for (const std::string& file : report->result.outputs) files << QString::fromStdString(file);
    }
    const QString message =
        report.ok() ? QString() : QString::fromStdString(report.status().ToString());
    QMetaObject::invokeMethod(
        this,
        [self, folder, files, message] {
          if (!self) return;
          if (message.isEmpty()) {
            emit self->ResultsSaved(folder, files);
          } else {
            emit self->SaveFailed(message);
          }
        },
        Qt::QueuedConnection);
  }));
}

std::shared_ptr<const PipelineFrameResult> PlaybackController::FailedResult(const Frame& frame,
                                                                            Status status) {
  auto failed = std::make_shared<PipelineFrameResult>();
  failed->stamp = StampOf(frame);
  failed->status = std::move(status);
  return failed;
}

void PlaybackController::StartWorker(std::unique_ptr<Player> player) {
  player_ = std::move(player);
  // Loop and speed are the window's settings, not the source's: every source opened honours them.
  player_->SetLoop(loop_);
  player_->SetSpeed(speed_);
  stop_ = false;
  worker_ = std::thread([this] { WorkerLoop(); });
  clockid_t clock{};
  if (pthread_getcpuclockid(worker_.native_handle(), &clock) == 0) worker_cpu_clock_ = clock;
  last_delivery_s_ = 0;
}

void PlaybackController::StopWorker() {
  if (!player_) return;
  stop_ = true;
  player_->Stop();
  if (worker_.joinable()) worker_.join();
  worker_cpu_clock_.reset();
  live_ = nullptr;
  player_.reset();
  std::lock_guard<std::mutex> lock(mutex_);
  last_frame_.reset();
  latest_.reset();
}

void PlaybackController::WorkerLoop() {
  while (!stop_) {
    const double start = HostTimeS();
    StatusOr<Frame> frame = player_->Next();
    if (!frame.ok()) {
      const StatusCode code = frame.status().code();
      if (code == StatusCode::kCancelled) break;
      if (code == StatusCode::kOutOfRange) {
        AbortProcessor("source ended");  // Live outputs hear of it before the GUI does.
        QMetaObject::invokeMethod(
            this,
            [this] {
              DeliverLatest();  // The last frame reaches the views before the end is told.
              SetPlayState(false, true);
              emit EndOfStream();
            },
            Qt::QueuedConnection);
        continue;  // Next() waits for Play, Step or Seek.
      }
      const QString message = QString::fromStdString(frame.status().ToString());
      if (code == StatusCode::kUnavailable && info_ && info_->live) {
        // A sensor timed out or went away: say so (once per outage) and keep trying; the
        // source reconnects by itself.
        if (!live_outage_) {
          live_outage_ = true;
          QMetaObject::invokeMethod(
              this, [this, message] { emit ReadError(message); }, Qt::QueuedConnection);
        }
        continue;
      }
      player_->Pause();
      QMetaObject::invokeMethod(
          this,
          [this, message] {
            SetPlayState(false, false);
            emit ReadError(message);
          },
          Qt::QueuedConnection);
      continue;
    }
    live_outage_ = false;
    const double got_s = HostTimeS();  // From here on the worker works rather than waits.
    auto shared = std::make_shared<const Frame>(std::move(*frame));
    ViewOptions options;
    FrameTap tap;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      last_frame_ = shared;
      options = view_options_;
      tap = tap_;
    }
    if (tap) tap(*shared);
    auto result = std::const_pointer_cast<PlaybackResult>(Prepare(*shared, options));
    result->pipeline = RunProcessor(*shared, /*replay=*/false, &result->pipeline_restarted);
    result->prepare_ms = (HostTimeS() - start) * 1000;
    Publish(std::move(result));
    worker_busy_us_ += static_cast<int64_t>((HostTimeS() - got_s) * 1e6);
  }
}

std::shared_ptr<const PlaybackResult> PlaybackController::Prepare(
    const Frame& frame, const ViewOptions& options) const {
  std::shared_ptr<const SourceInfo> info;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    info = info_;
  }
  auto result = std::make_shared<PlaybackResult>();
  result->stamp = StampOf(frame);
  result->frame_count = info ? info->frame_count : -1;
  if (const auto* rgbd = std::get_if<RgbdFrame>(&frame)) {
    result->primary_image = rgbd->color;
    result->secondary_image = rgbd->depth_m;
    result->secondary_is_depth = true;
    // The cloud is made by the GUI for the frames it shows (MakeCloud), not for every frame.
    result->cloud_stride = options.cloud_stride;
    result->max_depth_m = options.max_depth_m;
  } else if (const auto* stereo = std::get_if<StereoFrame>(&frame)) {
    result->primary_image = stereo->left;
    result->secondary_image = stereo->right;
  } else if (const auto* mono = std::get_if<MonoFrame>(&frame)) {
    result->primary_image = mono->image;
  } else if (const auto* cloud = std::get_if<CloudFrame>(&frame)) {
    result->cloud = cloud->cloud;
  }
  return result;
}

std::shared_ptr<const PointCloud> PlaybackController::MakeCloud(
    const PlaybackResult& result) const {
  if (result.cloud) return result.cloud;
  std::shared_ptr<const SourceInfo> info;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    info = info_;
  }
  if (!result.secondary_is_depth || !info || !info->rgbd || result.secondary_image.empty() ||
      result.primary_image.empty()) {
    return nullptr;
  }
  cv::Mat depth = result.secondary_image.clone();
  depth.setTo(std::numeric_limits<float>::quiet_NaN(), depth > result.max_depth_m);
  return std::make_shared<PointCloud>(
      DepthToCloud(depth, result.primary_image, info->rgbd->color, result.cloud_stride));
}

void PlaybackController::Publish(std::shared_ptr<const PlaybackResult> result) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    // A restart carried by a result the views never took must not be lost with it: the views
    // would go on drawing the previous run's trajectory under the new one.
    if (latest_ && delivery_pending_ && latest_->pipeline_restarted &&
        !result->pipeline_restarted) {
      auto merged = std::make_shared<PlaybackResult>(*result);
      merged->pipeline_restarted = true;
      result = std::move(merged);
    }
    latest_ = std::move(result);
    if (delivery_pending_) return;  // The GUI has not taken the previous one: replace it.
    delivery_pending_ = true;
  }
  QMetaObject::invokeMethod(this, &PlaybackController::DeliverWhenDue, Qt::QueuedConnection);
}

void PlaybackController::DeliverWhenDue() {
  // The views draw at most one frame per interval: the worker never waits for them, the newest
  // result replaces a pending one, and the frames the views cannot draw in time are skipped.
  const double wait_s = last_delivery_s_ + delivery_interval_s_ - HostTimeS();
  if (wait_s > 0) {
    QTimer::singleShot(static_cast<int>(std::ceil(wait_s * 1000)), this,
                       &PlaybackController::DeliverLatest);
    return;
  }
  DeliverLatest();
}

void PlaybackController::DeliverLatest() {
  std::shared_ptr<const PlaybackResult> result;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    result = std::move(latest_);
    delivery_pending_ = false;
  }
  if (!result) return;
  UpdateDrawingPace();
  emit FrameReady(std::move(result));
}

void PlaybackController::UpdateDrawingPace() {
  // What the rest of the process (the GUI thread, the 3D view's rasteriser threads) spent since
  // the last frame handed over, against what the worker spent: on a machine the pipeline has
  // to share, every millisecond of drawing is one the pipeline waits for. The interval keeps
  // drawing within kDrawShare of the worker's time, and at the full rate when it has time.
  const double now_s = HostTimeS();
  const double process_cpu_s = ThreadCpuS(CLOCK_PROCESS_CPUTIME_ID);
  const double worker_cpu_s = worker_cpu_clock_ ? ThreadCpuS(*worker_cpu_clock_) : 0;
  const double wall_s = now_s - last_delivery_s_;
  const int64_t busy_us = worker_busy_us_.load();
  if (last_delivery_s_ > 0 && wall_s < 2.0) {
    // A worker that waits for its frames (a recording played at its own rate, a camera) has
    // time to spare: drawing does not hold it back.
    const double busy_share = 1e-6 * static_cast<double>(busy_us - last_worker_busy_us_) / wall_s;
    const double worker_s = std::max(0.0, worker_cpu_s - last_worker_cpu_s_);
    const double drawing_s = std::max(0.0, (process_cpu_s - last_process_cpu_s_) - worker_s);
    draw_cpu_s_ = draw_cpu_s_ > 0 ? 0.7 * draw_cpu_s_ + 0.3 * drawing_s : drawing_s;
    const double worker_rate = worker_s / wall_s;  // Cores the pipeline uses.
    worker_rate_ = worker_rate_ > 0 ? 0.7 * worker_rate_ + 0.3 * worker_rate : worker_rate;
    // A recording played as fast as possible is all work (reading and decoding included).
    const bool flat_out = speed_ == 0 && info_ && !info_->live;
    delivery_interval_s_ = !flat_out && busy_share < kBusyShare
                               ? kMinDeliveryInterval_s
                               : std::clamp(draw_cpu_s_ / (kDrawShare * worker_rate_),
                                            kMinDeliveryInterval_s, kMaxDeliveryInterval_s);
  }
  last_delivery_s_ = now_s;
  last_worker_busy_us_ = busy_us;
  last_process_cpu_s_ = process_cpu_s;
  last_worker_cpu_s_ = worker_cpu_s;
}

void PlaybackController::RestartDrawingPace() {
  last_delivery_s_ = 0;
  delivery_interval_s_ = kMinDeliveryInterval_s;
}

double PlaybackController::ThreadCpuS(clockid_t clock) {
  timespec t{};
  if (clock_gettime(clock, &t) != 0) return 0;
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace sightline
