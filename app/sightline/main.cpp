// sightline: the desktop application.
#include <QApplication>
#include <QCommandLineParser>
#include <QDockWidget>
#include <QIcon>
#include <QLabel>
#include <QLocale>
#include <QPixmap>
#include <QTimer>
#include <cstdio>

#include "app/sightline/builtin_presenters.h"
#include "app/sightline/button_picker_presenter.h"
#include "app/sightline/demo_generator.h"
#include "app/sightline/language.h"
#include "app/sightline/main_window.h"
#include "app/sightline/mapping_presenter.h"
#include "app/sightline/playback_controller.h"
#include "app/sightline/ros_node_view.h"
#include "app/sightline/screenshot_driver.h"
#include "sightline_version.h"
#include "widgets/operator_panel.h"
#include "widgets/vtk_gl_widget.h"

namespace {

// The command line, parsed (Qt's parser exits on --help, --version and unknown options).
struct Arguments {
  QString source;  // --open PATH or the positional SOURCE.
  QString pipeline, profile, screenshot;
  QStringList assignments;  // --set KEY=VALUE, in order.
  bool demo = false, operator_mode = false, open_given = false;
  QString frames, timeout;
  QString language;  // --lang CODE: this run only; "" = the saved choice or the system's.
  QString ros_master, ros_namespace;  // --connect-ros URI, --ros-namespace NS.
};

// Applies --profile and --set to the active pipeline's options; false (reported) on an error.
bool ApplyOptionArguments(sightline::MainWindow* window, const QString& profile,
                          const QStringList& assignments) {
  if (profile.isEmpty() && assignments.isEmpty()) return true;
  const sightline::Status applied = window->ApplyOptionArguments(profile, assignments);
  if (applied.ok()) return true;
  std::fprintf(stderr, "sightline: %s\n", applied.ToString().c_str());
  return false;
}

// --screenshot FILE: plays --frames frames, saves the window (or `subject`) and exits. False on bad
// arguments.
bool StartScreenshot(sightline::MainWindow* window, const Arguments& args,
                     QWidget* subject = nullptr) {
  if (!args.open_given && !args.demo) {
    std::fprintf(stderr, "sightline: --screenshot needs --open PATH or --demo\n");
    return false;
  }
  bool ok = false;
  const int frames = args.frames.toInt(&ok);
  if (!ok || frames < 1) {
    std::fprintf(stderr, "sightline: --frames must be a positive number\n");
    return false;
  }
  new sightline::ScreenshotDriver(window, args.screenshot, frames, args.timeout.toInt(), subject);
  return true;
}

// `sightline --operator [SOURCE]`: the button picker's operator panel alone, full screen, playing
// SOURCE. Leaving the panel closes the window: every arm client gets a stop line ("quit").
// `--profile` and `--set` (e.g. button.gui.serve=true) apply to the button picker's options.
// With --screenshot the panel steps --frames frames instead of playing, and the panel is saved.
int RunOperatorMode(QApplication* app, sightline::MainWindow* window,
                    sightline::ButtonPickerPresenter* picker, const Arguments& args) {
  if (picker == nullptr || !window->ActivatePipeline(picker->Title())) {
    std::fprintf(stderr, "sightline: the button picker is not available\n");
    return 2;
  }
  if (!ApplyOptionArguments(window, args.profile, args.assignments)) return 2;
  picker->EnterOperatorMode();  // The panel alone; the main window stays hidden.
  QObject::connect(picker, &sightline::ButtonPickerPresenter::OperatorLeft, window, [app, window] {
    window->close();
    app->quit();
  });
  if (!args.screenshot.isEmpty()) {
    if (!StartScreenshot(window, args, picker->panel()->window())) return 2;
  } else {
    QObject::connect(
        window, &sightline::MainWindow::DatasetOpened, window,
        [window] { window->playback()->Play(); }, Qt::SingleShotConnection);
  }
  if (!args.source.isEmpty()) {
    const QString source = args.source;
    QTimer::singleShot(0, window, [window, source] { window->OpenPath(source); });
  }
  return app->exec();
}

// --connect-ros URI: watches the node on that master. With --screenshot the window is saved
// once the node's map is shown (exit 0), or the run fails after --timeout (exit 1). A bad URI or
// namespace is named on stderr and in the status bar; false then.
bool StartRosConnection(sightline::MainWindow* window, const Arguments& args) {
  const sightline::Status connected = window->ConnectRos(args.ros_master, args.ros_namespace);
  if (!connected.ok()) {
    std::fprintf(stderr, "sightline: --connect-ros: %s\n", connected.message().c_str());
    return false;
  }
  if (args.screenshot.isEmpty()) return true;
  const QString path = args.screenshot;
  QObject::connect(
      window->ros_node(), &sightline::RosNodeView::MapShown, window,
      [window, path](int width, int height) {
        // Let the views render before grabbing.
        QTimer::singleShot(500, window, [window, path, width, height] {
          if (!window->grab().save(path, "PNG")) {
            std::fprintf(stderr, "sightline: could not write screenshot %s\n", qPrintable(path));
            QApplication::exit(1);
            return;
          }
          // Where the map is in the picture, for whoever checks it.
          const QWidget* view = window->ros_node()->dock()->widget();
          const QPoint at = view->mapTo(window, QPoint(0, 0));
          std::printf(
              "sightline: wrote %s (map %dx%d from the ROS node; map view at %d,%d %dx%d)\n",
              qPrintable(path), width, height, at.x(), at.y(), view->width(), view->height());
          std::fflush(stdout);
          QApplication::exit(0);
        });
      },
      Qt::SingleShotConnection);
  const int timeout_s = args.timeout.toInt();
  QTimer::singleShot(timeout_s * 1000, window, [window, timeout_s] {
    std::fprintf(stderr,
                 "sightline: screenshot failed: no map from the ROS node within %d s (%s)\n",
                 timeout_s, qPrintable(window->ros_node()->status_label()->text()));
    QApplication::exit(1);
  });
  return true;
}

// `sightline --demo`: generates the demo recordings once, then opens the corridor drive.
void StartDemo(sightline::MainWindow* window, sightline::PipelinePresenter* mapping,
               bool autoplay) {
  auto* demo = new sightline::DemoGenerator(sightline::DemoGenerator::DefaultFolder(), window);
  window->ShowDemoProgress(demo);
  QObject::connect(demo, &sightline::DemoGenerator::Ready, window,
                   [window, autoplay](const QString& corridor) {
                     if (autoplay) {
                       QObject::connect(
                           window, &sightline::MainWindow::DatasetOpened, window,
                           [window] { window->PlayLooping(); }, Qt::SingleShotConnection);
                     }
                     window->OpenPath(corridor);
                   });
  // The demo shows the pipelines that run on its corridor drive.
  if (mapping != nullptr) window->ActivatePipeline(mapping->Title());
  demo->Start();
}

Arguments ParseArguments(const QApplication& app) {
  QCommandLineParser parser;
  parser.setApplicationDescription(
      "Sightline: robot perception on live sensors and recorded data.");
  parser.addHelpOption();
  parser.addVersionOption();
  QCommandLineOption open_option("open", "Open a dataset folder or file at start.", "PATH");
  QCommandLineOption screenshot_option(
      "screenshot", "Play --frames frames, save the window as a PNG to FILE and exit.", "FILE");
  QCommandLineOption frames_option("frames", "Frames to play before --screenshot (default 5).", "N",
                                   "5");
  QCommandLineOption timeout_option("timeout", "Give up on --screenshot after S seconds.", "S",
                                    "120");
  QCommandLineOption demo_option(
      "demo", "Open the built-in demo (simulated recordings, generated once into the cache).");
  QCommandLineOption pipeline_option(
      "pipeline", "Run a pipeline on every frame: a word of its menu title, e.g. mapping, stereo.",
      "NAME");
  QCommandLineOption operator_option(
      "operator",
      "Open the operator's button panel alone, full screen (F11: window, Esc: leave), and play "
      "SOURCE (a camera URI or a recording).");
  QCommandLineOption profile_option(
      "profile", "Load a YAML profile into the pipeline's options (as sightline-cli run).", "FILE");
  QCommandLineOption set_option(
      "set", "Set one of the pipeline's options, e.g. button.gui.serve=true (repeatable).",
      "KEY=VALUE");
  QCommandLineOption lang_option(
      "lang",
      "The GUI's language for this run: it, es, de or en (default: the one chosen in Settings > "
      "Language, else the system's).",
      "CODE");
  QCommandLineOption connect_ros_option(
      "connect-ros",
      "Watch the sightline-node on the ROS master at URI (e.g. http://robot:11311): its map in "
      "the ROS node dock, its trajectory, walls and clouds in the 3D view. With --screenshot, "
      "the window is saved once the map arrived.",
      "URI");
  QCommandLineOption ros_namespace_option(
      "ros-namespace", "The node's ROS namespace for --connect-ros (default /).", "NS", "/");
  parser.addOptions({open_option, demo_option, pipeline_option, operator_option, profile_option,
                     set_option, screenshot_option, frames_option, timeout_option, lang_option,
                     connect_ros_option, ros_namespace_option});
  parser.addPositionalArgument("SOURCE", "A dataset, recording or sensor URI to open (as --open).",
                               "[SOURCE]");
  parser.process(app);
  Arguments args;
  args.source = parser.value(open_option);
  if (!parser.positionalArguments().isEmpty()) args.source = parser.positionalArguments().first();
  args.open_given = !args.source.isEmpty();
  args.pipeline = parser.value(pipeline_option);
  args.profile = parser.value(profile_option);
  args.assignments = parser.values(set_option);
  args.screenshot = parser.value(screenshot_option);
  args.frames = parser.value(frames_option);
  args.timeout = parser.value(timeout_option);
  args.demo = parser.isSet(demo_option);
  args.operator_mode = parser.isSet(operator_option);
  args.language = parser.value(lang_option);
  args.ros_master = parser.value(connect_ros_option);
  args.ros_namespace = parser.value(ros_namespace_option);
  return args;
}

// --help and --version print without a display: Qt's offscreen platform stands in for X11.
void AllowHelpWithoutDisplay(int argc, char** argv) {
  if (qEnvironmentVariableIsSet("DISPLAY") || qEnvironmentVariableIsSet("WAYLAND_DISPLAY") ||
      qEnvironmentVariableIsSet("QT_QPA_PLATFORM")) {
    return;
  }
  for (int i = 1; i < argc; ++i) {
    const QByteArray arg(argv[i]);
    if (arg == "--help" || arg == "-h" || arg == "--version" || arg == "-v" ||
        arg == "--help-all") {
      qputenv("QT_QPA_PLATFORM", "offscreen");
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  AllowHelpWithoutDisplay(argc, argv);
  // VTK needs an OpenGL 3.2 core context: set the format before QApplication exists.
  sightline::VtkGlWidget::SetDefaultSurfaceFormat();
  QApplication app(argc, argv);
  QApplication::setOrganizationName("Sightline");
  QApplication::setApplicationName("Sightline");
  QApplication::setApplicationVersion(SIGHTLINE_VERSION " (commit " SIGHTLINE_GIT_COMMIT ")");
  QApplication::setWindowIcon(QIcon(":/icons/sightline.png"));
  QApplication::setDesktopFileName("sightline");

  const Arguments args = ParseArguments(app);
  if (!args.language.isEmpty() && !sightline::IsLanguage(args.language)) {
    std::fprintf(stderr, "sightline: --lang %s: not one of it, es, de, en\n",
                 qPrintable(args.language));
    return 2;
  }
  sightline::SwitchLanguage(args.language.isEmpty() ? sightline::SavedLanguage() : args.language,
                            &app);

  sightline::MainWindow window;
  // The Pipeline menu lists the core registry's pipelines, as `sightline-cli run` does.
  sightline::PipelinePresenter* mapping = nullptr;
  sightline::ButtonPickerPresenter* picker = nullptr;
  for (sightline::PipelinePresenter* presenter : sightline::MakeBuiltinPresenters()) {
    if (qobject_cast<sightline::MappingPresenter*>(presenter) != nullptr) mapping = presenter;
    if (auto* p = qobject_cast<sightline::ButtonPickerPresenter*>(presenter)) picker = p;
    window.AddPipeline(presenter);
  }
  if (args.operator_mode) {
    return RunOperatorMode(&app, &window, picker, args);
  }
  window.show();
  if (!args.pipeline.isEmpty() && !window.ActivatePipelineByWord(args.pipeline)) {
    std::fprintf(stderr, "sightline: no pipeline matches '%s' (see the Pipeline menu)\n",
                 qPrintable(args.pipeline));
    return 2;
  }
  if (!ApplyOptionArguments(&window, args.profile, args.assignments)) return 2;
  if (!args.ros_master.isEmpty()) {
    if (!StartRosConnection(&window, args)) return 2;
  } else if (!args.screenshot.isEmpty() && !StartScreenshot(&window, args)) {
    return 2;
  }
  if (args.demo) {
    StartDemo(&window, mapping, /*autoplay=*/args.screenshot.isEmpty());
  } else if (!args.source.isEmpty()) {
    const QString source = args.source;
    QTimer::singleShot(0, &window, [&window, source] { window.OpenPath(source); });
  }
  return app.exec();
}
