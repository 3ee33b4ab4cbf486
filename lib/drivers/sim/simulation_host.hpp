#pragma once
// One simulated world served as devices: the sim::World, the thread that
// steps it, and the simulation clock. Every simulated device of a world finds
// the same host in the device table's core::ConnectionPool, keyed by the
// world, and holds a SharedConnection::Use while it is set up.
//
// The world runs from start() (the devices' prepare(), before the server
// accepts clients) whether or not anyone is subscribed, as Stage did: its
// clock is the server's clock (core::ServerClock, claimed by every simulated
// device), starting at 0 when the world was loaded.
//
// Pacing: step k is due at origin + k·step/speedup of steady-clock time, an
// absolute deadline, so sleeping late once does not slow the simulation
// down; speedup 0 steps as fast as it can. When the thread falls more than
// kMaxLag behind (a loaded machine, a huge world), the origin moves up to now
// instead of catching up in a burst (counted: late_restarts()). pause(),
// step() and a run limit (simulation seconds, after which stepping stops as
// if paused) control it; a paused world publishes nothing new.

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <stop_token>
#include <string>
#include <thread>
#include <vector>

#include "core/clock.hpp"
#include "core/logger.hpp"
#include "core/shared_connection.hpp"
#include "drivers/sim/simulation_picture.hpp"
#include "sim/world/world.hpp"

namespace playerkit::drivers::sim {

struct SimulationSettings {
  double speedup = 1.0;             // × real time; 0: as fast as possible
  std::optional<double> run_limit;  // simulation seconds; stepping stops there
  bool start_paused = false;
  // The world starts from prepare() only, not from the first device set up.
  // The daemon sets up its always-on devices before prepare(), so a recorder
  // among them listens from the first step on.
  bool start_from_prepare_only = false;
  // A PNG of the world (trails fed every step), written by write_picture()
  // and when the host stops.
  std::optional<PictureSettings> picture{};
};

// Simulation seconds as a header time (whole microseconds).
[[nodiscard]] protocol::Timestamp simulation_timestamp(double seconds);

// Told of every step as it happens: on the stepping thread (or step()'s
// caller), with the world locked and the clock already at the step's time.
// Must not call back into the host.
class StepObserver {
 public:
  virtual void stepped(playerkit::sim::World& world) = 0;

 protected:
  ~StepObserver() = default;
};

class SimulationHost final : public core::SharedConnection {
 public:
  // Behind by more than this much real time, pacing starts over from now.
  static constexpr std::chrono::milliseconds kMaxLag{500};

  // `name` names the world in log lines (its file). Throws
  // std::invalid_argument for a negative or non-finite speedup or run limit.
  SimulationHost(playerkit::sim::World world, std::string name, SimulationSettings settings, core::Logger& logger);
  ~SimulationHost() override;

  // Starts the stepping thread; later calls do nothing.
  void start();
  // Stops it (the world keeps its state), then writes the picture if one
  // was asked for (the first stop after start() only). Also done by the
  // destructor.
  void stop();

  // Writes the picture now: true when written, false (logged) when no
  // picture was asked for or it could not be written. The world is locked
  // only while what is drawn is copied out.
  bool write_picture();

  // `f(world)` with the world locked: every read and change of the world
  // goes through here (from the event loop, requests, tests).
  template <class F>
  decltype(auto) with_world(F&& f) {
    std::lock_guard lock(world_mutex_);
    return f(world_);
  }

  // Subscriptions, counted per model: the world sees the first and the last
  // (sim::World::set_active), so two devices on one model do not stop each
  // other. activate() returns the simulation time it happened at.
  double activate(playerkit::sim::ModelId model);
  void deactivate(playerkit::sim::ModelId model);

  // From the next step on, `observer` hears of every step until it stops
  // observing (which waits for a step under way).
  void observe_steps(StepObserver* observer);
  void stop_observing_steps(StepObserver* observer);

  void pause();
  void resume();
  // One step now, then paused (also past the run limit).
  void step();
  [[nodiscard]] bool paused() const;
  [[nodiscard]] bool run_limit_reached() const;

  // Simulation seconds (updated after every step).
  [[nodiscard]] double time() const;
  // The simulation clock, for core::ServerClock::claim.
  [[nodiscard]] std::shared_ptr<const core::Clock> clock() const { return clock_; }
  [[nodiscard]] const std::string& name() const { return name_; }
  [[nodiscard]] const SimulationSettings& settings() const { return settings_; }
  // Times pacing fell more than kMaxLag behind and started over.
  [[nodiscard]] std::uint64_t late_restarts() const { return late_restarts_.load(); }

 protected:
  // The world runs from start() on, subscribed or not: the first device set
  // up starts it when nobody called start() (tests, tools without prepare),
  // unless the settings leave that to prepare().
  void open() override {
    if (!settings_.start_from_prepare_only) start();
  }
  void close() noexcept override {}

 private:
  void run(const std::stop_token& stop);
  // One world step with the world locked; the clock follows. True when the
  // run limit is reached by it.
  // One step; from the stepping thread (`by_hand` false) none while held_.
  // True when the run limit is reached.
  bool step_world(bool by_hand);
  [[nodiscard]] bool may_run() const;  // control_mutex_ held

  playerkit::sim::World world_;
  const std::string name_;
  const SimulationSettings settings_;
  core::Logger& logger_;
  const double step_seconds_;
  std::shared_ptr<core::ManualClock> clock_;
  std::atomic<double> time_{0.0};
  std::atomic<std::uint64_t> late_restarts_{0};
  // record() and snapshot() under world_mutex_; its write() is its own.
  std::unique_ptr<SimulationPicture> picture_;

  std::mutex world_mutex_;  // the world and active_
  std::map<playerkit::sim::ModelId, int> active_;
  std::vector<StepObserver*> step_observers_;  // under world_mutex_

  // Paused: the stepping thread takes no further step. Set with paused_,
  // read in step_world() under world_mutex_.
  std::atomic<bool> held_{false};

  mutable std::mutex control_mutex_;  // everything below
  std::condition_variable_any wakeup_;
  bool paused_ = false;
  bool limit_reached_ = false;
  bool started_ = false;
  bool final_picture_due_ = false;  // started with a picture, not yet stopped
  std::jthread thread_;  // last: stops before the rest goes
};

}  // namespace playerkit::drivers::sim
