// The window's layout outlives the window: docks hidden, moved or resized are as the user left
// them at the next start, and View > Reset layout brings back the first-start layout.
#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QSettings>

#include "app/sightline/main_window.h"

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

}  // namespace
}  // namespace sightline
