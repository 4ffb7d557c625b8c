// What the window remembers between starts: Settings > Language (switched while the window is
// open) and the window's layout (docks, their sizes, which views show; View > Reset layout).
#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QMenu>
#include <QMenuBar>
#include <QScreen>
#include <QSettings>
#include <QTimer>

#include "app/sightline/language.h"
#include "app/sightline/main_window.h"
#include "widgets/log_panel.h"

namespace sightline {

namespace {
const char kGeometryKey[] = "window/geometry";
const char kStateKey[] = "window/state";
// Bumped when the docks change so much that an old saved layout would mislead.
constexpr int kLayoutVersion = 1;
}  // namespace

void MainWindow::BuildLayoutMemory() {
  QAction* reset = view_menu_->addAction(tr("Reset &layout"));
  reset->setObjectName("reset_layout_action");
  connect(reset, &QAction::triggered, this, &MainWindow::ResetLayout);
  // After BuildViews' first-turn dock sizes: that is the default layout; then the saved one.
  QTimer::singleShot(0, this, [this] {
    default_state_ = saveState(kLayoutVersion);
    QSettings settings;
    if (settings.contains(kGeometryKey))
      restoreGeometry(settings.value(kGeometryKey).toByteArray());
    if (settings.contains(kStateKey)) {
      restoreState(settings.value(kStateKey).toByteArray(), kLayoutVersion);
    }
  });
}

void MainWindow::SaveLayout() {
  QSettings settings;
  settings.setValue(kGeometryKey, saveGeometry());
  settings.setValue(kStateKey, saveState(kLayoutVersion));
}

void MainWindow::ResetLayout() {
  QSettings settings;
  settings.remove(kGeometryKey);
  settings.remove(kStateKey);
  if (!default_state_.isEmpty()) restoreState(default_state_, kLayoutVersion);
  QSize size(1400, 900);
  if (const QScreen* screen = QGuiApplication::primaryScreen()) {
    size = size.boundedTo(screen->availableSize() * 0.9);
  }
  if (!isMaximized() && !isFullScreen()) resize(size);
}

void MainWindow::BuildSettings() {
  QMenu* settings = menuBar()->addMenu(tr("Setti&ngs"));
  settings->setObjectName("settings_menu");
  QMenu* languages = settings->addMenu(tr("&Language"));
  languages->setObjectName("language_menu");
  language_actions_ = new QActionGroup(this);
  // "" follows the system's language; the others are named in their own language, so they read
  // the same whatever the GUI speaks now.
  QAction* system = languages->addAction(tr("System language"));
  system->setData(QString());
  languages->addSeparator();
  std::vector<QAction*> actions = {system};
  for (const Language& language : Languages()) {
    QAction* action = languages->addAction(language.native_name);
    action->setData(language.code);
    actions.push_back(action);
  }
  const QString saved = SavedLanguage();
  for (QAction* action : actions) {
    action->setCheckable(true);
    action->setChecked(action->data().toString() == saved);
    language_actions_->addAction(action);
    connect(action, &QAction::triggered, this,
            [this, action] { SetLanguage(action->data().toString(), /*save=*/true); });
  }
}

QString MainWindow::SetLanguage(const QString& code, bool save) {
  const QString in_effect = SwitchLanguage(code, qApp);
  if (save) SaveLanguage(code);
  for (QAction* action : language_actions_->actions()) {
    const QString data = action->data().toString();
    action->setChecked(save ? data == code : data == in_effect);
  }
  for (const Language& language : Languages()) {
    if (language.code == in_effect) {
      log_panel_->AddMessage(LogPanel::Severity::kInfo,
                             tr("Language: %1").arg(language.native_name));
    }
  }
  return in_effect;
}

}  // namespace sightline
