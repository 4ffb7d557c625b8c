#include "app/sightline/mobility_presenter.h"

#include <QComboBox>
#include <QDockWidget>
#include <QMainWindow>

#include "app/sightline/mobility_views.h"
#include "core/mobility/mobility_map.h"
#include "core/pipeline/mobility_result.h"
#include "core/pipeline/pipeline_registry.h"
#include "widgets/scene_view.h"

namespace sightline {

namespace {

constexpr const char* kScoreLayer = "mobility/score";
constexpr const char* kGprLayer = "mobility/score_gpr";
constexpr const char* kSegmentLayer = "mobility/segments";
constexpr const char* kInputLayer = "cloud";  // The main window's cloud of the frame.

}  // namespace

MobilityPresenter::MobilityPresenter(QObject* parent)
    : PipelinePresenter(*BuiltinPipelines().Find("mobility"), parent) {}

const char* MobilityPresenter::TitleSource() const { return QT_TR_NOOP("Mobility map"); }

std::vector<std::string> MobilityPresenter::SceneLayers() {
  return {kScoreLayer, kGprLayer, kSegmentLayer};
}

void MobilityPresenter::Attach(QMainWindow* window) {
  if (images_dock_ == nullptr) {
    images_ = new MobilityImagePanel(window);
    images_->SetScoreSurface(MobilityScoreSurface());
    images_dock_ = new QDockWidget(tr("Mobility map (red 0, green 1)"), window);
    images_dock_->setObjectName("mobility_images_dock");
    images_dock_->setWidget(images_);
    timing_ = new MobilityTimingPanel(window);
    timing_dock_ = new QDockWidget(tr("Mobility stages (Table II)"), window);
    timing_dock_->setObjectName("mobility_timing_dock");
    timing_dock_->setWidget(timing_);
    connect(timing_->color_choice(), &QComboBox::currentIndexChanged, this,
            [this](int) { ApplyColorChoice(); });
  }
  scene_ = window->findChild<SceneView*>();
  window->addDockWidget(Qt::LeftDockWidgetArea, images_dock_);
  window->addDockWidget(Qt::LeftDockWidgetArea, timing_dock_);
  images_dock_->show();
  timing_dock_->show();
}

void MobilityPresenter::Detach() {
  if (images_dock_ != nullptr) images_dock_->hide();
  if (timing_dock_ != nullptr) timing_dock_->hide();
  if (scene_ != nullptr) {
    for (const std::string& layer : SceneLayers()) scene_->RemoveLayer(layer);
    scene_->SetLayerVisible(kInputLayer, true);
    scene_->SetKeys({});
  }
}

void MobilityPresenter::ApplyColorChoice() {
  if (scene_ == nullptr || timing_ == nullptr) return;
  const int choice = timing_->color_choice()->currentIndex();  // Rule, GPR, segment.
  const char* layers[3] = {kScoreLayer, kGprLayer, kSegmentLayer};
  for (int k = 0; k < 3; ++k) {
    if (scene_->HasLayer(layers[k])) scene_->SetLayerVisible(layers[k], k == choice);
  }
  // Rule and GPR clouds are coloured by score (as core's ScoreColorBgr); segments by region.
  const auto colour = [](float score) {
    const cv::Vec3b bgr = ScoreColorBgr(score);
    return QColor(bgr[2], bgr[1], bgr[0]);
  };
  if (choice == 2) {
    scene_->SetKeys({{QColor(200, 200, 200), tr("colour: one per segment")}});
  } else {
    scene_->SetKeys(
        {{colour(0.f), tr("score 0: not passable")}, {colour(1.f), tr("score 1: passable")}});
  }
}

void MobilityPresenter::Show(const PlaybackResult& result) {
  const auto* view = dynamic_cast<const MobilityFrameResult*>(result.pipeline.get());
  if (view == nullptr || images_ == nullptr || !view->mobility) return;
  images_->Show(*view->mobility);
  timing_->Show(*view);
  if (scene_ != nullptr && view->by_score) {
    scene_->SetPointCloud(kScoreLayer, view->by_score, SceneView::ColorMode::kRgb);
    scene_->SetPointCloud(kGprLayer, view->by_gpr, SceneView::ColorMode::kRgb);
    scene_->SetPointCloud(kSegmentLayer, view->by_segment, SceneView::ColorMode::kRgb);
    ApplyColorChoice();
    // The scored cloud stands in for the window's input cloud while the map runs.
    scene_->SetLayerVisible(kInputLayer, false);
  }
}

}  // namespace sightline
