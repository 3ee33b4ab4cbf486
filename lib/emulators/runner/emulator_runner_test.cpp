#include "emulators/runner/emulator_runner.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <thread>

#include "links/open_link.hpp"

namespace playerkit::emulators {
namespace emulator_runner_test {

using namespace std::chrono_literals;

// A device that answers "?" with "!" + the baud it was asked at, and says
// "tick" every 100 ms once asked "go".
class ToyDevice final : public DeviceEmulator {
 public:
  void receive(std::span<const std::uint8_t> bytes, Duration now, int host_baud) override {
    for (std::uint8_t byte : bytes) {
      if (byte == '?') {
        const std::string answer = "!" + std::to_string(host_baud);
        out_.push_back({{answer.begin(), answer.end()}, false});
      } else if (byte == 'g') {
        ticking_ = true;
        next_tick_ = now;
      } else if (byte == 'w') {
        hold_until_released();
      }
    }
    ++receives;
    events += 'R';
    heard_at.push_back(now);
  }
  void advance(Duration now) override {
    while (ticking_ && next_tick_ <= now) {
      out_.push_back({{'t', 'i', 'c', 'k'}, true});
      next_tick_ += 100ms;
    }
  }
  Duration next_deadline() const override { return ticking_ ? next_tick_ : Duration::max(); }
  std::vector<Telegram> take_output() override { return std::exchange(out_, {}); }
  void host_disconnected(Duration) override {
    ++disconnects;
    events += 'D';
  }
  std::string describe() const override { return "toy"; }

  // "w" keeps the runner busy in receive() until release (bounded), so a test
  // can make the host act while the runner is not reading.
  void hold_until_released() {
    held = true;
    for (int i = 0; i < 500 && !released; ++i) std::this_thread::sleep_for(10ms);
    held = false;
  }

  int receives = 0;
  int disconnects = 0;
  std::string events;  // R: bytes received, D: host gone, in the order seen
  std::vector<Duration> heard_at;  // when each receive() came
  std::atomic<bool> held{false};
  std::atomic<bool> released{false};

 private:
  std::vector<Telegram> out_;
  bool ticking_ = false;
  Duration next_tick_{0};
};

std::string read_for(links::ByteLink& link, std::chrono::milliseconds how_long) {
  std::string got;
  const auto until = links::deadline_in(how_long);
  std::array<std::uint8_t, 256> buffer{};
  while (links::LinkClock::now() < until) {
    const std::size_t n = link.read_some(buffer, until);
    got.append(buffer.begin(), buffer.begin() + static_cast<std::ptrdiff_t>(n));
  }
  return got;
}

void send(links::ByteLink& link, std::string_view text) {
  link.write_all(std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()),
                 links::deadline_in(1s));
}

// Reads until `enough` says so or the deadline passes; what was read.
template <class Enough>
std::string read_until(links::ByteLink& link, Enough enough, std::chrono::milliseconds limit = 5s) {
  std::string got;
  const auto until = links::deadline_in(limit);
  std::array<std::uint8_t, 256> buffer{};
  while (!enough(got) && links::LinkClock::now() < until) {
    const std::size_t n = link.read_some(buffer, until);
    got.append(buffer.begin(), buffer.begin() + static_cast<std::ptrdiff_t>(n));
  }
  return got;
}

// Asks "?" every 50 ms until the device answers (deadline 5 s).
void ask_until_answered(links::ByteLink& link) {
  const auto until = links::deadline_in(5s);
  std::array<std::uint8_t, 64> buffer{};
  while (links::LinkClock::now() < until) {
    send(link, "?");
    if (link.read_some(buffer, std::min(until, links::deadline_in(50ms))) > 0) return;
  }
  ADD_FAILURE() << "no answer within 5 s";
}

Duration first_heard_after(EmulatorRunner& runner, Duration since) {
  return runner.with_emulator<ToyDevice>([since](ToyDevice& d) {
    for (const Duration at : d.heard_at) {
      if (at >= since) return at;
    }
    return Duration::max();
  });
}

TEST(EmulatorRunner, ADriverOnThePtyTalksToTheEmulatorAtItsBaudRate) {
  EmulatorRunner runner(std::make_unique<ToyDevice>(), PtyEndpoint{});
  auto link = links::open_link(runner.device_path(), {.baud = 38400});
  send(*link, "?");
  EXPECT_EQ(read_for(*link, 300ms), "!38400");
  ASSERT_TRUE(link->set_baud(9600));
  send(*link, "?");
  EXPECT_EQ(read_for(*link, 300ms), "!9600");
}

TEST(EmulatorRunner, PeriodicOutputArrivesOnTime) {
  EmulatorRunner runner(std::make_unique<ToyDevice>(), PtyEndpoint{});
  auto link = links::open_link(runner.device_path(), {});
  send(*link, "g");
  const std::string got = read_for(*link, 1050ms);
  // 10 or 11 ticks in a second at 10 Hz (bounded, not timed to the ms).
  const auto ticks = static_cast<int>(got.size() / 4);
  EXPECT_GE(ticks, 8);
  EXPECT_LE(ticks, 13);
}

TEST(EmulatorRunner, TheSymlinkNamesThePtyAndGoesAwayAfterwards) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("playerkit-runner-test-" + std::to_string(::getpid()));
  {
    EmulatorRunner runner(std::make_unique<ToyDevice>(), PtyEndpoint{path});
    EXPECT_EQ(runner.device_path(), path.string());
    auto link = links::open_link(path.string(), {});
    send(*link, "?");
    EXPECT_EQ(read_for(*link, 300ms).substr(0, 1), "!");
  }
  EXPECT_FALSE(std::filesystem::exists(std::filesystem::symlink_status(path)));
}

