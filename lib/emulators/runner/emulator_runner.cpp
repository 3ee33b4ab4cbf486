#include "emulators/runner/emulator_runner.hpp"

#include <algorithm>
#include <array>

#include "links/link_error.hpp"
#include "links/pseudo_terminal.hpp"
#include "links/tcp_link.hpp"
#include "links/tcp_listener.hpp"

namespace playerkit::emulators {

namespace {

using namespace std::chrono_literals;
using SteadyClock = std::chrono::steady_clock;

constexpr auto kPollSlice = 50ms;   // how soon stop() is noticed
constexpr auto kWriteBudget = 200ms;  // a host not reading for this long loses the telegram

}  // namespace

EmulatorRunner::EmulatorRunner(std::unique_ptr<DeviceEmulator> emulator, const Endpoint& endpoint,
                               FaultPlan faults)
    : emulator_(std::move(emulator)), faults_(faults) {
  if (const auto* pty = std::get_if<PtyEndpoint>(&endpoint)) {
    pty_ = std::make_unique<links::PseudoTerminal>(pty->symlink);
    device_path_ = pty_->path();
    thread_ = std::thread([this] { run_pty(); });
  } else {
    const auto& tcp = std::get<TcpEndpoint>(endpoint);
    listener_ = std::make_unique<links::TcpListener>(tcp.host, tcp.port);
    device_path_ = listener_->address();
    thread_ = std::thread([this] { run_tcp(); });
  }
}

EmulatorRunner::~EmulatorRunner() { stop(); }

void EmulatorRunner::stop() {
  stopping_ = true;
  if (thread_.joinable()) thread_.join();
}

Duration EmulatorRunner::now() const {
  return std::chrono::duration_cast<Duration>(SteadyClock::now() - started_);
}

RunnerStats EmulatorRunner::stats() const {
  std::lock_guard lock(mutex_);
  RunnerStats copy = stats_;
  copy.faults = faults_.counts();
  return copy;
}

SteadyClock::time_point EmulatorRunner::next_wake() const {
  const SteadyClock::time_point soonest = SteadyClock::now() + kPollSlice;
  std::lock_guard lock(mutex_);
  const Duration due = emulator_->next_deadline();
  if (due == Duration::max() || due - now() >= kPollSlice) return soonest;
  return started_ + std::chrono::duration_cast<SteadyClock::duration>(due);
}

std::vector<std::vector<std::uint8_t>> EmulatorRunner::exchange(std::span<const std::uint8_t> received,
                                                                int host_baud) {
  std::lock_guard lock(mutex_);
  const Duration at = now();
  const bool dead = faults_.plan().line_dead(at, host_opened_at_);
  stats_.bytes_in += received.size();
  if (!received.empty() && !dead) emulator_->receive(received, at, host_baud);
  emulator_->advance(at);
  std::vector<std::vector<std::uint8_t>> chunks;
  for (const Telegram& telegram : emulator_->take_output()) {
    if (dead) {
      faults_.drop();
      continue;
    }
    ++stats_.telegrams_out;
    for (auto& chunk : faults_.apply(telegram)) chunks.push_back(std::move(chunk));
  }
  return chunks;
}

void EmulatorRunner::host_came() {
  std::lock_guard lock(mutex_);
  ++stats_.host_connects;
  host_opened_at_ = now();
}

void EmulatorRunner::host_left() {
  std::lock_guard lock(mutex_);
  ++stats_.host_disconnects;
  emulator_->host_disconnected(now());
}

void EmulatorRunner::run_pty() {
  std::array<std::uint8_t, 4096> buffer{};
  while (!stopping_) {
    links::PseudoTerminal::Received got;
    try {
      got = pty_->read_some(buffer, next_wake());
    } catch (const links::LinkError&) {
      // The master itself failing is not something a device sees; try again.
      std::this_thread::sleep_for(kPollSlice);
      continue;
    }
    // A host that closed and opened again between two reads: the device
    // must forget the old session before it hears the new one's first bytes.
    if (got.host_reopened) host_left();
    if (got.host_opened) host_came();
    const auto chunks = exchange(std::span(buffer.data(), got.count), pty_->slave_baud());
    for (const auto& chunk : chunks) {
      if (pty_->write_all(chunk, SteadyClock::now() + kWriteBudget)) {
        std::lock_guard lock(mutex_);
        stats_.bytes_out += chunk.size();
      }
    }
    if (got.host_closed && !got.host_reopened) host_left();
  }
}

void EmulatorRunner::run_tcp() {
  std::array<std::uint8_t, 4096> buffer{};
  std::unique_ptr<links::TcpLink> host;
  while (!stopping_) {
    if (!host) {
      host = listener_->accept(next_wake());
      if (host) {
        host_came();
      } else {
        (void)exchange({}, 0);  // nobody on the line: what the device sends is lost
      }
      continue;
    }
    std::size_t count = 0;
    try {
      count = host->read_some(buffer, next_wake());
      for (const auto& chunk : exchange(std::span(buffer.data(), count), 0)) {
        host->write_all(chunk, SteadyClock::now() + kWriteBudget);
        std::lock_guard lock(mutex_);
        stats_.bytes_out += chunk.size();
      }
    } catch (const links::LinkError&) {
      host.reset();
      host_left();
    }
  }
}

}  // namespace playerkit::emulators
