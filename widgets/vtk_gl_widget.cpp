#include "widgets/vtk_gl_widget.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkNew.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLState.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <QPointer>
#include <QScreen>
#include <QWheelEvent>
#include <QtDebug>
#include <cmath>

namespace sightline {
namespace {

// VTK key symbol (X11 keysym names) for keys that have no printable character.
const char* KeySymOf(int qt_key) {
  switch (qt_key) {
    case Qt::Key_Backspace:
      return "BackSpace";
    case Qt::Key_Tab:
      return "Tab";
    case Qt::Key_Return:
    case Qt::Key_Enter:
      return "Return";
    case Qt::Key_Escape:
      return "Escape";
    case Qt::Key_Space:
      return "space";
    case Qt::Key_Delete:
      return "Delete";
    case Qt::Key_Home:
      return "Home";
    case Qt::Key_End:
      return "End";
    case Qt::Key_PageUp:
      return "Prior";
    case Qt::Key_PageDown:
      return "Next";
    case Qt::Key_Left:
      return "Left";
    case Qt::Key_Up:
      return "Up";
    case Qt::Key_Right:
      return "Right";
    case Qt::Key_Down:
      return "Down";
    case Qt::Key_Shift:
      return "Shift_L";
    case Qt::Key_Control:
      return "Control_L";
    case Qt::Key_Alt:
      return "Alt_L";
    case Qt::Key_Plus:
      return "plus";
    case Qt::Key_Minus:
      return "minus";
    default:
      return nullptr;
  }
}

}  // namespace

struct VtkGlWidget::Impl {
  explicit Impl(VtkGlWidget* owner) : widget(owner) {}

  VtkGlWidget* widget;
  vtkNew<vtkGenericOpenGLRenderWindow> window;
  vtkNew<vtkGenericRenderWindowInteractor> interactor;
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkCallbackCommand> window_observer;
  vtkNew<vtkCallbackCommand> interactor_observer;

  // The context and surface that QOpenGLWidget renders with, saved in initializeGL. VTK's
  // make-current requests go to exactly this pair (see OnWindowEvent).
  QPointer<QOpenGLContext> context;
  QSurface* surface = nullptr;

  bool render_pending = true;
  bool in_paint = false;
  int64_t render_count = 0;
  int wheel_delta = 0;  // Accumulated angle delta (1/8 degree) of high-resolution wheels.

  bool IsCurrent() const {
    QOpenGLContext* current = QOpenGLContext::currentContext();
    return context && current == context && current->surface() == surface;
  }

  // VTK asks for the context through events because the generic render window owns none.
  static void OnWindowEvent(vtkObject*, unsigned long event_id, void* client_data,
                            void* call_data) {
    auto* self = static_cast<Impl*>(client_data);
    switch (event_id) {
      case vtkCommand::WindowMakeCurrentEvent:
        // Only QOpenGLContext::makeCurrent on the saved pair: QOpenGLWidget::makeCurrent would
        // also rebind Qt's FBO behind VTK's cached GL state, and the blit would then fail.
        if (self->context && self->surface && !self->IsCurrent()) {
          self->context->makeCurrent(self->surface);
        }
        break;
      case vtkCommand::WindowIsCurrentEvent:
        *static_cast<bool*>(call_data) = self->IsCurrent();
        break;
      case vtkCommand::WindowFrameEvent:
        // A render finished; show it. Inside paintGL the blit follows anyway.
        if (!self->in_paint) self->widget->update();
        break;
      default:
        break;
    }
  }

  static void OnInteractorEvent(vtkObject*, unsigned long event_id, void* client_data, void*) {
    auto* self = static_cast<Impl*>(client_data);
    // RenderEvent: the interaction style wants a new frame; coalesce it into the next paint.
    // ExitEvent: swallowed, because the trackball style's 'e' and 'q' keys would end the program.
    if (event_id == vtkCommand::RenderEvent) self->widget->ScheduleRender();
  }

  void ForwardMouse(QMouseEvent* event, unsigned long vtk_event, bool repeat) {
    const double dpr = widget->devicePixelRatioF();
    const Qt::KeyboardModifiers mods = event->modifiers();
    interactor->SetEventInformationFlipY(static_cast<int>(event->position().x() * dpr),
                                         static_cast<int>(event->position().y() * dpr),
                                         (mods & Qt::ControlModifier) ? 1 : 0,
                                         (mods & Qt::ShiftModifier) ? 1 : 0, 0, repeat ? 1 : 0);
    interactor->SetAltKey((mods & Qt::AltModifier) ? 1 : 0);
    interactor->InvokeEvent(vtk_event, event);
  }