TEST(EmulatorRunner, AHostClosingThePortIsSeenAndMayComeBack) {
  EmulatorRunner runner(std::make_unique<ToyDevice>(), PtyEndpoint{});
  for (int session = 0; session < 2; ++session) {
    auto link = links::open_link(runner.device_path(), {});
    send(*link, "?");
    EXPECT_EQ(read_for(*link, 300ms).substr(0, 1), "!");
  }
  bool seen = false;
  for (int i = 0; i < 40 && !seen; ++i) {
    seen = runner.with_emulator<ToyDevice>([](ToyDevice& d) { return d.disconnects >= 2; });
    if (!seen) std::this_thread::sleep_for(50ms);
  }
  EXPECT_TRUE(seen);
  EXPECT_GE(runner.stats().host_connects, 2u);
}

TEST(EmulatorRunner, AHostThatReopensWhileTheRunnerIsBusyStartsAFreshSession) {
  // The close and the reopen reach the runner in one read, together with the
  // new session's first bytes: the device must hear the hang-up first, or it
  // resets after the new session has begun (a p2os robot then forgets SYNC0).
  auto device = std::make_unique<ToyDevice>();
  ToyDevice& toy = *device;
  EmulatorRunner runner(std::move(device), PtyEndpoint{});
  auto first = links::open_link(runner.device_path(), {});
  send(*first, "w");
  for (int i = 0; i < 200 && !toy.held; ++i) std::this_thread::sleep_for(10ms);
  ASSERT_TRUE(toy.held);
  first.reset();
  auto second = links::open_link(runner.device_path(), {});
  send(*second, "?");
  toy.released = true;
  EXPECT_EQ(read_for(*second, 300ms).substr(0, 1), "!");
  EXPECT_EQ(runner.with_emulator<ToyDevice>([](ToyDevice& d) { return d.events; }), "RDR");
  EXPECT_EQ(runner.stats().host_connects, 2u);
}

TEST(EmulatorRunner, WorksOnALoopbackTcpPortToo) {
  EmulatorRunner runner(std::make_unique<ToyDevice>(), TcpEndpoint{});
  ASSERT_EQ(runner.device_path().rfind("tcp:127.0.0.1:", 0), 0u) << runner.device_path();
  auto link = links::open_link(runner.device_path(), {});
  send(*link, "?");
  EXPECT_EQ(read_for(*link, 300ms), "!0");  // no line speed over TCP
}

TEST(EmulatorRunner, AVanishedLineCarriesNothingUntilItComesBack) {
  FaultPlan plan;
  add_fault(plan, "vanish=0:0.6");
  EmulatorRunner runner(std::make_unique<ToyDevice>(), PtyEndpoint{}, plan);
  auto link = links::open_link(runner.device_path(), {});
  send(*link, "?");
  EXPECT_EQ(read_for(*link, 300ms), "");  // lost: the cable is out
  std::this_thread::sleep_for(400ms);
  send(*link, "?");
  EXPECT_EQ(read_for(*link, 300ms), "!9600");  // back
}

