#include "app/cli/progress.h"

#include <unistd.h>

#include <cstdio>

#include "core/common/timing.h"

namespace sightline::cli {

ProgressLine::ProgressLine(std::string label)
    : label_(std::move(label)), enabled_(isatty(STDERR_FILENO) == 1), start_s_(HostTimeS()) {}

ProgressLine::~ProgressLine() { Finish(); }

void ProgressLine::Update(int64_t done, int64_t total) {
  if (!enabled_) return;
  const double now = HostTimeS();
  if (now - last_draw_s_ < 0.2 && done != total) return;
  last_draw_s_ = now;
  const double elapsed = now - start_s_;
  const double fps = elapsed > 0 ? done / elapsed : 0;
  if (total > 0) {
    const double eta = fps > 0 ? (total - done) / fps : 0;
    std::fprintf(stderr, "\r%s: %lld/%lld frames  %.1f fps  ETA %.0f s   ", label_.c_str(),
                 static_cast<long long>(done), static_cast<long long>(total), fps, eta);
  } else {
    std::fprintf(stderr, "\r%s: %lld frames  %.1f fps   ", label_.c_str(),
                 static_cast<long long>(done), fps);
  }
  std::fflush(stderr);
  drawn_ = true;
}

void ProgressLine::Finish() {
  if (enabled_ && drawn_) {
    std::fprintf(stderr, "\r%80s\r", "");
    std::fflush(stderr);
    drawn_ = false;
  }
}

}  // namespace sightline::cli
