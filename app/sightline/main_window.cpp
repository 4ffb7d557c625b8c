#include "app/sightline/main_window.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QPointer>
#include <QProgressBar>
#include <QScreen>
#include <QSettings>
#include <QSlider>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTimer>
#include <QToolBar>

#include "app/sightline/calibration_dialog.h"
#include "app/sightline/core_texts.h"
#include "app/sightline/demo_generator.h"
#include "app/sightline/evaluation_panel.h"
#include "app/sightline/pipeline_presenter.h"
#include "app/sightline/playback_controller.h"
#include "app/sightline/view_options.h"
#include "core/sensors/driver_registry.h"
#include "widgets/image_view.h"
#include "widgets/log_panel.h"
#include "widgets/parameter_panel.h"
#include "widgets/playback_bar.h"
#include "widgets/scene_view.h"

namespace sightline {

namespace {
constexpr int kMaxRecent = 8;
const char kRecentKey[] = "recent_paths";
}  // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
  setWindowTitle(tr("Sightline"));
  setAcceptDrops(true);
  // 1400x900, or 90 % of a smaller screen.
  QSize size(1400, 900);
  if (const QScreen* screen = QGuiApplication::primaryScreen()) {
    size = size.boundedTo(screen->availableSize() * 0.9);
  }
  resize(size);
  playback_ = new PlaybackController(this);
  Status declared = options_.Declare(ViewOptions::Describe());
  BuildViews();
  BuildMenus();
  ConnectPlayback();
  if (!declared.ok())
    log_panel_->AddMessage(LogPanel::Severity::kError, QString::fromStdString(declared.ToString()));
  ShowWelcome();
}

MainWindow::~MainWindow() = default;

void MainWindow::BuildViews() {
  scene_view_ = new SceneView(this);
  scene_view_->setMinimumSize(320, 240);
  setCentralWidget(scene_view_);

  auto add_dock = [this](QWidget* widget, const QString& title, const QString& name,
                         Qt::DockWidgetArea area) {
    auto* dock = new QDockWidget(title, this);
    dock->setObjectName(name);
    dock->setWidget(widget);
    addDockWidget(area, dock);
    return dock;
  };
  primary_view_ = new ImageView(this);
  secondary_view_ = new ImageView(this);
  primary_dock_ = add_dock(primary_view_, tr("Colour"), "colour_dock", Qt::LeftDockWidgetArea);
  secondary_dock_ = add_dock(secondary_view_, tr("Depth"), "depth_dock", Qt::LeftDockWidgetArea);

  parameter_panel_ = new ParameterPanel(this);
  parameter_panel_->SetProfileExclusion("view.");  // Profiles hold pipeline options only.
  parameter_panel_->SetOptions(options_);
  QDockWidget* parameters_dock =
      add_dock(parameter_panel_, tr("Parameters"), "parameters_dock", Qt::RightDockWidgetArea);
  log_panel_ = new LogPanel(this);
  QDockWidget* log_dock = add_dock(log_panel_, tr("Log"), "log_dock", Qt::RightDockWidgetArea);
  evaluation_panel_ = new EvaluationPanel(this);
  evaluation_dock_ =
      add_dock(evaluation_panel_, tr("Evaluation"), "evaluation_dock", Qt::RightDockWidgetArea);
  tabifyDockWidget(log_dock, evaluation_dock_);
  log_dock->raise();
  // The images and the 3D view get the full height; dock sizes apply once the window has its
  // size, hence after the first event-loop turn.
  // Tuning needs a dozen rows in sight: the Parameters dock takes the right side's height but
  // what the log and the evaluation need (they stay readable, and grow when dragged).
  QTimer::singleShot(0, this, [this, parameters_dock, log_dock] {
    resizeDocks({primary_dock_}, {420}, Qt::Horizontal);
    resizeDocks({parameters_dock, log_dock}, {4, 1}, Qt::Vertical);
  });

  playback_bar_ = new PlaybackBar(this);
  auto* bar = new QToolBar(tr("Playback"), this);
  bar->setObjectName("playback_toolbar");
  bar->addWidget(playback_bar_);
  addToolBar(Qt::BottomToolBarArea, bar);

  status_label_ = new QLabel(this);
  statusBar()->addPermanentWidget(status_label_);
}

