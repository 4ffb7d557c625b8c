// The GUI side of a perception pipeline: its options, its processor, and the views that draw
// its results. The main window lists presenters in its Pipeline menu; one is active at a time.
#pragma once

#include <QCoreApplication>
#include <QObject>
#include <QString>
#include <memory>

#include "app/sightline/frame_processor.h"
#include "app/sightline/playback_result.h"
#include "core/io/source.h"
#include "core/options/option_set.h"

class QMainWindow;

namespace sightline {

// One pipeline in the GUI. Lives on the GUI thread; only its FrameProcessor runs on the worker.
class PipelinePresenter : public QObject {
  Q_OBJECT

 public:
  using QObject::QObject;
  ~PipelinePresenter() override = default;

  // Menu title in English, marked with QT_TR_NOOP so lupdate files it under the presenter's
  // class, e.g. "Indoor mapping". `sightline --pipeline WORD` matches it in any language.
  virtual const char* TitleSource() const = 0;
  // Menu title in the user's language.
  QString Title() const {
    return QCoreApplication::translate(metaObject()->className(), TitleSource());
  }
  // Declares the pipeline's options (its Describe() tables) into the window's option set.
  virtual Status DeclareOptions(OptionSet* options) const = 0;
  // Whether the pipeline can run on frames of this kind.
  virtual bool Accepts(SourceKind kind) const = 0;
  // A processor for an opened source, or nullptr when the source lacks what it needs (then
  // Message says why).
  virtual std::unique_ptr<FrameProcessor> CreateProcessor(const SourceInfo& info) = 0;
  // Adds the pipeline's views to the window / removes them again.
  virtual void Attach(QMainWindow* window) = 0;
  virtual void Detach() = 0;
  // Draws the pipeline's result of one frame.
  virtual void Show(const PlaybackResult& result) = 0;

 signals:
  // Something the user should read in the log (severity 0 info, 1 warning, 2 error).
  void Message(int severity, const QString& text);
};

}  // namespace sightline
