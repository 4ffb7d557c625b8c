#include "board_renderer.h"

#include <cmath>
#include <opencv2/imgproc.hpp>

namespace sightline::testing {

cv::Mat RenderBoardView(const PinholeCamera& camera, const Eigen::Isometry3d& camera_from_board,
                        const ChessboardOptions& board, double noise_sigma, int seed) {
  const int px = 24;  // Texture pixels per square.
  const double s = board.square_size_m, delta = s / px;
  const int squares_x = board.columns + 3, squares_y = board.rows + 3;  // Incl. margin.
  cv::Mat texture(squares_y * px, squares_x * px, CV_8UC1, cv::Scalar(235));
  for (int r = 1; r < squares_y - 1; ++r) {
    for (int c = 1; c < squares_x - 1; ++c) {
      if ((r + c) % 2 == 0) {
        texture(cv::Rect(c * px, r * px, px, px)).setTo(25);
      }
    }
  }
  // Texture pixel (u, v) centre -> board point (-2 s + (u + 0.5) delta, ...).
  Eigen::Matrix3d board_from_texture;
  board_from_texture << delta, 0, -2 * s + 0.5 * delta, 0, delta, -2 * s + 0.5 * delta, 0, 0, 1;
  Eigen::Matrix3d image_from_board;
  image_from_board.col(0) = camera_from_board.linear().col(0);
  image_from_board.col(1) = camera_from_board.linear().col(1);
  image_from_board.col(2) = camera_from_board.translation();
  const Eigen::Matrix3d h = camera.K() * image_from_board * board_from_texture;
  cv::Mat h_cv(3, 3, CV_64F);
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) h_cv.at<double>(r, c) = h(r, c);
  }
  cv::Mat image;
  cv::warpPerspective(texture, image, h_cv, cv::Size(camera.width, camera.height), cv::INTER_AREA,
                      cv::BORDER_CONSTANT, cv::Scalar(128));
  cv::GaussianBlur(image, image, cv::Size(3, 3), 0.7);
  cv::Mat noise(image.size(), CV_32F);
  cv::RNG rng(seed);
  rng.fill(noise, cv::RNG::NORMAL, 0, noise_sigma);
  cv::Mat out;
  image.convertTo(out, CV_32F);
  out += noise;
  out.convertTo(image, CV_8U);
  return image;
}

std::vector<cv::Point2f> ProjectBoard(const PinholeCamera& camera,
                                      const Eigen::Isometry3d& camera_from_board,
                                      const ChessboardOptions& board) {
  std::vector<cv::Point2f> out;
  for (const cv::Point3f& p : board.ObjectPoints()) {
    const Eigen::Vector2d uv = camera.Project(camera_from_board * Eigen::Vector3d(p.x, p.y, p.z));
    out.emplace_back(static_cast<float>(uv.x()), static_cast<float>(uv.y()));
  }
  return out;
}

Eigen::Isometry3d BoardFromCameraLookingAt(const ChessboardOptions& board, double distance_m,
                                           double off_axis_deg, double azimuth_deg,
                                           double roll_deg) {
  const double d2r = M_PI / 180;
  const Eigen::Vector3d centre((board.columns - 1) * board.square_size_m / 2,
                               (board.rows - 1) * board.square_size_m / 2, 0);
  // The camera sits on the board's -z side (the board's z axis points away from the camera).
  const double a = off_axis_deg * d2r, b = azimuth_deg * d2r;
  const Eigen::Vector3d direction(std::sin(a) * std::cos(b), std::sin(a) * std::sin(b),
                                  -std::cos(a));
  const Eigen::Vector3d position = centre + distance_m * direction;
  const Eigen::Vector3d z = (centre - position).normalized();
  Eigen::Vector3d x = Eigen::Vector3d::UnitX() - z * z.x();
  x.normalize();
  const Eigen::Vector3d y = z.cross(x);
  Eigen::Matrix3d r;
  r << x, y, z;
  Eigen::Isometry3d board_from_camera = Eigen::Isometry3d::Identity();
  board_from_camera.linear() = r * Eigen::AngleAxisd(roll_deg * d2r, Eigen::Vector3d::UnitZ());
  board_from_camera.translation() = position;
  return board_from_camera;
}

}  // namespace sightline::testing
