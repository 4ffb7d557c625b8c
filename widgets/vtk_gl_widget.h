// A Qt6 QOpenGLWidget that hosts a VTK 9 render window, without VTK's own Qt module (which
// Debian builds against Qt5 and which must never be loaded into this Qt6 process).
#pragma once

#include <QOpenGLWidget>
#include <QSurfaceFormat>
#include <cstdint>
#include <memory>

class vtkRenderer;
class vtkRenderWindow;

namespace sightline {

// Renders one vtkRenderer into a QOpenGLWidget, with trackball-camera mouse interaction.
// Rendering happens only on demand: ScheduleRender() (and any interaction) marks the scene dirty
// and asks Qt for a repaint; many requests before the next paint make one render.
//
//   int main(int argc, char** argv) {
//     sightline::VtkGlWidget::SetDefaultSurfaceFormat();  // Before QApplication.
//     QApplication app(argc, argv);
//     sightline::VtkGlWidget view;
//     view.renderer()->AddActor(actor);
//     view.ScheduleRender();
//     view.show();
//     return app.exec();
//   }
class VtkGlWidget : public QOpenGLWidget {
  Q_OBJECT

 public:
  // Creates the VTK render window, interactor and renderer; GL resources come with initializeGL.
  explicit VtkGlWidget(QWidget* parent = nullptr);
  // Releases VTK's GL resources while the context still exists.
  ~VtkGlWidget() override;

  // The surface format VTK needs (OpenGL 3.2 core, RGBA8, depth, no stencil, no multisampling).
  static QSurfaceFormat DefaultSurfaceFormat();
  // Installs DefaultSurfaceFormat() as Qt's default. Call before constructing QApplication.
  static void SetDefaultSurfaceFormat();

  // The renderer that draws the scene; add props to it, then call ScheduleRender().
  vtkRenderer* renderer() const;
  // The VTK render window (a vtkGenericOpenGLRenderWindow driven by this widget).
  vtkRenderWindow* renderWindow() const;

  // Requests a VTK render at the next repaint. Cheap; calls coalesce.
  void ScheduleRender();
  // Number of VTK renders done so far (lets tests and benchmarks check that renders coalesce).
  int64_t render_count() const;

 protected:
  void initializeGL() override;
  void resizeGL(int w, int h) override;
  void paintGL() override;

  void mousePressEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void mouseDoubleClickEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void keyPressEvent(QKeyEvent* event) override;
  void keyReleaseEvent(QKeyEvent* event) override;
  void enterEvent(QEnterEvent* event) override;
  void leaveEvent(QEvent* event) override;

 private:
  struct Impl;

  // Releases VTK's GL resources; connected to QOpenGLContext::aboutToBeDestroyed.
  void CleanupContext();

  std::unique_ptr<Impl> impl_;
};

}  // namespace sightline
