#include "drivers/sim/simulation_host.hpp"

#include <cmath>
#include <exception>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace playerkit::drivers::sim {

namespace {

void check_setting(double value, const char* what) {
  if (!std::isfinite(value) || value < 0.0) {
    throw std::invalid_argument(std::string(what) + " must be 0 or more, not " + std::to_string(value));
  }
}

// Compared against the world's time, a sum of whole steps: a limit written as
// 2.0 is reached by step 20 of 0.1 s even though 20 × 0.1 is 2.0000000000000004.
constexpr double kTimeTolerance = 1e-9;

}  // namespace

protocol::Timestamp simulation_timestamp(double seconds) {
  if (!(seconds > 0.0)) return {};
  return core::from_microseconds(static_cast<std::uint64_t>(std::llround(seconds * 1e6)));
}

SimulationHost::SimulationHost(playerkit::sim::World world, std::string name, SimulationSettings settings,
                               core::Logger& logger)
    : world_(std::move(world)),
      name_(std::move(name)),
      settings_(settings),
      logger_(logger),
      step_seconds_(world_.settings().step),
      clock_(std::make_shared<core::ManualClock>()) {
  check_setting(settings_.speedup, "the speedup");
  if (settings_.run_limit) check_setting(*settings_.run_limit, "the run limit");
  time_.store(world_.time());
  clock_->set(simulation_timestamp(world_.time()));
  paused_ = settings_.start_paused;
  held_.store(settings_.start_paused);
  limit_reached_ = settings_.run_limit && world_.time() + kTimeTolerance >= *settings_.run_limit;
  if (settings_.picture) {
    picture_ = std::make_unique<SimulationPicture>(*settings_.picture);
    picture_->record(world_);
  }
}

SimulationHost::~SimulationHost() { stop(); }

void SimulationHost::start() {
  std::lock_guard lock(control_mutex_);
  if (started_) return;
  started_ = true;
  final_picture_due_ = picture_ != nullptr;
  thread_ = std::jthread([this](const std::stop_token& stop) { run(stop); });
}

void SimulationHost::stop() {
  thread_.request_stop();
  if (thread_.joinable() && thread_.get_id() != std::this_thread::get_id()) thread_.join();
  bool write_final = false;
  {
    std::lock_guard lock(control_mutex_);
    std::swap(write_final, final_picture_due_);
  }
  if (write_final) write_picture();
}

bool SimulationHost::write_picture() {
  if (!picture_) {
    logger_.warning(name_ + ": no picture to write (player-serve --picture FILE.png asks for one)");
    return false;
  }
  const auto snapshot = with_world([this](const playerkit::sim::World& world) { return picture_->snapshot(world); });
  const std::string file = picture_->settings().file.string();
  try {
    picture_->write(snapshot);
  } catch (const std::exception& e) {  // never out of stop(), which the destructor calls
    logger_.error(name_ + ": picture not written: " + e.what());
    return false;
  }
  std::ostringstream message;
  message << name_ << ": wrote the picture " << file << " (t = " << snapshot.time << " s)";
  logger_.info(message.str());
  return true;
}

double SimulationHost::activate(playerkit::sim::ModelId model) {
  std::lock_guard lock(world_mutex_);
  if (active_[model]++ == 0) world_.set_active(model, true);
  return world_.time();
}

void SimulationHost::observe_steps(StepObserver* observer) {
  std::lock_guard lock(world_mutex_);
  step_observers_.push_back(observer);
}

void SimulationHost::stop_observing_steps(StepObserver* observer) {
  std::lock_guard lock(world_mutex_);
  std::erase(step_observers_, observer);
}

void SimulationHost::deactivate(playerkit::sim::ModelId model) {
  std::lock_guard lock(world_mutex_);
  auto found = active_.find(model);
  if (found == active_.end()) return;
  if (--found->second == 0) {
    active_.erase(found);
    world_.set_active(model, false);
  }
}

void SimulationHost::pause() {
  std::lock_guard lock(control_mutex_);
  paused_ = true;
  held_.store(true);
  wakeup_.notify_all();
}

void SimulationHost::resume() {
  std::lock_guard lock(control_mutex_);
  paused_ = false;
  held_.store(false);
  wakeup_.notify_all();
}

void SimulationHost::step() {
  {
    std::lock_guard lock(control_mutex_);
    paused_ = true;
    held_.store(true);
    wakeup_.notify_all();
  }
  // The stepping thread may be inside a step: the world lock orders the two.
  if (step_world(true)) {
    std::lock_guard lock(control_mutex_);
    limit_reached_ = true;
  }
}

bool SimulationHost::paused() const {
  std::lock_guard lock(control_mutex_);
  return paused_;
}

bool SimulationHost::run_limit_reached() const {
  std::lock_guard lock(control_mutex_);
  return limit_reached_;
}

double SimulationHost::time() const { return time_.load(); }

bool SimulationHost::may_run() const { return !paused_ && !limit_reached_; }

bool SimulationHost::step_world(bool by_hand) {
  std::lock_guard lock(world_mutex_);
  // The stepping thread saw the world running, then let go of control_mutex_
  // for the step: a pause() since then holds it here, so that once pause()
  // has returned and a step under way has ended, the world stands still.
  if (!by_hand && held_.load()) return false;
  world_.step();
  if (picture_) picture_->record(world_);
  const double now = world_.time();
  time_.store(now);
  clock_->set(simulation_timestamp(now));
  for (StepObserver* observer : step_observers_) observer->stepped(world_);
  return settings_.run_limit && now + kTimeTolerance >= *settings_.run_limit;
}

void SimulationHost::run(const std::stop_token& stop) {
  using Clock = std::chrono::steady_clock;
  const auto step_real = std::chrono::duration_cast<Clock::duration>(
      std::chrono::duration<double>(settings_.speedup > 0.0 ? step_seconds_ / settings_.speedup : 0.0));
  std::unique_lock lock(control_mutex_);
  // Pacing: step `done + 1` is due at origin + (done + 1) · step_real.
  Clock::time_point origin = Clock::now();
  std::uint64_t done = 0;
  bool was_running = false;
  while (!stop.stop_requested()) {
    if (!may_run()) {
      was_running = false;
      wakeup_.wait(lock, stop, [this] { return may_run(); });
      continue;
    }
    if (!was_running) {  // (re)started: pace from now
      origin = Clock::now();
      done = 0;
      was_running = true;
    }
    if (settings_.speedup > 0.0) {
      const auto due = origin + step_real * static_cast<Clock::rep>(done + 1);
      const auto now = Clock::now();
      if (now > due + kMaxLag) {
        late_restarts_.fetch_add(1);
        origin = now - step_real;
        done = 0;
      } else if (now < due) {
        // Woken early by pause() or stop(): look again.
        if (wakeup_.wait_until(lock, stop, due, [this] { return !may_run(); })) continue;
        if (stop.stop_requested()) break;
      }
    }
    lock.unlock();
    const bool limit = step_world(false);
    if (settings_.speedup == 0.0) std::this_thread::yield();  // let the event loop at the world
    lock.lock();
    ++done;
    if (limit && !limit_reached_) {
      limit_reached_ = true;
      logger_.info(name_ + ": the simulation stops at " + std::to_string(time_.load()) +
                   " s, its run limit; devices keep serving that moment");
    }
  }
}

}  // namespace playerkit::drivers::sim