void MainWindow::BuildMenus() {
  QMenu* file = menuBar()->addMenu(tr("&File"));
  QAction* open_folder = file->addAction(tr("&Open dataset folder..."));
  open_folder->setShortcut(QKeySequence::Open);
  connect(open_folder, &QAction::triggered, this, [this] {
    const QString dir = QFileDialog::getExistingDirectory(this, tr("Open dataset folder"));
    if (!dir.isEmpty()) OpenPath(dir);
  });
  QAction* open_file = file->addAction(tr("Open recording &file (PCD, ONI)..."));
  connect(open_file, &QAction::triggered, this, [this] {
    const QString path = QFileDialog::getOpenFileName(this, tr("Open point cloud"), QString(),
                                                      tr("Recordings (*.pcd *.oni *.bag)"));
    if (!path.isEmpty()) OpenPath(path);
  });
  recent_menu_ = file->addMenu(tr("Open &recent"));
  RebuildRecentMenu();
  file->addSeparator();
  BuildResults(file);
  file->addSeparator();
  BuildRos(file);
  file->addSeparator();
  QAction* quit = file->addAction(tr("&Quit"));
  quit->setShortcut(QKeySequence::Quit);
  connect(quit, &QAction::triggered, this, &QWidget::close);

  view_menu_ = menuBar()->addMenu(tr("&View"));
  view_menu_->setObjectName("view_menu");  // Pipelines add their views here, whatever the language.
  QAction* reset = view_menu_->addAction(tr("&Reset 3D view"));
  reset->setShortcut(Qt::Key_R | Qt::CTRL);
  connect(reset, &QAction::triggered, scene_view_, &SceneView::ResetView);
  QAction* follow = view_menu_->addAction(tr("&Follow the trajectory"));
  follow->setObjectName("follow_action");
  follow->setToolTip(tr("Fit the 3D view again whenever a growing trajectory leaves it."));
  follow->setCheckable(true);
  follow->setChecked(scene_view_->follow());
  connect(follow, &QAction::toggled, scene_view_, &SceneView::SetFollow);
  view_menu_->addSeparator();
  for (QDockWidget* dock : findChildren<QDockWidget*>())
    view_menu_->addAction(dock->toggleViewAction());

  // Every sensor driver, greyed out with the reason when it cannot run here.
  QMenu* sensors = menuBar()->addMenu(tr("&Sensors"));
  sensors->setToolTipsVisible(true);
  for (const DriverInfo& driver : BuiltinDrivers()) {
    if (driver.name == "rosbag") continue;  // Files: File > Open recording file.
    const Status available = driver.available ? driver.available() : Status::Ok();
    QString text = CoreText(driver.description);
    text.replace('&', QStringLiteral("&&"));  // "?fps=30&loop=1" is no accelerator.
    if (!available.ok()) text += tr(" (unavailable)");
    QAction* connect_action = sensors->addAction(text);
    connect_action->setEnabled(available.ok());
    connect_action->setToolTip(
        available.ok()
            ? tr("Connect to the first %1 device").arg(QString::fromStdString(driver.name))
            : QString::fromStdString(available.message()));
    const QString uri = QString::fromStdString(driver.scheme);
    const bool needs_folder = driver.name == "replay";  // replay://PATH plays a recording.
    connect(connect_action, &QAction::triggered, this, [this, uri, needs_folder] {
      if (!needs_folder) return OpenPath(uri);
      const QString dir = QFileDialog::getExistingDirectory(this, tr("Replay recording"));
      if (!dir.isEmpty()) OpenPath(uri + dir);
    });
  }
  BuildRecording(sensors);

  pipeline_menu_ = menuBar()->addMenu(tr("&Pipeline"));
  pipeline_actions_ = new QActionGroup(this);
  QAction* none = pipeline_menu_->addAction(tr("None (show frames only)"));
  none->setCheckable(true);
  none->setChecked(true);
  pipeline_actions_->addAction(none);
  connect(none, &QAction::triggered, this, [this] { ActivatePipeline(QString()); });
  pipeline_menu_->addSeparator();

  QMenu* tools = menuBar()->addMenu(tr("&Tools"));
  QAction* evaluate = tools->addAction(tr("&Evaluate trajectory..."));
  connect(evaluate, &QAction::triggered, this, [this] {
    evaluation_dock_->show();
    evaluation_dock_->raise();
  });
  QAction* evaluate_run = tools->addAction(tr("Evaluate &current run"));
  evaluate_run->setToolTip(
      tr("Compares the running pipeline's trajectory with the dataset's ground truth."));
  connect(evaluate_run, &QAction::triggered, this, &MainWindow::EvaluateCurrentRun);
  connect(tools->addAction(tr("&Calibrate camera...")), &QAction::triggered, this, [this] {
    const SourceInfo* info = playback_->info();
    OpenCalibrationDialog(this, info ? QString::fromStdString(info->path) : QString());
  });

  BuildSettings();
  BuildLayoutMemory();
  QMenu* help = menuBar()->addMenu(tr("&Help"));
  connect(help->addAction(tr("&About Sightline")), &QAction::triggered, this, [this] {
    QMessageBox::about(this, tr("About Sightline"),
                       tr("Sightline: robot perception for assistive and mobile robotics.\n"
                          "Indoor mapping, mobility maps, stereo odometry and monocular "
                          "button localisation on live sensors or recorded data."));
  });
}

