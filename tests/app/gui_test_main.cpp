// gtest main for GUI tests: a QApplication with VTK's OpenGL surface format.
#include <gtest/gtest.h>

#include <QApplication>

#include "widgets/vtk_gl_widget.h"

int main(int argc, char** argv) {
  sightline::VtkGlWidget::SetDefaultSurfaceFormat();
  QApplication app(argc, argv);
  QApplication::setOrganizationName("SightlineTests");
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
