// A 3D scene of named layers (clouds, lines, trajectories, poses, camera frusta) for robot
// perception results. VTK stays inside the .cpp files.
#pragma once

#include <Eigen/Geometry>
#include <QColor>
#include <QString>
#include <memory>
#include <opencv2/core/mat.hpp>
#include <string>
#include <utility>
#include <vector>

#include "widgets/vtk_gl_widget.h"

class QLabel;

namespace sightline {

struct PointCloud;
class Trajectory;

// A 3D view with named layers. Setting a layer replaces what it showed; layers are drawn in the
// world frame, optionally placed by SetLayerPose. The default axes suit camera optical frames
// (z forward, y down): the first view looks along +z from behind with -y up. Call
// SetViewAxes({0, 0, 1}, {1, 0, 0}) for z-up robot or map frames.
//
// Only the GUI thread may call it; hand results over with queued signals carrying
// std::shared_ptr<const ...>. Renders are scheduled, never immediate, so updating ten layers
// costs one render.
//
//   SceneView* view = new SceneView(this);
//   view->SetPointCloud("cloud", frame.cloud, SceneView::ColorMode::kAuto);
//   view->SetTrajectory("estimate", trajectory, Qt::yellow);
//   view->SetFrusta("camera", {world_from_camera}, Qt::cyan, 0.3);
class SceneView : public VtkGlWidget {
  Q_OBJECT

 public:
  // How points of a cloud layer get their colour.
  enum class ColorMode {
    kAuto,    // kRgb when the cloud has colours, else kDepth.
    kRgb,     // The cloud's own colours (falls back to kDepth without them).
    kDepth,   // Distance along the forward axis, turbo colour map.
    kHeight,  // Height along the up axis, turbo colour map.
  };

  // A line segment in the layer's frame, metres.
  using Segment = std::pair<Eigen::Vector3d, Eigen::Vector3d>;

  // Creates an empty scene with a ground grid and a dark background.
  explicit SceneView(QWidget* parent = nullptr);
  // Out of line: Impl holds VTK types.
  ~SceneView() override;

  // Shows a point cloud; NaN points are skipped. The cloud is converted at once and not kept.
  void SetPointCloud(const std::string& layer, const std::shared_ptr<const PointCloud>& cloud,
                     ColorMode mode = ColorMode::kAuto, double point_size_px = 2.0);
  // Shows line segments in one colour.
  void SetLines(const std::string& layer, const std::vector<Segment>& segments, QColor color,
                double line_width_px = 2.0);
  // Shows the path through a trajectory's positions.
  void SetTrajectory(const std::string& layer, const Trajectory& trajectory, QColor color,
                     double line_width_px = 2.0);
  // Shows an axis triad of length `size` metres per pose (world_from_frame). An invalid colour
  // (QColor()) draws x red, y green, z blue; a valid one draws all axes in it, to tell pose sets
  // apart.
  void SetPoses(const std::string& layer, const std::vector<Eigen::Isometry3d>& poses, QColor color,
                double size);
  // Shows a camera frustum per pose (world_from_camera, optical frame): apex at the centre,
  // image plane at `size` metres along z, and a small triangle over the image's top edge.
  void SetFrusta(const std::string& layer, const std::vector<Eigen::Isometry3d>& poses,
                 QColor color, double size);
  // Shows an image on a flat rectangle, e.g. an occupancy map on the floor: `origin` is where the
  // image's bottom-left corner lies (layer frame, metres), `right` the rectangle's edge along the
  // image's bottom row and `up` its edge along the left column (bottom to top). `image` is BGR
  // (CV_8UC3) or grey (CV_8UC1) and is copied; `opacity` in [0, 1]. Setting the layer again
  // updates the texture and the corners of the same actor (a growing map is not rebuilt).
  void SetImagePlane(const std::string& layer, const cv::Mat& image, const Eigen::Vector3d& origin,
                     const Eigen::Vector3d& right, const Eigen::Vector3d& up, double opacity = 1.0);
  // Removes a layer; unknown names are ignored.
  void RemoveLayer(const std::string& layer);
  // Removes every layer (the ground grid stays).
  void ClearLayers();
  // Places a layer in the world (world_from_layer), e.g. a cloud in the camera frame.
  void SetLayerPose(const std::string& layer, const Eigen::Isometry3d& world_from_layer);
  // Shows or hides a layer without discarding it. A cloud set while its layer is hidden is
  // built when the layer is shown.
  void SetLayerVisible(const std::string& layer, bool visible);
  // Whether a layer of that name exists.
  bool HasLayer(const std::string& layer) const;
  // Whether a layer is shown (true for a layer not made yet: it shows once set).
  bool IsLayerVisible(const std::string& layer) const;
  // Names of all layers, sorted.
  std::vector<std::string> LayerNames() const;

  // Shows a square grid perpendicular to the up axis, `height_m` above the origin (e.g. -1.2 for
  // the floor under a camera held at 1.2 m in an optical-frame scene).
  void SetGroundGrid(bool visible, double spacing_m = 1.0, int cells_per_side = 20,
                     double height_m = 0.0);
  // The scene's up and forward directions (world frame); they orient the grid, the default
  // view, and kHeight / kDepth colouring of clouds set afterwards.
  void SetViewAxes(const Eigen::Vector3d& up, const Eigen::Vector3d& forward);
  // Fits all visible layers (the grid only when nothing else is shown), looking along the
  // forward axis from behind and slightly above, with the up axis up.
  void ResetView();
  // Background colour of the view.
  void SetBackground(QColor color);

  // A key to the layers' colours (e.g. estimate and ground truth, wall classes) in the view's
  // top-left corner; empty hides it. ClearLayers removes it too.
  struct Key {
    QColor color;
    QString label;
  };
  void SetKeys(const std::vector<Key>& keys);
  const std::vector<Key>& keys() const { return keys_; }
  // The widget that shows the key (hidden when there is none).
  QLabel* keys_label() const { return keys_label_; }

  // Follow (View > Follow the trajectory): FollowContent re-fits the view (ResetView) when
  // `content` leaves the box it was last fitted to, that box grown by a quarter of the extent
  // (at least `min_margin`) so that a growing trajectory re-fits every few metres, not every
  // frame. Nothing while follow is off. Returns whether it fitted; ClearLayers forgets the box.
  bool FollowContent(const Eigen::AlignedBox3d& content, double min_margin = 2.0);
  void SetFollow(bool follow) { follow_ = follow; }
  bool follow() const { return follow_; }
  // Fits made by FollowContent since the view was made.
  int follow_fits() const { return follow_fits_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::vector<Key> keys_;
  QLabel* keys_label_ = nullptr;
  bool follow_ = true;
  Eigen::AlignedBox3d followed_box_;  // Empty: nothing followed yet.
  int follow_fits_ = 0;
};

}  // namespace sightline
