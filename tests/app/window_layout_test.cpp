// The window's layout outlives the window: docks hidden, moved or resized are as the user left
// them at the next start, and View > Reset layout brings back the first-start layout.
#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QScrollArea>
#include <QSettings>
#include <QTest>

#include "app/sightline/builtin_presenters.h"
#include "app/sightline/main_window.h"
#include "app/sightline/pipeline_presenter.h"
#include "widgets/option_editor.h"
#include "widgets/parameter_panel.h"

namespace sightline {
namespace {

void Settle() {
  for (int i = 0; i < 5; ++i) QApplication::processEvents();
}

QDockWidget* Dock(const MainWindow& window, const char* name) {
  auto* dock = window.findChild<QDockWidget*>(name);
  EXPECT_NE(dock, nullptr) << name;
  return dock;
}

TEST(WindowLayout, IsRestoredAtTheNextStartAndResetFromTheViewMenu) {
  QSettings().clear();
  {
    MainWindow first;
    first.show();
    Settle();
    ASSERT_FALSE(Dock(first, "depth_dock")->isHidden());
    Dock(first, "depth_dock")->hide();
    first.addDockWidget(Qt::LeftDockWidgetArea, Dock(first, "parameters_dock"));
    ASSERT_EQ(first.dockWidgetArea(Dock(first, "parameters_dock")), Qt::LeftDockWidgetArea);
    ASSERT_TRUE(first.close());
  }
  EXPECT_TRUE(QSettings().contains("window/state")) << "closing the window saves no layout";

  MainWindow second;
  second.show();
  Settle();
  EXPECT_TRUE(Dock(second, "depth_dock")->isHidden()) << "the hidden view shows again";
  EXPECT_EQ(second.dockWidgetArea(Dock(second, "parameters_dock")), Qt::LeftDockWidgetArea)
      << "the moved dock went back";

  auto* reset = second.findChild<QAction*>("reset_layout_action");
  ASSERT_NE(reset, nullptr) << "no View > Reset layout";
  reset->trigger();
  Settle();
  EXPECT_FALSE(Dock(second, "depth_dock")->isHidden());
  EXPECT_EQ(second.dockWidgetArea(Dock(second, "parameters_dock")), Qt::RightDockWidgetArea);
  EXPECT_FALSE(QSettings().contains("window/state")) << "the reset layout would come back";
}

// Tuning needs to see a dozen options at once: at the window's first-start size on a
// 1280x800 screen the Parameters dock shows at least 12 whole rows of the mapping options.
TEST(WindowLayout, TheParametersDockShowsAtLeastTwelveRowsAtTheDefaultSize) {
  QSettings().clear();
  MainWindow window;
  for (PipelinePresenter* presenter : MakeBuiltinPresenters()) window.AddPipeline(presenter);
  ASSERT_TRUE(window.ActivatePipelineByWord("mapping"));
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  Settle();
  QTest::qWait(200);
  auto* panel = window.findChild<ParameterPanel*>();
  ASSERT_NE(panel, nullptr);
  auto* scroll = panel->findChild<QScrollArea*>();
  ASSERT_NE(scroll, nullptr);
  const QRect viewport = scroll->viewport()->rect();
  int whole_rows = 0;
  for (const OptionEditor* editor : panel->findChildren<OptionEditor*>()) {
    if (!editor->isVisible()) continue;
    const QRect box(editor->mapTo(scroll->viewport(), QPoint(0, 0)), editor->size());
    if (viewport.contains(box.topLeft()) && viewport.contains(box.bottomLeft())) ++whole_rows;
  }
  EXPECT_GE(whole_rows, 12) << "window " << window.width() << "x" << window.height()
                            << ", parameters viewport " << viewport.height() << " px high";
}

}  // namespace
}  // namespace sightline
