#include "core/pipeline/player.h"

#include <gtest/gtest.h>

#include <future>
#include <thread>

#include "core/io/dataset.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

// A recording of n small mono frames at 100 Hz held in memory.
class MemorySource : public Source {
 public:
  explicit MemorySource(int n) : n_(n) {}
  Status Open() override {
    info_.format = "memory";
    info_.kind = SourceKind::kMono;
    info_.frame_count = n_;
    info_.seekable = true;
    info_.rate_hz = 100;
    return Status::Ok();
  }
  const SourceInfo& info() const override { return info_; }
  Status Grab() override {
    if (next_ >= n_) return OutOfRange("end");
    grabbed_ = next_++;
    return Status::Ok();
  }
  StatusOr<Frame> Retrieve() override {
    MonoFrame f;
    f.stamp.sequence_id = grabbed_;
    f.stamp.sensor_time_s = grabbed_ * 0.01;
    f.image = cv::Mat(2, 2, CV_8UC1, cv::Scalar(grabbed_));
    return Frame(f);
  }
  int64_t Position() const override { return next_; }
  Status Seek(int64_t index) override {
    if (index < 0 || index >= n_) return OutOfRange("seek " + std::to_string(index));
    next_ = index;
    return Status::Ok();
  }

 private:
  int n_;
  int64_t next_ = 0, grabbed_ = -1;
  SourceInfo info_;
};

std::unique_ptr<Player> MakePlayer(int n) {
  auto source = std::make_unique<MemorySource>(n);
  EXPECT_TRUE(source->Open().ok());
  return std::make_unique<Player>(std::move(source));
}

int64_t IdOf(const StatusOr<Frame>& f) { return StampOf(*f).sequence_id; }

TEST(Player, PlaysEveryFrameInOrderAsFastAsPossible) {
  auto player = MakePlayer(5);
  player->SetSpeed(0);
  player->Play();
  for (int i = 0; i < 5; ++i) {
    StatusOr<Frame> f = player->Next();
    ASSERT_TRUE(f.ok());
    EXPECT_EQ(IdOf(f), i);
  }
  EXPECT_EQ(player->Next().status().code(), StatusCode::kOutOfRange);
  EXPECT_FALSE(player->playing());
}

TEST(Player, StepDeliversExactlyOneFrameThenWaits) {
  auto player = MakePlayer(5);
  player->Step();
  EXPECT_EQ(IdOf(player->Next()), 0);
  auto pending = std::async(std::launch::async, [&] { return player->Next(); });
  EXPECT_EQ(pending.wait_for(std::chrono::milliseconds(50)), std::future_status::timeout);
  player->Step();
  EXPECT_EQ(IdOf(pending.get()), 1);
}

TEST(Player, SeekWhilePausedDeliversThatFrame) {
  auto player = MakePlayer(10);
  player->Seek(7);
  EXPECT_EQ(player->position(), 7);
  EXPECT_EQ(IdOf(player->Next()), 7);
  EXPECT_EQ(player->position(), 8);
}

TEST(Player, LoopsBackToTheStart) {
  auto player = MakePlayer(3);
  player->SetSpeed(0);
  player->SetLoop(true);
  player->Play();
  std::vector<int64_t> ids;
  for (int i = 0; i < 7; ++i) ids.push_back(IdOf(player->Next()));
  EXPECT_EQ(ids, (std::vector<int64_t>{0, 1, 2, 0, 1, 2, 0}));
}

TEST(Player, StopWakesAWaitingReader) {
  auto player = MakePlayer(3);
  auto pending = std::async(std::launch::async, [&] { return player->Next(); });
  player->Stop();
  EXPECT_EQ(pending.get().status().code(), StatusCode::kCancelled);
}

TEST(Player, PlaysRealTumRecording) {
  SIGHTLINE_REQUIRE_DATA(dir, "tum_fr1_desk");
  StatusOr<std::unique_ptr<Source>> source = OpenDataset(dir);
  ASSERT_TRUE(source.ok()) << source.status().ToString();
  Player player(std::move(*source));
  player.SetSpeed(0);
  player.Play();
  int frames = 0;
  while (true) {
    StatusOr<Frame> f = player.Next();
    if (!f.ok()) {
      EXPECT_EQ(f.status().code(), StatusCode::kOutOfRange);
      break;
    }
    ASSERT_TRUE(std::holds_alternative<RgbdFrame>(*f));
    ++frames;
  }
  EXPECT_EQ(frames, 9);
}

}  // namespace
}  // namespace sightline