void MainWindow::ConnectPlayback() {
  connect(playback_, &PlaybackController::FrameReady, this, &MainWindow::ShowFrame);
  // A recording's first frame in the views at once, before Play (nothing is counted as shown).
  connect(playback_, &PlaybackController::FirstFrame, this,
          [this](const std::shared_ptr<const PlaybackResult>& result) {
            if (result && frames_shown_ == 0) ShowImages(*result);
          });
  connect(playback_, &PlaybackController::Opened, this, &MainWindow::OnOpened);
  connect(playback_, &PlaybackController::OpenFailed, this,
          [this](const QString& path, const QString& message) {
            log_panel_->AddMessage(LogPanel::Severity::kError,
                                   tr("Could not open %1: %2").arg(path, message));
            statusBar()->showMessage(tr("Could not open %1").arg(path), 10000);
            emit DatasetFailed(message);
          });
  connect(playback_, &PlaybackController::ReadError, this, [this](const QString& message) {
    log_panel_->AddMessage(LogPanel::Severity::kError, message);
    playback_bar_->SetPlaying(false);
  });
  connect(playback_, &PlaybackController::EndOfStream, this, [this] {
    log_panel_->AddMessage(LogPanel::Severity::kInfo, tr("End of recording."));
    playback_bar_->SetPlaying(false);
  });
  connect(playback_bar_, &PlaybackBar::PlayRequested, this, [this] {
    playback_->Play();
    playback_bar_->SetPlaying(true);
  });
  connect(playback_bar_, &PlaybackBar::PauseRequested, this, [this] {
    playback_->Pause();
    playback_bar_->SetPlaying(false);
  });
  connect(playback_bar_, &PlaybackBar::StepRequested, this, [this] {
    playback_->Step();
    playback_bar_->SetPlaying(false);
  });
  connect(playback_bar_, &PlaybackBar::SeekRequested, this, &MainWindow::OnSeekRequested);
  connect(playback_bar_->slider(), &QSlider::sliderReleased, this, [this] {
    const int64_t pending = pending_seek_;
    pending_seek_ = -1;
    if (pending >= 0) OnSeekRequested(pending);
  });
  connect(playback_bar_, &PlaybackBar::SpeedChanged, playback_, &PlaybackController::SetSpeed);
  connect(playback_bar_, &PlaybackBar::LoopChanged, playback_, &PlaybackController::SetLoop);
  connect(parameter_panel_, &ParameterPanel::OptionsChanged, this, &MainWindow::OnOptionsChanged);
}