TEST(EmulatorRunner, BadChecksumsReachTheHost) {
  FaultPlan plan;
  add_fault(plan, "bad-checksum=1");
  EmulatorRunner runner(std::make_unique<ToyDevice>(), PtyEndpoint{}, plan);
  auto link = links::open_link(runner.device_path(), {});
  send(*link, "g");
  const std::string got = read_for(*link, 350ms);
  ASSERT_GE(got.size(), 4u);
  EXPECT_EQ(got.substr(0, 3), "tic");
  EXPECT_NE(got[3], 'k');  // the "checksum" byte was flipped
  EXPECT_GE(runner.stats().faults.bad_checksums, 1u);
}

TEST(EmulatorRunner, ASilentStartHearsNothingBeforeItsTime) {
  FaultPlan plan;
  add_fault(plan, "silent-start=0.5");
  EmulatorRunner runner(std::make_unique<ToyDevice>(), PtyEndpoint{}, plan);
  auto link = links::open_link(runner.device_path(), {});
  ask_until_answered(*link);
  EXPECT_GE(first_heard_after(runner, Duration::zero()), Duration(500ms));
  // Once booted it stays up: a host that comes back is heard the first time.
  link.reset();
  link = links::open_link(runner.device_path(), {});
  send(*link, "?");
  EXPECT_EQ(read_until(*link, [](const std::string& s) { return !s.empty(); }).substr(0, 1), "!");
}

TEST(EmulatorRunner, ASlowStartBeginsAgainEveryTimeTheHostOpensTheLine) {
  FaultPlan plan;
  add_fault(plan, "slow-start=0.4");
  EmulatorRunner runner(std::make_unique<ToyDevice>(), PtyEndpoint{}, plan);
  for (int session = 0; session < 2; ++session) {
    const Duration before_open = runner.now();
    auto link = links::open_link(runner.device_path(), {});
    ask_until_answered(*link);
    EXPECT_GE(first_heard_after(runner, before_open), before_open + Duration(400ms)) << "session " << session;
  }
  EXPECT_GE(runner.stats().host_connects, 2u);
}

TEST(EmulatorRunner, GarbageArrivesBeforeTelegramsOnThePty) {
  FaultPlan plan;
  add_fault(plan, "garbage=1");
  EmulatorRunner runner(std::make_unique<ToyDevice>(), PtyEndpoint{}, plan);
  auto link = links::open_link(runner.device_path(), {});
  send(*link, "g");
  const std::string got = read_until(*link, [](const std::string& s) {
    return s.find("tick") != std::string::npos && s.find("tick") > 0;
  });
  ASSERT_NE(got.find("tick"), std::string::npos);
  EXPECT_GT(got.find("tick"), 0u) << "noise first";
  EXPECT_GE(runner.stats().faults.garbage_runs, 1u);
}

TEST(EmulatorRunner, TruncatedTelegramsNeverArriveWhole) {
  FaultPlan plan;
  add_fault(plan, "truncate=1");
  EmulatorRunner runner(std::make_unique<ToyDevice>(), PtyEndpoint{}, plan);
  auto link = links::open_link(runner.device_path(), {});
  send(*link, "g");
  const std::string got = read_until(*link, [](const std::string& s) { return s.size() >= 12; });
  ASSERT_GE(got.size(), 12u);
  EXPECT_EQ(got.find('k'), std::string::npos) << "every tick lost at least its last byte: " << got;
  EXPECT_GE(runner.stats().faults.truncated, 4u);
}

TEST(EmulatorRunner, DroppedBytesLeaveHolesInWhatArrives) {
  FaultPlan plan;
  add_fault(plan, "drop=0.5");
  EmulatorRunner runner(std::make_unique<ToyDevice>(), PtyEndpoint{}, plan);
  auto link = links::open_link(runner.device_path(), {});
  send(*link, "g");
  (void)read_until(*link, [](const std::string& s) { return s.size() >= 20; });
  runner.stop();  // the counts hold still from here
  const RunnerStats stats = runner.stats();
  EXPECT_GT(stats.faults.dropped_bytes, 0u);
  EXPECT_EQ(stats.bytes_out + stats.faults.dropped_bytes, 4 * stats.telegrams_out);
}

}  // namespace emulator_runner_test
}  // namespace playerkit::emulators
