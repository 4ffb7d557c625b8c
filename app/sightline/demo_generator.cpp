#include "app/sightline/demo_generator.h"

#include <QDir>
#include <QFile>
#include <QPointer>
#include <QStandardPaths>
#include <QtConcurrent/QtConcurrentRun>

#include "core/sim/simulate.h"

namespace sightline {

namespace {

// Bump when the demo's content changes, so old caches are not reused.
constexpr char kDemoVersion[] = "demo-v1";
constexpr char kCompleteMarker[] = "COMPLETE";

}  // namespace

DemoGenerator::DemoGenerator(QString folder, QObject* parent, int corridor_frames, int panel_frames)
    : QObject(parent),
      folder_(std::move(folder)),
      corridor_frames_(corridor_frames),
      panel_frames_(panel_frames) {}

DemoGenerator::~DemoGenerator() {
  cancel_ = true;
  future_.waitForFinished();
}

QString DemoGenerator::DefaultFolder() {
  return QStandardPaths::writableLocation(QStandardPaths::GenericCacheLocation) + "/sightline/" +
         kDemoVersion;
}

QString DemoGenerator::corridor_path() const { return folder_ + "/corridor"; }
QString DemoGenerator::panel_path() const { return folder_ + "/panel"; }

void DemoGenerator::Start() {
  if (QFile::exists(folder_ + "/" + kCompleteMarker)) {
    QMetaObject::invokeMethod(
        this, [this] { emit Ready(corridor_path()); }, Qt::QueuedConnection);
    return;
  }
  if (!QDir().mkpath(folder_)) {
    QMetaObject::invokeMethod(
        this, [this] { emit Failed(tr("cannot create the demo folder %1").arg(folder_)); },
        Qt::QueuedConnection);
    return;
  }
  const std::string corridor = corridor_path().toStdString();
  const std::string panel = panel_path().toStdString();
  const QString marker = folder_ + "/" + kCompleteMarker;
  const int corridor_frames = corridor_frames_;
  const int panel_frames = panel_frames_;
  future_ = QtConcurrent::run([this, corridor, panel, marker, corridor_frames, panel_frames] {
    const int total = corridor_frames + panel_frames;
    auto report = [this](int done, int total_frames) {
      QMetaObject::invokeMethod(
          this, [this, done, total_frames] { emit Progress(done, total_frames); },
          Qt::QueuedConnection);
    };
    sim::SimulationCallbacks callbacks;
    callbacks.cancel = &cancel_;
    sim::SimulationOptions corridor_options = sim::SimulationOptions::ForScene("corridor");
    corridor_options.frames = corridor_frames;
    callbacks.progress = [&](int64_t done, int64_t) { report(static_cast<int>(done), total); };
    StatusOr<sim::SimulationSummary> made = sim::Simulate(corridor_options, corridor, callbacks);
    if (made.ok()) {
      sim::SimulationOptions panel_options = sim::SimulationOptions::ForScene("panel");
      panel_options.frames = panel_frames;
      callbacks.progress = [&](int64_t done, int64_t) {
        report(corridor_frames + static_cast<int>(done), total);
      };
      made = sim::Simulate(panel_options, panel, callbacks);
    }
    if (!made.ok()) {
      const QString message = QString::fromStdString(made.status().ToString());
      QMetaObject::invokeMethod(
          this, [this, message] { emit Failed(message); }, Qt::QueuedConnection);
      return;
    }
    QFile done(marker);
    if (!done.open(QIODevice::WriteOnly)) {
      QMetaObject::invokeMethod(
          this, [this, marker] { emit Failed(tr("cannot write %1").arg(marker)); },
          Qt::QueuedConnection);
      return;
    }
    done.write("complete\n");
    done.close();
    QMetaObject::invokeMethod(
        this, [this] { emit Ready(corridor_path()); }, Qt::QueuedConnection);
  });
}

}  // namespace sightline
