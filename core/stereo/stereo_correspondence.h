// A feature seen in both images of a rectified pair at two times: the input of motion estimation.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/stereo/stereo_geometry.h"

namespace sightline {

// A stereo observation in a rectified pair: left pixel and right column (same row).
struct StereoObservation {
  double u_left = 0;   // [px]
  double v = 0;        // Row in both images [px].
  double u_right = 0;  // [px]

  double disparity() const { return u_left - u_right; }
};

// One feature at the previous and the current time, with both triangulations.
struct StereoCorrespondence {
  StereoObservation previous;
  StereoObservation current;
  Eigen::Vector3d x_previous = Eigen::Vector3d::Zero();  // Point in the previous left camera [m].
  Eigen::Vector3d x_current = Eigen::Vector3d::Zero();   // Point in the current left camera [m].
};

// Fills x_previous and x_current from the observations.
inline void Triangulate(const RectifiedStereoCamera& camera, StereoCorrespondence* c) {
  c->x_previous = camera.Triangulate(c->previous.u_left, c->previous.v, c->previous.disparity());
  c->x_current = camera.Triangulate(c->current.u_left, c->current.v, c->current.disparity());
}

}  // namespace sightline