void MainWindow::ShowDemoProgress(DemoGenerator* demo) {
  auto* bar = new QProgressBar(this);
  bar->setMaximumWidth(240);
  bar->setFormat(tr("Demo %p%"));
  bar->hide();
  statusBar()->addWidget(bar);
  connect(demo, &DemoGenerator::Progress, this, [this, bar](int done, int total) {
    if (bar->isHidden()) {
      bar->show();
      log_panel_->AddMessage(LogPanel::Severity::kInfo,
                             tr("Generating the demo recordings (only the first time)..."));
    }
    bar->setRange(0, total);
    bar->setValue(done);
  });
  connect(demo, &DemoGenerator::Ready, this, [this, bar, demo] {
    bar->deleteLater();
    log_panel_->AddMessage(
        LogPanel::Severity::kInfo,
        tr("Demo: a robot drives a simulated office corridor (RGB-D, stereo, wheel odometry, "
           "exact ground truth). The arm-camera panel approach is in %1.")
            .arg(demo->panel_path()));
  });
  connect(demo, &DemoGenerator::Failed, this, [this, bar](const QString& message) {
    bar->deleteLater();
    log_panel_->AddMessage(LogPanel::Severity::kError,
                           tr("The demo could not be made: %1").arg(message));
    emit DatasetFailed(message);
  });
}

void MainWindow::PlayLooping() {
  playback_->SetLoop(true);
  playback_bar_->SetLoop(true);
  playback_->Play();
  playback_bar_->SetPlaying(true);
}

void MainWindow::AddPipeline(PipelinePresenter* presenter) {
  presenter->setParent(this);
  pipelines_.push_back(presenter);
  QAction* action = pipeline_menu_->addAction(presenter->Title());
  action->setCheckable(true);
  pipeline_actions_->addAction(action);
  // The title at the time of the click: the language may have changed since.
  connect(action, &QAction::triggered, this,
          [this, presenter] { ActivatePipeline(presenter->Title()); });
  connect(presenter, &PipelinePresenter::Message, this, [this](int severity, const QString& text) {
    log_panel_->AddMessage(severity >= 2   ? LogPanel::Severity::kError
                           : severity == 1 ? LogPanel::Severity::kWarning
                                           : LogPanel::Severity::kInfo,
                           text);
  });
}

bool MainWindow::ActivatePipeline(const QString& title) {
  PipelinePresenter* next = nullptr;
  for (PipelinePresenter* p : pipelines_) {
    if (p->Title() == title) next = p;
  }
  if (!title.isEmpty() && next == nullptr) return false;
  if (active_pipeline_ != nullptr) active_pipeline_->Detach();
  active_pipeline_ = next;
  pipeline_frames_ = 0;
  for (QAction* action : pipeline_actions_->actions()) {
    action->setChecked(action->text() == (next ? next->Title() : tr("None (show frames only)")));
  }
  // The panel shows the view options and the active pipeline's options.
  OptionSet options;
  Status declared = options.Declare(ViewOptions::Describe());
  if (declared.ok() && next != nullptr) declared = next->DeclareOptions(&options);
  if (!declared.ok()) {
    log_panel_->AddMessage(LogPanel::Severity::kError, QString::fromStdString(declared.ToString()));
    return false;
  }
  // Keep the user's view settings.
  for (const OptionSpec& spec : options_.specs()) {
    if (options.Has(spec.key)) (void)options.Set(spec.key, *options_.Get(spec.key));
  }
  options_ = options;
  parameter_panel_->SetOptions(options_);
  if (next == nullptr) {
    playback_->SetProcessorFactory(nullptr, options_);
    log_panel_->AddMessage(LogPanel::Severity::kInfo, tr("No pipeline: showing frames only."));
    return true;
  }
  next->Attach(this);
  QPointer<PipelinePresenter> presenter(next);
  playback_->SetProcessorFactory(
      [presenter](const PipelineSource& source) -> std::unique_ptr<Pipeline> {
        if (!presenter || !presenter->Accepts(source.info.kind)) return nullptr;
        return presenter->CreateProcessor(source);
      },
      options_);
  log_panel_->AddMessage(LogPanel::Severity::kInfo, tr("Pipeline: %1").arg(next->Title()));
  if (playback_->info() != nullptr && !next->Accepts(playback_->info()->kind)) {
    log_panel_->AddMessage(
        LogPanel::Severity::kWarning,
        tr("%1 cannot run on %2 frames; open another dataset.")
            .arg(next->Title(), QString::fromUtf8(SourceKindName(playback_->info()->kind))));
  }
  return true;
}

