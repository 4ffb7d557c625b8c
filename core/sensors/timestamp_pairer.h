// Pairs the frames of two streams (left/right camera, depth/colour) by timestamp.
#pragma once

#include <cmath>
#include <cstdint>
#include <deque>
#include <optional>
#include <utility>

namespace sightline {

// Matches items of stream 0 and stream 1 whose times differ by at most a tolerance. Each
// stream's times must not decrease. An item that can no longer find a partner (the other
// stream has moved past it) is dropped and counted, so memory stays bounded.
//
//   TimestampPairer<cv::Mat> pairer(0.005);
//   pairer.Add(0, left_time_s, left);                  // nullopt: waits for the right image
//   if (auto pair = pairer.Add(1, right_time_s, right)) Use(pair->first, pair->second);
//   stats.unpaired = pairer.unpaired();
//
// Not thread-safe; one capture thread feeds it.
template <typename T>
class TimestampPairer {
 public:
  // `tolerance` in the unit of the times given to Add(); `max_pending` items wait per stream.
  explicit TimestampPairer(double tolerance, size_t max_pending = 8)
      : tolerance_(tolerance), max_pending_(max_pending == 0 ? 1 : max_pending) {}

  // Adds an item of stream 0 or 1. Returns (stream 0 item, stream 1 item) when a pair forms;
  // at most one pair can form per call.
  std::optional<std::pair<T, T>> Add(int stream, double time, T item) {
    std::deque<Entry>& mine = pending_[stream == 0 ? 0 : 1];
    mine.push_back(Entry{time, std::move(item)});
    if (mine.size() > max_pending_) {
      mine.pop_front();
      ++unpaired_;
    }
    std::deque<Entry>& a = pending_[0];
    std::deque<Entry>& b = pending_[1];
    while (!a.empty() && !b.empty()) {
      const double diff = a.front().time - b.front().time;
      if (std::abs(diff) <= tolerance_) {
        // A later item of the earlier stream may match better (e.g. a frame arriving late).
        if (diff < 0 && a.size() > 1 && std::abs(a[1].time - b.front().time) < std::abs(diff)) {
          a.pop_front();
          ++unpaired_;
          continue;
        }
        if (diff > 0 && b.size() > 1 && std::abs(b[1].time - a.front().time) < std::abs(diff)) {
          b.pop_front();
          ++unpaired_;
          continue;
        }
        std::pair<T, T> pair(std::move(a.front().item), std::move(b.front().item));
        a.pop_front();
        b.pop_front();
        ++paired_;
        return pair;
      }
      // The earlier item is too old for the other stream's current and later items.
      (diff < 0 ? a : b).pop_front();
      ++unpaired_;
    }
    return std::nullopt;
  }

  // Items dropped without a partner so far.
  uint64_t unpaired() const { return unpaired_; }
  // Pairs formed so far.
  uint64_t paired() const { return paired_; }
  // Items currently waiting for a partner.
  size_t pending() const { return pending_[0].size() + pending_[1].size(); }
  // Forgets waiting items (e.g. after a reconnect) without counting them.
  void Clear() {
    pending_[0].clear();
    pending_[1].clear();
  }

 private:
  struct Entry {
    double time;
    T item;
  };
  double tolerance_;
  size_t max_pending_;
  std::deque<Entry> pending_[2];
  uint64_t unpaired_ = 0;
  uint64_t paired_ = 0;
};

}  // namespace sightline