  void ForwardKey(QKeyEvent* event, bool press) {
    const QString text = event->text();
    const char ascii = text.size() == 1 && text[0].unicode() < 128 && text[0].isPrint()
                           ? static_cast<char>(text[0].unicode())
                           : 0;
    char printable[2] = {ascii, 0};
    const char* sym = KeySymOf(event->key());
    if (sym == nullptr) sym = ascii != 0 ? printable : "None";
    const Qt::KeyboardModifiers mods = event->modifiers();
    interactor->SetKeyEventInformation((mods & Qt::ControlModifier) ? 1 : 0,
                                       (mods & Qt::ShiftModifier) ? 1 : 0, ascii,
                                       event->isAutoRepeat() ? 1 : 0, sym);
    interactor->SetAltKey((mods & Qt::AltModifier) ? 1 : 0);
    if (press) {
      interactor->InvokeEvent(vtkCommand::KeyPressEvent, event);
      if (ascii != 0) interactor->InvokeEvent(vtkCommand::CharEvent, event);
    } else {
      interactor->InvokeEvent(vtkCommand::KeyReleaseEvent, event);
    }
  }
};

VtkGlWidget::VtkGlWidget(QWidget* parent)
    : QOpenGLWidget(parent), impl_(std::make_unique<Impl>(this)) {
  if (QSurfaceFormat::defaultFormat().version() < qMakePair(3, 2)) {
    // The application forgot SetDefaultSurfaceFormat(); at least this widget gets a usable GL.
    qWarning("VtkGlWidget: call VtkGlWidget::SetDefaultSurfaceFormat() before QApplication");
    setFormat(DefaultSurfaceFormat());
  }
  setFocusPolicy(Qt::StrongFocus);
  setUpdateBehavior(QOpenGLWidget::NoPartialUpdate);

  vtkGenericOpenGLRenderWindow* window = impl_->window;
  window->SetReadyForRendering(false);          // No context before initializeGL.
  window->SetFrameBlitModeToNoBlit();           // paintGL blits into Qt's framebuffer itself.
  window->SetForceMaximumHardwareLineWidth(1);  // Wide lines through VTK's shader, not the driver.
  window->AddRenderer(impl_->renderer);

  impl_->window_observer->SetClientData(impl_.get());
  impl_->window_observer->SetCallback(&Impl::OnWindowEvent);
  window->AddObserver(vtkCommand::WindowMakeCurrentEvent, impl_->window_observer);
  window->AddObserver(vtkCommand::WindowIsCurrentEvent, impl_->window_observer);
  window->AddObserver(vtkCommand::WindowFrameEvent, impl_->window_observer);

  vtkGenericRenderWindowInteractor* interactor = impl_->interactor;
  interactor->SetRenderWindow(window);
  interactor->EnableRenderOff();  // Interaction only schedules renders (RenderEvent below).
  vtkNew<vtkInteractorStyleTrackballCamera> style;
  interactor->SetInteractorStyle(style);
  impl_->interactor_observer->SetClientData(impl_.get());
  impl_->interactor_observer->SetCallback(&Impl::OnInteractorEvent);
  interactor->AddObserver(vtkCommand::RenderEvent, impl_->interactor_observer);
  interactor->AddObserver(vtkCommand::ExitEvent, impl_->interactor_observer);
  interactor->Initialize();
}

VtkGlWidget::~VtkGlWidget() {
  // The context dies in ~QOpenGLWidget, after this object is gone: release VTK's resources now.
  if (impl_->context) {
    disconnect(impl_->context, &QOpenGLContext::aboutToBeDestroyed, this,
               &VtkGlWidget::CleanupContext);
    makeCurrent();
    CleanupContext();
    doneCurrent();
  }
  impl_->window->RemoveObserver(impl_->window_observer);
  impl_->interactor->RemoveObserver(impl_->interactor_observer);
}

QSurfaceFormat VtkGlWidget::DefaultSurfaceFormat() {
  QSurfaceFormat format;
  format.setRenderableType(QSurfaceFormat::OpenGL);
  format.setVersion(3, 2);
  format.setProfile(QSurfaceFormat::CoreProfile);
  format.setSwapBehavior(QSurfaceFormat::DoubleBuffer);
  format.setRedBufferSize(8);
  format.setGreenBufferSize(8);
  format.setBlueBufferSize(8);
  format.setAlphaBufferSize(8);
  format.setDepthBufferSize(8);
  format.setStencilBufferSize(0);
  format.setSamples(0);  // VTK renders into its own framebuffers; the context needs none.
  return format;
}

void VtkGlWidget::SetDefaultSurfaceFormat() {
  QSurfaceFormat::setDefaultFormat(DefaultSurfaceFormat());
}

vtkRenderer* VtkGlWidget::renderer() const { return impl_->renderer; }

vtkRenderWindow* VtkGlWidget::renderWindow() const { return impl_->window; }

void VtkGlWidget::ScheduleRender() {
  impl_->render_pending = true;
  update();  // Qt merges update requests until the next paint.
}

int64_t VtkGlWidget::render_count() const { return impl_->render_count; }

void VtkGlWidget::initializeGL() {
  // Called again with a new context when the widget moves to another top-level window.
  impl_->context = context();
  impl_->surface = context()->surface();
  connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &VtkGlWidget::CleanupContext,
          static_cast<Qt::ConnectionType>(Qt::DirectConnection | Qt::UniqueConnection));

