#include "core/common/bounded_queue.h"

#include <gtest/gtest.h>

#include <thread>

namespace sightline {
namespace {

TEST(BoundedQueue, BlockingPolicyLosesNothingUnderTwoThreads) {
  BoundedQueue<int> queue("frames", 3, QueuePolicy::kBlockWhenFull);
  constexpr int kCount = 20000;
  std::thread producer([&] {
    for (int i = 0; i < kCount; ++i) ASSERT_TRUE(queue.Push(i));
    queue.Shutdown();
  });
  std::vector<int> received;
  while (auto item = queue.Pop()) received.push_back(*item);
  producer.join();
  ASSERT_EQ(received.size(), static_cast<size_t>(kCount));
  for (int i = 0; i < kCount; ++i) ASSERT_EQ(received[i], i);  // Order kept.
  EXPECT_EQ(queue.dropped(), 0u);
}

TEST(BoundedQueue, DropOldestCountsEveryDrop) {
  BoundedQueue<int> queue("live", 4, QueuePolicy::kDropOldest);
  constexpr int kCount = 20000;
  std::atomic<bool> done{false};
  std::vector<int> received;
  std::thread consumer([&] {
    while (auto item = queue.Pop()) {
      received.push_back(*item);
      if (received.size() % 64 == 0) std::this_thread::sleep_for(std::chrono::microseconds(50));
    }
  });
  for (int i = 0; i < kCount; ++i) ASSERT_TRUE(queue.Push(i));
  queue.Shutdown();
  consumer.join();
  // Everything pushed was either received or counted as dropped, never both, never lost.
  EXPECT_EQ(received.size() + queue.dropped(), static_cast<size_t>(kCount));
  EXPECT_EQ(queue.pushed(), static_cast<uint64_t>(kCount));
  for (size_t i = 1; i < received.size(); ++i) ASSERT_LT(received[i - 1], received[i]);
  EXPECT_EQ(received.back(), kCount - 1);  // The newest item always survives.
}

TEST(BoundedQueue, DropOldestKeepsNewestWhenNobodyReads) {
  BoundedQueue<int> queue("live", 2, QueuePolicy::kDropOldest);
  for (int i = 0; i < 5; ++i) queue.Push(i);
  EXPECT_EQ(queue.dropped(), 3u);
  EXPECT_EQ(*queue.TryPop(), 3);
  EXPECT_EQ(*queue.TryPop(), 4);
  EXPECT_FALSE(queue.TryPop().has_value());
}

TEST(BoundedQueue, ShutdownWakesBlockedProducerAndConsumer) {
  BoundedQueue<int> full("full", 1, QueuePolicy::kBlockWhenFull);
  full.Push(1);
  std::thread producer([&] { EXPECT_FALSE(full.Push(2)); });
  BoundedQueue<int> empty("empty", 1, QueuePolicy::kBlockWhenFull);
  std::thread consumer([&] { EXPECT_FALSE(empty.Pop().has_value()); });
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  full.Shutdown();
  empty.Shutdown();
  producer.join();
  consumer.join();
  EXPECT_EQ(*full.Pop(), 1);  // Queued items survive shutdown.
  EXPECT_FALSE(full.Pop().has_value());
}

}  // namespace
}  // namespace sightline
