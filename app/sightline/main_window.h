// Sightline's main window: dockable colour, depth and 3D views, the tuning panel, the log and
// the playback bar around one PlaybackController.
#pragma once

#include <QMainWindow>
#include <QStringList>
#include <memory>
#include <vector>

#include "app/sightline/playback_result.h"
#include "core/options/option_set.h"

class QAction;
class QActionGroup;
class QDockWidget;
class QLabel;
class QMenu;
class QTemporaryDir;

namespace sightline {

class DemoGenerator;
class EvaluationPanel;
class ImageView;
class LiveStatusWidget;
class LogPanel;
class ParameterPanel;
class PlaybackBar;
class PipelinePresenter;
class PlaybackController;
class RecordingController;
class RosNodeView;
class RemoteOperatorPresenter;
class SceneView;

// The window a lab engineer or presenter works in. It holds views and wiring only: reading and
// processing happen in PlaybackController's worker thread.
class MainWindow : public QMainWindow {
  Q_OBJECT

 public:
  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;

  // Opens a dataset folder or file in the background (File > Open, drag and drop, --open).
  void OpenPath(const QString& path);
  // Shows the demo's generation progress and errors in the status bar and the log.
  void ShowDemoProgress(DemoGenerator* demo);
  // Starts playback with looping on (the demo).
  void PlayLooping();
  // Adds a pipeline to the Pipeline menu.
  void AddPipeline(PipelinePresenter* presenter);
  // Makes a pipeline (by menu title) the one that runs on every frame; "" for none.
  bool ActivatePipeline(const QString& title);
  // Activates the first pipeline whose title, translated or English, contains `word` (any
  // case), e.g. "stereo".
  bool ActivatePipelineByWord(const QString& word);
  // Applies a YAML profile (when `profile` is not empty), then "key=value" assignments, to the
  // active pipeline's options, as `sightline-cli run --profile --set` does: all or nothing, the
  // error naming the file, line or key.
  Status ApplyOptionArguments(const QString& profile, const QStringList& assignments);
  PipelinePresenter* active_pipeline() const { return active_pipeline_; }

  SceneView* scene_view() const { return scene_view_; }
  EvaluationPanel* evaluation_panel() const { return evaluation_panel_; }
  PlaybackController* playback() const { return playback_; }
  // Sensors > Record / Stop recording, and the status bar's live-sensor indicator.
  RecordingController* recording() const { return recording_; }
  LiveStatusWidget* live_status() const { return live_status_; }
  // File > Connect to ROS master: watches a sightline-node's map, odometry, walls and clouds
  // (main_window_ros.cpp). The error names a bad URI or namespace.
  Status ConnectRos(const QString& master_uri, const QString& ros_namespace);
  RosNodeView* ros_node() const { return ros_node_; }
  // The operator panel of a connected sightline-node that runs the button pipeline.
  RemoteOperatorPresenter* remote_operator() const { return remote_operator_; }
  // File > Save results: writes the running pipeline's results into `folder` as `sightline-cli
  // run` does (background; ResultsSaved or ResultsSaveFailed follows).
  void SaveResultsTo(const QString& folder);
  // Tools > Evaluate current run: the run's trajectory against the dataset's ground truth, in
  // the evaluation dock.
  void EvaluateCurrentRun();
  // Settings > Language: switches the GUI's language now ("" = the system's, else a code of
  // Languages()) and, when `save`, keeps the choice for the next start. Returns the code in
  // effect.
  QString SetLanguage(const QString& code, bool save);
  // The docks, their sizes and the visible views are saved on close and restored at the next
  // start; View > Reset layout brings back the layout the window opens with the first time.
  void SaveLayout();
  void ResetLayout();
  // Frames shown since the last open.
  int64_t frames_shown() const { return frames_shown_; }
  // Frames the active pipeline has processed since it last started over (open, switch, seek).
  int64_t pipeline_frames() const { return pipeline_frames_; }

 signals:
  // A frame reached the views (after they were updated).
  void FrameShown(int64_t sequence_id);
  void DatasetOpened(const QString& path);
  void DatasetFailed(const QString& message);
  void ResultsSaved(const QString& folder);
  void ResultsSaveFailed(const QString& message);

 protected:
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dropEvent(QDropEvent* event) override;
  void closeEvent(QCloseEvent* event) override;

 private:
  void BuildViews();
  void BuildMenus();
  // Record / Stop actions (menu and toolbar), recording progress and the live status
  // (main_window_recording.cpp).
  void BuildRecording(QMenu* sensors);
  // File > Save results (main_window_results.cpp).
  void BuildResults(QMenu* file);
  // File > Connect to ROS master / Disconnect and the "ROS node" dock (main_window_ros.cpp).
  void BuildRos(QMenu* file);
  void BuildSettings();
  void BuildLayoutMemory();
  void EvaluateSavedRun(const QString& folder);
  void ConnectPlayback();
  // The playback bar's seek (main_window_playback.cpp): a pipeline that builds a map (SLAM,
  // odometry) starts over at a seek, so the window asks first; a drag asks once, at release.
  void OnSeekRequested(int64_t index);
  bool ConfirmMapReset();
  // Empties every image view and plot of the previous run (pipeline docks, evaluation).
  void ClearRunViews();
  void ShowFrame(const std::shared_ptr<const PlaybackResult>& result);
  // The colour, depth (or right) images and the cloud of a frame.
  void ShowImages(const PlaybackResult& result);
  void OnOpened(const QString& path);
  void OnOptionsChanged(const OptionSet& options);
  void ShowWelcome();
  void AddRecent(const QString& path);
  void RebuildRecentMenu();

  PlaybackController* playback_ = nullptr;
  RecordingController* recording_ = nullptr;
  LiveStatusWidget* live_status_ = nullptr;
  RosNodeView* ros_node_ = nullptr;
  RemoteOperatorPresenter* remote_operator_ = nullptr;
  ImageView* primary_view_ = nullptr;
  ImageView* secondary_view_ = nullptr;
  QDockWidget* primary_dock_ = nullptr;
  QDockWidget* evaluation_dock_ = nullptr;
  EvaluationPanel* evaluation_panel_ = nullptr;
  QDockWidget* secondary_dock_ = nullptr;
  SceneView* scene_view_ = nullptr;
  ParameterPanel* parameter_panel_ = nullptr;
  LogPanel* log_panel_ = nullptr;
  PlaybackBar* playback_bar_ = nullptr;
  QLabel* status_label_ = nullptr;
  QMenu* recent_menu_ = nullptr;
  QMenu* view_menu_ = nullptr;
  QMenu* pipeline_menu_ = nullptr;
  QActionGroup* pipeline_actions_ = nullptr;
  QActionGroup* language_actions_ = nullptr;
  QByteArray default_state_;  // The dock layout before any saved one was restored.
  std::vector<PipelinePresenter*> pipelines_;
  PipelinePresenter* active_pipeline_ = nullptr;
  OptionSet options_;
  int64_t frames_shown_ = 0;
  int64_t pipeline_frames_ = 0;
  int64_t last_shown_id_ = 0;
  int64_t pending_seek_ = -1;  // A seek asked for during a slider drag, done at release.
  bool first_cloud_ = true;
  std::unique_ptr<QTemporaryDir> evaluation_folder_;  // Where Evaluate current run saves.
};

}  // namespace sightline