  vtkGenericOpenGLRenderWindow* window = impl_->window;
  window->GetState()->Reset();
  window->SetOwnContext(0);
  window->OpenGLInitContext();
  window->SetReadyForRendering(true);
  impl_->render_pending = true;
}

void VtkGlWidget::resizeGL(int w, int h) {
  const double dpr = devicePixelRatioF();
  const int device_w = static_cast<int>(std::lround(w * dpr));
  const int device_h = static_cast<int>(std::lround(h * dpr));
  impl_->interactor->UpdateSize(device_w, device_h);  // Also resizes the render window.
  if (const QScreen* s = screen()) {
    impl_->window->SetScreenSize(static_cast<int>(s->size().width() * dpr),
                                 static_cast<int>(s->size().height() * dpr));
  }
  impl_->window->SetDPI(static_cast<int>(std::lround(72 * dpr)));
  impl_->render_pending = true;
}

void VtkGlWidget::paintGL() {
  vtkGenericOpenGLRenderWindow* window = impl_->window;
  if (!window->GetReadyForRendering()) return;
  vtkOpenGLState* state = window->GetState();
  state->Reset();  // Qt changed GL state behind VTK's cache since the last frame.
  state->Push();
  state->vtkglDepthFunc(GL_LEQUAL);  // Qt leaves GL_LESS; VTK expects GL_LEQUAL.

  if (impl_->render_pending) {
    impl_->render_pending = false;
    impl_->in_paint = true;
    window->Render();
    impl_->in_paint = false;
    ++impl_->render_count;
  }
  // A render may have switched contexts (e.g. a progress callback painting another widget).
  if (!impl_->IsCurrent()) impl_->context->makeCurrent(impl_->surface);

  QOpenGLExtraFunctions* gl = impl_->context->extraFunctions();
  gl->glBindFramebuffer(GL_DRAW_FRAMEBUFFER, defaultFramebufferObject());
  const GLenum draw_buffer = GL_COLOR_ATTACHMENT0;
  gl->glDrawBuffers(1, &draw_buffer);
  const bool scissor = gl->glIsEnabled(GL_SCISSOR_TEST) == GL_TRUE;
  if (scissor) {
    state->vtkglDisable(GL_SCISSOR_TEST);
    gl->glDisable(GL_SCISSOR_TEST);
  }
  const double dpr = devicePixelRatioF();
  const int target_w = static_cast<int>(std::lround(width() * dpr));
  const int target_h = static_cast<int>(std::lround(height() * dpr));
  int* source_size = window->GetRenderFramebuffer()->GetLastSize();
  window->BlitDisplayFramebuffer(0, 0, 0, source_size[0], source_size[1], 0, 0, target_w, target_h,
                                 GL_COLOR_BUFFER_BIT, GL_LINEAR);

  // Opaque alpha, or the compositor blends the view with whatever lies behind the window.
  GLboolean mask[4];
  gl->glGetBooleanv(GL_COLOR_WRITEMASK, mask);
  GLfloat clear[4];
  gl->glGetFloatv(GL_COLOR_CLEAR_VALUE, clear);
  gl->glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
  gl->glClearColor(0, 0, 0, 1);
  gl->glClear(GL_COLOR_BUFFER_BIT);
  gl->glColorMask(mask[0], mask[1], mask[2], mask[3]);
  gl->glClearColor(clear[0], clear[1], clear[2], clear[3]);

  if (scissor) {
    state->vtkglEnable(GL_SCISSOR_TEST);
    gl->glEnable(GL_SCISSOR_TEST);
  }
  state->Pop();
}

