// main() for widget tests: a QApplication around GoogleTest. Tests run on Qt's offscreen
// platform unless QT_QPA_PLATFORM says otherwise (the OpenGL scene test sets xcb under Xvfb).
#include <gtest/gtest.h>

#include <QApplication>

#include "tests/support/isolated_home.h"
#include "widgets/vtk_gl_widget.h"

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  const sightline::testing::IsolatedHome home;  // Never the user's settings.
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
  sightline::VtkGlWidget::SetDefaultSurfaceFormat();
  QApplication app(argc, argv);
  return RUN_ALL_TESTS();
}
