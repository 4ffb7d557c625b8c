// The mobility map's dock panels: the scores projected on the colour image, the top-view grid,
// the GPR score surface, and the per-stage timing table (ms and points, as the seed's Table II).
#pragma once

#include <QWidget>
#include <memory>

#include "core/mobility/mobility_types.h"
#include "core/pipeline/mobility_result.h"

class QComboBox;
class QLabel;
class QTableWidget;

namespace sightline {

class ImageView;

// The per-stage timing table with a summary line above it.
class MobilityTimingPanel : public QWidget {
  Q_OBJECT

 public:
  explicit MobilityTimingPanel(QWidget* parent = nullptr);
  // Shows one frame's stages (its statistics, with their units), status and segment count.
  void Show(const MobilityFrameResult& result);
  const QTableWidget* table() const { return table_; }
  // How the 3D cloud is coloured: by the rule's score, the GPR's score or the segment.
  QComboBox* color_choice() const { return color_choice_; }

 private:
  QLabel* summary_ = nullptr;
  QTableWidget* table_ = nullptr;
  QComboBox* color_choice_ = nullptr;
};

// The image views of one frame: projection, top view and the (fixed) GPR surface.
class MobilityImagePanel : public QWidget {
  Q_OBJECT

 public:
  explicit MobilityImagePanel(QWidget* parent = nullptr);
  void Show(const MobilityResult& result);
  void SetScoreSurface(const cv::Mat& image);
  const ImageView* projection_view() const { return projection_; }
  const ImageView* top_view() const { return top_; }

 private:
  ImageView* projection_ = nullptr;
  ImageView* top_ = nullptr;
  ImageView* surface_ = nullptr;
};

}  // namespace sightline