Status MainWindow::ApplyOptionArguments(const QString& profile, const QStringList& assignments) {
  // Both on a copy first, so that a bad assignment leaves the profile unapplied as well.
  OptionSet edited = options_;
  if (!profile.isEmpty()) SIGHTLINE_RETURN_IF_ERROR(edited.LoadYaml(profile.toStdString()));
  for (const QString& assignment : assignments) {
    SIGHTLINE_RETURN_IF_ERROR(edited.ApplyOverride(assignment.toStdString()));
  }
  parameter_panel_->SetOptions(edited);
  OnOptionsChanged(edited);
  return Status::Ok();
}

bool MainWindow::ActivatePipelineByWord(const QString& word) {
  for (PipelinePresenter* p : pipelines_) {
    if (p->Title().contains(word, Qt::CaseInsensitive) ||
        QString::fromUtf8(p->TitleSource()).contains(word, Qt::CaseInsensitive)) {
      return ActivatePipeline(p->Title());
    }
  }
  return false;
}

void MainWindow::OpenPath(const QString& path) {
  log_panel_->AddMessage(LogPanel::Severity::kInfo, tr("Opening %1 ...").arg(path));
  statusBar()->showMessage(tr("Opening %1 ...").arg(path));
  playback_->Open(path);
}

void MainWindow::OnOpened(const QString& path) {
  const SourceInfo* info = playback_->info();
  frames_shown_ = 0;
  pipeline_frames_ = 0;
  last_shown_id_ = 0;
  pending_seek_ = -1;
  first_cloud_ = true;
  scene_view_->ClearLayers();
  ClearRunViews();  // The colour and depth views too.
  const bool rgbd = info->kind == SourceKind::kRgbd;
  const bool stereo = info->kind == SourceKind::kStereo;
  primary_dock_->setWindowTitle(rgbd ? tr("Colour") : stereo ? tr("Left") : tr("Image"));
  secondary_dock_->setWindowTitle(stereo ? tr("Right") : tr("Depth"));
  // A live source (camera, replay://) has no end: the bar plays it and counts its frames.
  playback_bar_->SetFrameCount(info->live ? -1 : std::max<int64_t>(0, info->frame_count));
  playback_bar_->SetPosition(0);
  playback_bar_->SetPlaying(false);
  playback_bar_->SetLoop(playback_->loop());
  const QString summary = tr("%1: %2, %3 frames, %4x%5%6")
                              .arg(QFileInfo(path).fileName(), QString::fromStdString(info->format))
                              .arg(info->frame_count)
                              .arg(info->width)
                              .arg(info->height)
                              .arg(info->has_ground_truth ? tr(", ground truth") : QString());
  status_label_->setText(summary);
  log_panel_->AddMessage(LogPanel::Severity::kInfo, tr("Opened %1").arg(summary));
  for (const std::string& note : info->notes) {
    log_panel_->AddMessage(LogPanel::Severity::kInfo, QString::fromStdString(note));
  }
  statusBar()->clearMessage();
  setWindowTitle(tr("Sightline - %1").arg(QFileInfo(path).fileName()));
  AddRecent(path);
  playback_->SetViewOptions(options_.Extract(ViewOptions::Describe()));
  emit DatasetOpened(path);
}

