// Opens a dataset and plays it on a worker thread; hands prepared frames to the GUI.
#pragma once

#include <QFuture>
#include <QObject>
#include <QString>
#include <QStringList>
#include <atomic>
#include <ctime>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include "app/sightline/playback_result.h"
#include "app/sightline/view_options.h"
#include "core/common/timing.h"
#include "core/io/source.h"
#include "core/sensors/sensor_stats.h"

namespace sightline {

class LiveSource;
class Player;

// Owns the reading thread. All public methods are called on the GUI thread and never block on
// file I/O; results arrive through the FrameReady signal, coalesced so that a busy GUI always
// gets the newest frame rather than a backlog.
//
//   PlaybackController playback;
//   connect(&playback, &PlaybackController::FrameReady, view, &View::Show);
//   playback.Open("/data/tum_fr1_desk");   // Opened() or OpenFailed() follows.
//   playback.Play();
class PlaybackController : public QObject {
  Q_OBJECT

 public:
  explicit PlaybackController(QObject* parent = nullptr);
  ~PlaybackController() override;

  // Opens a dataset, a recording (.oni) or a sensor URI (openni2://, aravis://, v4l2://) in the
  // background; emits Opened or OpenFailed.
  void Open(const QString& path);
  // Closes the source; the running pipeline is told first (Pipeline::Abort with `reason`, e.g.
  // arm clients get a stop line naming it).
  void Close(const std::string& reason = "source closed");
  void Play();
  void Pause();
  void Step();
  void Seek(int64_t index);
  // Speed and loop hold for the open source and every one opened later.
  void SetSpeed(double factor);
  void SetLoop(bool loop);
  bool loop() const { return loop_; }
  // New view options, applied to the next frame and to the current one at once.
  void SetViewOptions(const ViewOptions& options);

  // Makes a pipeline's object for an opened source (its calibration, folder and ground truth).
  using ProcessorFactory = std::function<std::unique_ptr<Pipeline>(const PipelineSource& source)>;
  // Runs a pipeline on every frame from now on (nullptr: none). Also made anew on each Open.
  void SetProcessorFactory(ProcessorFactory factory, const OptionSet& options);
  // New pipeline options: applied before the next frame, and the current frame is run again.
  void SetPipelineOptions(const OptionSet& options);

  // Writes the running pipeline's results so far into `folder`, exactly the files `sightline-cli
  // run` writes (metrics.json included), in the background; emits ResultsSaved or SaveFailed.
  // `pipeline_name` is the registry's name, written into metrics.json.
  void SaveResults(const QString& folder, const QString& pipeline_name);

  // Called on the reading thread with every frame read (the recorder); nullptr removes it, and
  // so does opening another source.
  using FrameTap = std::function<void(const Frame& frame)>;
  void SetFrameTap(FrameTap tap);
  // The open source's counters when it is a live sensor (a thread-safe snapshot), else nullopt.
  std::optional<SensorStats> live_stats() const;

  bool is_open() const { return static_cast<bool>(info_); }
  // Frames are being played (Play), not paused, stepped or at the end (GUI thread).
  bool playing() const { return playing_; }
  // Playback reached the end of a recording and waits (GUI thread).
  bool ended() const { return ended_; }
  // Valid after Opened().
  const SourceInfo* info() const { return info_.get(); }
  // The 3D cloud of a prepared RGB-D frame (depth and colour through the open source's
  // calibration, with the view options of the frame), or its own cloud; nullptr when it has
  // none. Made on request: only the frames a visible 3D view draws pay for it.
  std::shared_ptr<const PointCloud> MakeCloud(const PlaybackResult& result) const;
  const Trajectory* ground_truth() const;
  // Frames the pipelines have processed since this controller was made (any thread): every
  // frame played, whether or not the views drew its result.
  int64_t frames_processed() const { return frames_processed_.load(); }

 signals:
  void Opened(const QString& path);
  void OpenFailed(const QString& path, const QString& message);
  void FrameReady(std::shared_ptr<const sightline::PlaybackResult> result);
  // Soon after Opened, for a recording: its first frame prepared for the views (no pipeline
  // result), while the player still waits before it. Not a frame played: no FrameReady.
  void FirstFrame(std::shared_ptr<const sightline::PlaybackResult> result);
  // A frame could not be read; playback pauses. The message names the file.
  void ReadError(const QString& message);
  void EndOfStream();
  // playing() or ended() changed: emitted at once on Pause, Step, Seek and the end.
  void PlayStateChanged(bool playing, bool ended);
  // SaveResults finished: the folder and the files written in it.
  void ResultsSaved(const QString& folder, const QStringList& files);
  void SaveFailed(const QString& message);

