// The live simulated camera `sim://panel?seed=N&fps=F`: the simulator's panel scene of seed N
// rendered in real time by the mono camera in the hand of an arm that moves as it is told. Each
// frame is rendered from the newest pose on PoseBoard::Global()'s "arm" channel
// (base_from_end_effector, posted by the button pipeline for every arm_pose it receives) times
// the scene's true hand-eye, and stamped with that pose's time (the arm's clock); before any
// pose it shows the start pose of the simulated arm's plan (core/button/arm_simulator.h) at the
// wall-clock time. It lives here, not in core/sensors, because it needs core/sim and
// core/button (above core/sensors); OpenRunSource() opens it beside every sensor URI.
#pragma once

#include <chrono>
#include <memory>
#include <optional>
#include <string>

#include "core/button/arm_simulator.h"
#include "core/common/pose_board.h"
#include "core/options/option_set.h"
#include "core/sensors/live_source.h"
#include "core/sim/simulator.h"

namespace sightline {

// The query of a sim:// URI.
struct SimPanelUri {
  int seed = 4;
  double fps = 10;  // Frames rendered per second (at most; a slow host renders fewer).
};

// True for "sim://..." URIs.
bool IsSimUri(const std::string& uri);
// Parses "sim://panel", "sim://panel?seed=N", "sim://panel?seed=N&fps=F". InvalidArgument naming
// the URI and the bad part otherwise (another scene, an unknown key, a bad number).
StatusOr<SimPanelUri> ParseSimPanelUri(const std::string& uri);

class SimPanelSource : public LiveSource {
 public:
  explicit SimPanelSource(std::string uri, SimPanelUri parsed);
  ~SimPanelSource() override;

  // The PoseBoard channel it follows.
  static constexpr const char* kChannel = "arm";

 protected:
  Status Connect(SourceInfo* info) override;
  StatusOr<std::optional<CapturedFrame>> ReadFrame(std::chrono::milliseconds timeout) override;
  void Disconnect(bool device_lost) override;
  std::string DeviceLabel() const override;

 private:
  using Clock = std::chrono::steady_clock;

  const std::string uri_;
  const SimPanelUri parsed_;
  std::optional<sim::Simulator> simulator_;
  std::optional<ArmSimWorld> world_;
  Clock::time_point due_;
  int64_t rendered_ = 0;
  int64_t last_count_ = -1;  // PoseBoard count of the pose of the last frame.
  double last_stamp_s_ = 0;
};

// Opens what a pipeline run or the GUI reads frames from: sim:// URIs here, everything else
// through OpenSource() (core/sensors/driver_registry.h).
StatusOr<std::unique_ptr<Source>> OpenRunSource(const std::string& uri,
                                                const OptionSet& options = OptionSet());
// IsSensorUri() or IsSimUri(): a live source rather than a dataset folder.
bool IsLiveUri(const std::string& uri);

// The pixel (X,Y) of button `button`'s centre in the first frame of `uri` (the plan's start
// pose); InvalidArgument when there is no such button or it is not in view.
StatusOr<std::string> SimTapPixel(const std::string& uri, int button);

// A run on a sim:// URI: "button.run.tap=button:K" becomes button K's pixel at frame 0
// (SimTapPixel), and an empty mono.run.hand_eye the scene's true hand-eye, written to
// out_dir/sim_hand_eye.yaml. Nothing for other URIs or keys `options` does not declare.
Status PrepareSimRun(const std::string& uri, const std::string& out_dir, OptionSet* options);

}  // namespace sightline
