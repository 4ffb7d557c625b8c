// A bounded, named queue between pipeline stages that can be shut down.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <mutex>
#include <optional>
#include <string>
#include <utility>

namespace sightline {

// What Push() does when the queue is full.
enum class QueuePolicy {
  kBlockWhenFull,  // Recorded playback: wait for space, nothing is lost, runs are reproducible.
  kDropOldest,     // Live sensors: discard the oldest item, latency stays bounded; drops counted.
};

// Thread-safe bounded FIFO with a shutdown that wakes every waiter.
//
//   BoundedQueue<std::shared_ptr<const RgbdFrame>> frames("frames", 4, QueuePolicy::kDropOldest);
//   // producer:                          // consumer:
//   frames.Push(frame);                    while (auto f = frames.Pop()) Process(**f);
//   ...
//   frames.Shutdown();                     // Pop() drains what is left, then returns nullopt.
template <typename T>
class BoundedQueue {
 public:
  BoundedQueue(std::string name, size_t capacity, QueuePolicy policy)
      : name_(std::move(name)), capacity_(capacity == 0 ? 1 : capacity), policy_(policy) {}
  BoundedQueue(const BoundedQueue&) = delete;
  BoundedQueue& operator=(const BoundedQueue&) = delete;

  // Adds an item. Returns false (item discarded) once the queue is shut down.
  bool Push(T item) {
    std::unique_lock<std::mutex> lock(mutex_);
    if (policy_ == QueuePolicy::kBlockWhenFull) {
      not_full_.wait(lock, [&] { return shutdown_ || items_.size() < capacity_; });
    }
    if (shutdown_) return false;
    if (items_.size() >= capacity_) {  // kDropOldest.
      items_.pop_front();
      ++dropped_;
    }
    items_.push_back(std::move(item));
    ++pushed_;
    lock.unlock();
    not_empty_.notify_one();
    return true;
  }

  // Waits for an item. Returns nullopt when the queue is shut down and empty.
  std::optional<T> Pop() {
    std::unique_lock<std::mutex> lock(mutex_);
    not_empty_.wait(lock, [&] { return shutdown_ || !items_.empty(); });
    return TakeFront(lock);
  }

  // Like Pop() but gives up after `timeout`.
  template <typename Rep, typename Period>
  std::optional<T> PopFor(std::chrono::duration<Rep, Period> timeout) {
    std::unique_lock<std::mutex> lock(mutex_);
    not_empty_.wait_for(lock, timeout, [&] { return shutdown_ || !items_.empty(); });
    return TakeFront(lock);
  }

  // Returns an item if one is ready, without waiting.
  std::optional<T> TryPop() {
    std::unique_lock<std::mutex> lock(mutex_);
    return TakeFront(lock);
  }

  // Refuses further pushes and wakes all waiters. Items already queued can still be popped.
  void Shutdown() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      shutdown_ = true;
    }
    not_empty_.notify_all();
    not_full_.notify_all();
  }

  // Discards queued items (e.g. on seek) without counting them as drops.
  void Clear() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      items_.clear();
    }
    not_full_.notify_all();
  }

  const std::string& name() const { return name_; }
  size_t capacity() const { return capacity_; }
  QueuePolicy policy() const { return policy_; }
  bool IsShutdown() const {
    std::lock_guard<std::mutex> l(mutex_);
    return shutdown_;
  }
  size_t size() const {
    std::lock_guard<std::mutex> l(mutex_);
    return items_.size();
  }
  uint64_t pushed() const {
    std::lock_guard<std::mutex> l(mutex_);
    return pushed_;
  }
  uint64_t popped() const {
    std::lock_guard<std::mutex> l(mutex_);
    return popped_;
  }
  // Items discarded by kDropOldest.
  uint64_t dropped() const {
    std::lock_guard<std::mutex> l(mutex_);
    return dropped_;
  }

 private:
  std::optional<T> TakeFront(std::unique_lock<std::mutex>& lock) {
    if (items_.empty()) return std::nullopt;
    std::optional<T> item(std::move(items_.front()));
    items_.pop_front();
    ++popped_;
    lock.unlock();
    not_full_.notify_one();
    return item;
  }

  const std::string name_;
  const size_t capacity_;
  const QueuePolicy policy_;
  mutable std::mutex mutex_;
  std::condition_variable not_empty_;
  std::condition_variable not_full_;
  std::deque<T> items_;
  bool shutdown_ = false;
  uint64_t pushed_ = 0, popped_ = 0, dropped_ = 0;
};

}  // namespace sightline