 private:
  // Reads a seekable recording's first frame and rewinds (any thread); nullptr otherwise.
  static std::shared_ptr<const Frame> ReadFirstFrame(Source& source);
  // Prepares `frame` in the background and emits FirstFrame unless another Open came since.
  void PublishPreview(std::shared_ptr<const Frame> frame, uint64_t generation);
  void StartWorker(std::unique_ptr<Player> player);
  void StopWorker();
  void WorkerLoop();
  std::shared_ptr<const PlaybackResult> Prepare(const Frame& frame,
                                                const ViewOptions& options) const;
  // Stores the newest result and notifies the GUI unless a notification is already pending.
  void Publish(std::shared_ptr<const PlaybackResult> result);
  // Hands the newest result to the views now, or when the drawing interval has passed.
  void DeliverWhenDue();
  void DeliverLatest();
  // Sets the next delivery interval from the CPU time drawing took (GUI thread).
  void UpdateDrawingPace();
  // Playing starts, steps or seeks: the pace is measured anew (GUI thread).
  void RestartDrawingPace();
  // A CPU-time clock's reading in seconds (0 when it cannot be read).
  static double ThreadCpuS(clockid_t clock);
  // Builds the processor for the current source from the factory (GUI thread); the previous
  // one is aborted with `reason` first (its live outputs, e.g. arm clients, are told).
  void RebuildProcessor(const std::string& reason);
  // Tells the running processor that its run ends (any thread).
  void AbortProcessor(const std::string& reason);
  void SetPlayState(bool playing, bool ended);
  // Runs the processor on a frame (any thread; serialised by processor_mutex_).
  // `restarted` (optional): set when the pipeline started over at this frame (its first frame,
  // or a seek or loop that broke the recording's sequence).
  std::shared_ptr<const PipelineFrameResult> RunProcessor(const Frame& frame, bool replay,
                                                          bool* restarted = nullptr);
  // A result that says why a frame gave none.
  static std::shared_ptr<const PipelineFrameResult> FailedResult(const Frame& frame, Status status);
  // Keeps a background task's future so the destructor can wait for it.
  void Track(QFuture<void> future);

  std::unique_ptr<Player> player_;
  const LiveSource* live_ = nullptr;  // The source inside player_ when it is live (GUI thread).
  std::shared_ptr<const SourceInfo> info_;
  std::thread worker_;
  std::atomic<bool> stop_{false};
  bool live_outage_ = false;  // Worker thread only: a live source is currently not delivering.
  uint64_t open_generation_ = 0;
  std::vector<QFuture<void>> background_;  // GUI thread only.
  bool playing_ = false;                   // GUI thread only.
  bool ended_ = false;                     // GUI thread only.
  bool loop_ = false;                      // GUI thread only.
  double speed_ = 1.0;                     // GUI thread only.

  ProcessorFactory processor_factory_;  // GUI thread only.
  // The open source's ground truth and odometry (PipelineSource::From); GUI thread only.
  PipelineSource source_extras_;

  std::mutex processor_mutex_;  // Guards the processor and its bookkeeping.
  std::unique_ptr<Pipeline> processor_;
  PipelineSource processor_source_;  // What processor_ is opened on.
  bool processor_opened_ = false;
  OptionSet processor_options_;
  bool processor_options_dirty_ = false;
  int64_t last_processed_id_ = -1;
  TimingStats processor_timing_;    // This run's per-stage timing, as metrics.json reports it.
  double processor_started_s_ = 0;  // Host time of the run's first frame (0: none yet).
  std::atomic<int64_t> frames_processed_{0};

  mutable std::mutex mutex_;  // Guards everything below.
  ViewOptions view_options_;
  std::shared_ptr<const Frame> last_frame_;
  bool reprocess_ = false;
  std::shared_ptr<const PlaybackResult> latest_;
  bool delivery_pending_ = false;

  // Drawing pace (GUI thread): a frame is handed to the views at most every
  // delivery_interval_s_. While the worker is busy with frames, it is chosen so that drawing
  // (the process's CPU time outside the worker) takes at most kDrawShare of the worker's CPU
  // time, between the bounds below (the views
  // show at least 2 frames a second).
  static constexpr double kDrawShare = 0.2;
  static constexpr double kMinDeliveryInterval_s = 1.0 / 30;
  static constexpr double kMaxDeliveryInterval_s = 0.5;
  // Below this share of wall time spent working (not waiting for frames) the worker has time
  // to spare and the views draw at the full rate.
  static constexpr double kBusyShare = 0.8;
  std::atomic<int64_t> worker_busy_us_{0};  // Worker time spent on frames, microseconds.
  int64_t last_worker_busy_us_ = 0;
  std::optional<clockid_t> worker_cpu_clock_;  // The worker thread's CPU-time clock.
  double last_delivery_s_ = 0;
  double last_process_cpu_s_ = 0;
  double last_worker_cpu_s_ = 0;
  double draw_cpu_s_ = 0;   // Smoothed CPU seconds of drawing per frame handed over.
  double worker_rate_ = 0;  // Smoothed cores the worker used.
  double delivery_interval_s_ = kMinDeliveryInterval_s;
  FrameTap tap_;
};

}  // namespace sightline
