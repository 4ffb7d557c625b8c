// gtest main for GUI tests: a QApplication with VTK's OpenGL surface format.
#include <gtest/gtest.h>

#include <QApplication>
#include <cstring>

#include "tests/support/isolated_home.h"
#include "widgets/vtk_gl_widget.h"

int main(int argc, char** argv) {
  // Listing tests (ctest discovery at build time) needs no display.
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--gtest_list_tests") == 0) {
      ::testing::InitGoogleTest(&argc, argv);
      return RUN_ALL_TESTS();
    }
  }
  const sightline::testing::IsolatedHome home;  // Never the user's settings.
  if (home.path().empty()) return 2;
  sightline::VtkGlWidget::SetDefaultSurfaceFormat();
  QApplication app(argc, argv);
  QApplication::setOrganizationName("SightlineTests");
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
