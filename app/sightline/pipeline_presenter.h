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
#include "core/pipeline/pipeline_registry.h"

class QMainWindow;

namespace sightline {

// One pipeline in the GUI. Lives on the GUI thread; only its FrameProcessor runs on the worker.
class PipelinePresenter : public QObject {
  Q_OBJECT

 public:
  using QObject::QObject;
  // A presenter of the registry's pipeline `info`: its options, kinds and object come from
  // there, so the GUI runs exactly what `sightline-cli run` runs.
  explicit PipelinePresenter(PipelineInfo info, QObject* parent = nullptr)
      : QObject(parent), info_(std::move(info)) {}
  ~PipelinePresenter() override = default;

  // The registry's entry (empty name for a presenter made without one).
  const PipelineInfo& info() const { return info_; }

  // Menu title in English, marked with QT_TR_NOOP so lupdate files it under the presenter's
  // class, e.g. "Indoor mapping". `sightline --pipeline WORD` matches it in any language.
  virtual const char* TitleSource() const = 0;
  // Menu title in the user's language.
  QString Title() const {
    return QCoreApplication::translate(metaObject()->className(), TitleSource());
  }
  // Declares the pipeline's options (its Describe() tables) into the window's option set.
  virtual Status DeclareOptions(OptionSet* options) const {
    return info_.declare_options ? info_.declare_options(options) : Status::Ok();
  }
  // Whether the pipeline can run on frames of this kind.
  virtual bool Accepts(SourceKind kind) const { return info_.Accepts(kind); }
  // The pipeline object for an opened source (its info and ground truth), or nullptr when the
  // source lacks what it needs (then Message says why).
  virtual std::unique_ptr<Pipeline> CreateProcessor(const PipelineSource& source) {
    if (!info_.create || !info_.Accepts(source.info.kind)) return nullptr;
    return info_.create();
  }
  // Adds the pipeline's views to the window / removes them again.
  virtual void Attach(QMainWindow* window) = 0;
  virtual void Detach() = 0;
  // Draws the pipeline's result of one frame.
  virtual void Show(const PlaybackResult& result) = 0;

 signals:
  // Something the user should read in the log (severity 0 info, 1 warning, 2 error).
  void Message(int severity, const QString& text);

 private:
  PipelineInfo info_;
};

}  // namespace sightline