void MainWindow::ShowFrame(const std::shared_ptr<const PlaybackResult>& result) {
  if (!result) return;
  ShowImages(*result);
  if (active_pipeline_ != nullptr && result->pipeline) {
    if (!result->pipeline->status.ok()) {
      log_panel_->AddMessage(LogPanel::Severity::kWarning,
                             QString::fromStdString(result->pipeline->status.ToString()));
    }
    active_pipeline_->Show(*result);
    if (result->pipeline->status.ok()) ++pipeline_frames_;
  }
  last_shown_id_ = result->stamp.sequence_id;
  playback_bar_->SetPosition(result->stamp.sequence_id);
  status_label_->setToolTip(tr("frame %1, read in %2 ms")
                                .arg(result->stamp.sequence_id)
                                .arg(result->prepare_ms, 0, 'f', 1));
  ++frames_shown_;
  emit FrameShown(result->stamp.sequence_id);
}

void MainWindow::ShowImages(const PlaybackResult& result) {
  if (!result.primary_image.empty()) {
    primary_view_->SetImage(result.primary_image);
  }
  if (!result.secondary_image.empty()) {
    if (result.secondary_is_depth) {
      const ViewOptions view = options_.Extract(ViewOptions::Describe());
      secondary_view_->SetDepthRange(0.0, view.depth_range_m);
      secondary_view_->SetImage(result.secondary_image, ImageView::Kind::kDepthMeters);
    } else {
      secondary_view_->SetImage(result.secondary_image);
    }
  }
  // The frame's cloud only when the 3D view shows it (a pipeline may hide it for its own).
  std::shared_ptr<const PointCloud> cloud = result.cloud;
  if (!cloud && scene_view_->isVisible() && scene_view_->IsLayerVisible("cloud")) {
    cloud = playback_->MakeCloud(result);
  }
  if (cloud) {
    scene_view_->SetPointCloud("cloud", cloud, SceneView::ColorMode::kAuto);
    if (first_cloud_) {
      scene_view_->ResetView();
      first_cloud_ = false;
    }
  }
}

void MainWindow::OnOptionsChanged(const OptionSet& options) {
  options_ = options;
  const ViewOptions view = options_.Extract(ViewOptions::Describe());
  std::string error;
  if (!view.IsValid(&error)) {
    log_panel_->AddMessage(LogPanel::Severity::kWarning, QString::fromStdString(error));
    return;
  }
  playback_->SetViewOptions(view);
  if (active_pipeline_ != nullptr) playback_->SetPipelineOptions(options_);
}

void MainWindow::ShowWelcome() {
  log_panel_->AddMessage(
      LogPanel::Severity::kInfo,
      tr("No dataset open. Use File > Open dataset folder (TUM RGB-D, EuRoC, KITTI, an image "
         "folder or PCD files), or drop a folder on this window."));
  status_label_->setText(tr("No dataset open"));
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
  if (event->mimeData()->hasUrls()) event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event) {
  const QList<QUrl> urls = event->mimeData()->urls();
  if (!urls.isEmpty() && urls.first().isLocalFile()) OpenPath(urls.first().toLocalFile());
}

void MainWindow::closeEvent(QCloseEvent* event) {
  playback_->Close("quit");       // The pipeline's live outputs (e.g. arm clients) are told first.
  if (isVisible()) SaveLayout();  // Not the hidden window behind the operator mode.
  QMainWindow::closeEvent(event);
}

void MainWindow::AddRecent(const QString& path) {
  QSettings settings;
  QStringList recent = settings.value(kRecentKey).toStringList();
  recent.removeAll(path);
  recent.prepend(path);
  while (recent.size() > kMaxRecent) recent.removeLast();
  settings.setValue(kRecentKey, recent);
  RebuildRecentMenu();
}

void MainWindow::RebuildRecentMenu() {
  recent_menu_->clear();
  const QStringList recent = QSettings().value(kRecentKey).toStringList();
  for (const QString& path : recent) {
    connect(recent_menu_->addAction(path), &QAction::triggered, this,
            [this, path] { OpenPath(path); });
  }
  recent_menu_->setEnabled(!recent.isEmpty());
}

}  // namespace sightline
