// A one-line progress display (frames done, fps, ETA) for terminals.
#pragma once

#include <cstdint>
#include <string>

namespace sightline::cli {

// Redraws one status line on stderr when it is a terminal; silent otherwise.
class ProgressLine {
 public:
  explicit ProgressLine(std::string label);
  ~ProgressLine();
  void Update(int64_t done, int64_t total);
  // Clears the line.
  void Finish();

 private:
  std::string label_;
  bool enabled_;
  double start_s_;
  double last_draw_s_ = -1;
  bool drawn_ = false;
};

}  // namespace sightline::cli
