#include "app/sightline/mobility_presenter.h"

#include <QComboBox>
#include <QDockWidget>
#include <QMainWindow>
#include <limits>

#include "app/sightline/mobility_views.h"
#include "core/mobility/mobility_map.h"
#include "core/mobility/mobility_mapper.h"
#include "core/mobility/score_plot.h"
#include "widgets/scene_view.h"

namespace sightline {

namespace {

constexpr const char* kScoreLayer = "mobility/score";
constexpr const char* kGprLayer = "mobility/score_gpr";
constexpr const char* kSegmentLayer = "mobility/segments";
constexpr const char* kInputLayer = "cloud";  // The main window's cloud of the frame.

// What the mobility processor hands the GUI for one frame.
struct MobilityViewResult : PipelineFrameResult {
  std::shared_ptr<const MobilityResult> mobility;
  std::shared_ptr<const PointCloud> by_score;    // The scored cloud in rule-score colours.
  std::shared_ptr<const PointCloud> by_gpr;      // ... in GPR-score colours.
  std::shared_ptr<const PointCloud> by_segment;  // ... in segment colours.
};

// A colour per segment id (the ground grey-blue, unsegmented dark).
Eigen::Matrix<uint8_t, 3, 1> SegmentColor(const MobilityResult& r, int segment) {
  if (segment < 0) return {50, 50, 50};
  if (r.segments[segment].is_ground) return {110, 130, 170};
  const uint32_t h = static_cast<uint32_t>(segment) * 2654435761u;
  return {static_cast<uint8_t>(80 + (h >> 8) % 176), static_cast<uint8_t>(80 + (h >> 16) % 176),
          static_cast<uint8_t>(80 + (h >> 24) % 176)};
}

// Runs MobilityMapper on the playback worker; frames are independent, so a re-run is a run.
class MobilityProcessor : public FrameProcessor {
 public:
  explicit MobilityProcessor(SourceInfo info) : info_(std::move(info)) {}

  Status Configure(const OptionSet& options) override {
    const MobilityOptions parsed = options.Extract(MobilityOptions::Describe());
    return mapper_.Configure(parsed);
  }

  std::shared_ptr<const PipelineFrameResult> ProcessFrame(const Frame& frame) override {
    auto result = std::make_shared<MobilityViewResult>();
    result->stamp = StampOf(frame);
    MobilityInput input;
    if (const auto* rgbd = std::get_if<RgbdFrame>(&frame)) {
      if (!info_.rgbd) {
        result->status = FailedPrecondition(info_.path + ": the RGB-D source has no camera");
        return result;
      }
      input = MobilityInputFromRgbd(*rgbd, info_.rgbd->color);
    } else if (const auto* cloud = std::get_if<CloudFrame>(&frame)) {
      input = MobilityInputFromCloud(*cloud);
    } else {
      result->status = FailedPrecondition("the mobility map needs RGB-D frames or point clouds");
      return result;
    }
    result->mobility = mapper_.Process(input);
    const MobilityResult& r = *result->mobility;
    result->status = r.status;
    for (const StageReport& s : r.stages)
      result->stats.emplace_back("mobility/" + s.name + "_ms", s.ms);
    result->stats.emplace_back("mobility/total_ms", r.TotalMs());
    result->stats.emplace_back("mobility/segments", static_cast<double>(r.segments.size()));
    auto by_score = std::make_shared<PointCloud>();
    auto by_gpr = std::make_shared<PointCloud>();
    auto by_segment = std::make_shared<PointCloud>();
    for (PointCloud* cloud : {by_score.get(), by_gpr.get(), by_segment.get()}) {
      cloud->points = r.points;
      cloud->width = static_cast<int>(r.points.size());
    }
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (size_t i = 0; i < r.points.size(); ++i) {
      const int s = r.segment[i];
      const cv::Vec3b rule =
          ScoreColorBgr(s < 0 ? nan : static_cast<float>(r.segments[s].score_rule));
      const cv::Vec3b gpr =
          ScoreColorBgr(s < 0 ? nan : static_cast<float>(r.segments[s].score_gpr));
      by_score->colors.emplace_back(rule[2], rule[1], rule[0]);
      by_gpr->colors.emplace_back(gpr[2], gpr[1], gpr[0]);
      by_segment->colors.push_back(SegmentColor(r, s));
    }
    result->by_score = std::move(by_score);
    result->by_gpr = std::move(by_gpr);
    result->by_segment = std::move(by_segment);
    return result;
  }

  std::shared_ptr<const PipelineFrameResult> ReprocessFrame(const Frame& frame) override {
    return ProcessFrame(frame);
  }
  void Reset() override {}

 private:
  SourceInfo info_;
  MobilityMapper mapper_;
};

}  // namespace

MobilityPresenter::MobilityPresenter(QObject* parent) : PipelinePresenter(parent) {}

const char* MobilityPresenter::TitleSource() const { return QT_TR_NOOP("Mobility map"); }

Status MobilityPresenter::DeclareOptions(OptionSet* options) const {
  return options->Declare(MobilityOptions::Describe());
}

bool MobilityPresenter::Accepts(SourceKind kind) const {
  return kind == SourceKind::kRgbd || kind == SourceKind::kCloud;
}

std::unique_ptr<Pipeline> MobilityPresenter::CreateProcessor(const PipelineSource& source) {
  const SourceInfo& info = source.info;
  return std::make_unique<MobilityProcessor>(info);
}

std::vector<std::string> MobilityPresenter::SceneLayers() {
  return {kScoreLayer, kGprLayer, kSegmentLayer};
}

void MobilityPresenter::Attach(QMainWindow* window) {
  if (images_dock_ == nullptr) {
    images_ = new MobilityImagePanel(window);
    images_->SetScoreSurface(RenderScoreSurface(GprScore::TrainOnTable()));
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
  }
}

void MobilityPresenter::ApplyColorChoice() {
  if (scene_ == nullptr || timing_ == nullptr) return;
  const int choice = timing_->color_choice()->currentIndex();  // Rule, GPR, segment.
  const char* layers[3] = {kScoreLayer, kGprLayer, kSegmentLayer};
  for (int k = 0; k < 3; ++k) {
    if (scene_->HasLayer(layers[k])) scene_->SetLayerVisible(layers[k], k == choice);
  }
}

void MobilityPresenter::Show(const PlaybackResult& result) {
  const auto* view = dynamic_cast<const MobilityViewResult*>(result.pipeline.get());
  if (view == nullptr || images_ == nullptr || !view->mobility) return;
  images_->Show(*view->mobility);
  timing_->Show(*view->mobility);
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