void VtkGlWidget::CleanupContext() {
  if (!impl_->context) return;
  // Finalize needs the context current; VTK asks for it through WindowMakeCurrentEvent.
  impl_->window->Finalize();
  impl_->window->SetReadyForRendering(false);
  impl_->context = nullptr;
  impl_->surface = nullptr;
}

void VtkGlWidget::mousePressEvent(QMouseEvent* event) {
  switch (event->button()) {
    case Qt::LeftButton:
      impl_->ForwardMouse(event, vtkCommand::LeftButtonPressEvent, false);
      break;
    case Qt::MiddleButton:
      impl_->ForwardMouse(event, vtkCommand::MiddleButtonPressEvent, false);
      break;
    case Qt::RightButton:
      impl_->ForwardMouse(event, vtkCommand::RightButtonPressEvent, false);
      break;
    default:
      break;
  }
}

void VtkGlWidget::mouseReleaseEvent(QMouseEvent* event) {
  switch (event->button()) {
    case Qt::LeftButton:
      impl_->ForwardMouse(event, vtkCommand::LeftButtonReleaseEvent, false);
      break;
    case Qt::MiddleButton:
      impl_->ForwardMouse(event, vtkCommand::MiddleButtonReleaseEvent, false);
      break;
    case Qt::RightButton:
      impl_->ForwardMouse(event, vtkCommand::RightButtonReleaseEvent, false);
      break;
    default:
      break;
  }
}

void VtkGlWidget::mouseDoubleClickEvent(QMouseEvent* event) {
  // VTK sees a double click as a press with the repeat flag set.
  if (event->button() == Qt::LeftButton) {
    impl_->ForwardMouse(event, vtkCommand::LeftButtonPressEvent, true);
  } else if (event->button() == Qt::RightButton) {
    impl_->ForwardMouse(event, vtkCommand::RightButtonPressEvent, true);
  } else if (event->button() == Qt::MiddleButton) {
    impl_->ForwardMouse(event, vtkCommand::MiddleButtonPressEvent, true);
  }
}

void VtkGlWidget::mouseMoveEvent(QMouseEvent* event) {
  impl_->ForwardMouse(event, vtkCommand::MouseMoveEvent, false);
}

void VtkGlWidget::wheelEvent(QWheelEvent* event) {
  const double dpr = devicePixelRatioF();
  const Qt::KeyboardModifiers mods = event->modifiers();
  impl_->interactor->SetEventInformationFlipY(
      static_cast<int>(event->position().x() * dpr), static_cast<int>(event->position().y() * dpr),
      (mods & Qt::ControlModifier) ? 1 : 0, (mods & Qt::ShiftModifier) ? 1 : 0);
  impl_->interactor->SetAltKey((mods & Qt::AltModifier) ? 1 : 0);
  // One VTK wheel step per notch (120); touchpads send many small deltas.
  impl_->wheel_delta += event->angleDelta().y();
  constexpr int kNotch = 120;
  if (impl_->wheel_delta >= kNotch) {
    impl_->interactor->InvokeEvent(vtkCommand::MouseWheelForwardEvent, event);
    impl_->wheel_delta = 0;
  } else if (impl_->wheel_delta <= -kNotch) {
    impl_->interactor->InvokeEvent(vtkCommand::MouseWheelBackwardEvent, event);
    impl_->wheel_delta = 0;
  }
  event->accept();
}

void VtkGlWidget::keyPressEvent(QKeyEvent* event) { impl_->ForwardKey(event, true); }

void VtkGlWidget::keyReleaseEvent(QKeyEvent* event) { impl_->ForwardKey(event, false); }

void VtkGlWidget::enterEvent(QEnterEvent* event) {
  impl_->interactor->InvokeEvent(vtkCommand::EnterEvent, event);
  QOpenGLWidget::enterEvent(event);
}

void VtkGlWidget::leaveEvent(QEvent* event) {
  impl_->interactor->InvokeEvent(vtkCommand::LeaveEvent, event);
  QOpenGLWidget::leaveEvent(event);
}

}  // namespace sightline
