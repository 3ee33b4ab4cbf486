// A passthrough device whose remote accepts the connection and then hangs
// (says nothing, sends only a banner, or sends garbage) must hold up only the
// client opening it: that client gets 'e' once the connect timeout expires,
// and every other client of the server keeps its full data rate meanwhile.
// (Setup used to run on the server's event loop: eight opens from one client
// took the others from 10 to 0.5 rounds a second.)

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "drivers/builtin.hpp"
#include "drivers/passthrough/passthrough_driver.hpp"
#include "protocol/banner.hpp"
#include "protocol/interfaces.hpp"
#include "support/raw_client.hpp"
#include "support/scratch_directory.hpp"
#include "test_server.hpp"

namespace playerkit::drivers {
namespace hanging_remote_test {

using namespace std::chrono_literals;
using playerkit::testing::RawClient;
using playerkit::testing::TestServer;
using protocol::DeviceAddress;
using protocol::MessageType;
using Clock = std::chrono::steady_clock;

enum class Behaviour { kSilent, kBannerOnly, kGarbage };

// A TCP listener on a free loopback port that accepts every connection and
// then behaves badly; connections stay open until it is destroyed.
class HangingRemote {
 public:
  explicit HangingRemote(Behaviour behaviour) : behaviour_(behaviour) {
    listener_ = ::socket(AF_INET, SOCK_STREAM, 0);
    if (listener_ < 0) throw std::runtime_error("socket() failed");
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    address.sin_port = 0;
    socklen_t length = sizeof(address);
    if (::bind(listener_, reinterpret_cast<sockaddr*>(&address), sizeof(address)) != 0 ||
        ::listen(listener_, 16) != 0 ||
        ::getsockname(listener_, reinterpret_cast<sockaddr*>(&address), &length) != 0) {
      ::close(listener_);
      throw std::runtime_error("cannot listen on loopback");
    }
    port_ = ntohs(address.sin_port);
    thread_ = std::thread([this] { accept_until_stopped(); });
  }
  ~HangingRemote() {
    stop_ = true;
    thread_.join();
    for (int fd : accepted_) ::close(fd);
    ::close(listener_);
  }
  HangingRemote(const HangingRemote&) = delete;
  HangingRemote& operator=(const HangingRemote&) = delete;

  [[nodiscard]] std::uint16_t port() const { return port_; }

 private:
  void accept_until_stopped() {
    while (!stop_) {
      pollfd waiting{listener_, POLLIN, 0};
      if (::poll(&waiting, 1, 20) <= 0) continue;
      const int fd = ::accept(listener_, nullptr, nullptr);
      if (fd < 0) continue;
      accepted_.push_back(fd);
      if (behaviour_ == Behaviour::kBannerOnly) {
        const auto banner = protocol::make_banner();
        (void)!::send(fd, banner.data(), banner.size(), MSG_NOSIGNAL);
      } else if (behaviour_ == Behaviour::kGarbage) {
        const std::vector<std::uint8_t> garbage(64, 0xa5);
        (void)!::send(fd, garbage.data(), garbage.size(), MSG_NOSIGNAL);
      }
    }
  }

  Behaviour behaviour_;
  int listener_ = -1;
  std::uint16_t port_ = 0;
  std::atomic<bool> stop_{false};
  std::vector<int> accepted_;  // the thread's until joined
  std::thread thread_;
};

constexpr std::uint16_t kWatcherHz = 50;
constexpr auto kBaselineWindow = 1500ms;
// The client opening a hanging remote waits the connect timeout; allow this
// much more on a busy machine.
constexpr auto kAnswerMargin = 1500ms;

constexpr DeviceAddress kWatched{protocol::kLaserCode, 0};
constexpr DeviceAddress kSilent{protocol::kLaserCode, 1};
constexpr DeviceAddress kBannerOnly{protocol::kLaserCode, 2};
constexpr DeviceAddress kGarbage{protocol::kLaserCode, 3};

std::string passthrough_to(int index, std::uint16_t port) {
  return "laser:" + std::to_string(index) + " ( driver \"passthrough\" host \"127.0.0.1\" port " +
         std::to_string(port) + " index 0 )\n";
}

// SYNCH messages (one per data round) read until `until` says stop or the
// limit passes.
template <typename Until>
int count_rounds(RawClient& client, Until until, std::chrono::milliseconds limit) {
  int rounds = 0;
  const auto deadline = Clock::now() + limit;
  while (!until() && Clock::now() < deadline) {
    const auto message = client.read_message(20ms);
    if (message && message->type() == MessageType::kSynch) ++rounds;
  }
  return rounds;
}

struct Open {
  DeviceAddress device;
  char granted = '?';
  Clock::duration took{};
};

// What a watcher of kWatched saw while another client made `opens` (one after
// the other, each closed again), against its rate with nobody else about.
struct Watched {
  double baseline_rate = 0;  // rounds a second alone
  int rounds_meanwhile = 0;
  double window_s = 0;       // how long the opens took
  std::string opener_error;  // empty when every open got an answer
};

Watched watch_while_opening(std::uint16_t port, std::vector<Open>& opens) {
  Watched watched;
  RawClient watcher(port);
  watcher.read_banner();
  if (watcher.open(kWatched, 'r') != 'r' || watcher.set_frequency(kWatcherHz) != MessageType::kAck) {
    watched.opener_error = "the watcher could not open its device";
    return watched;
  }
  const auto baseline_start = Clock::now();
  const int baseline_rounds = count_rounds(watcher, [] { return false; }, kBaselineWindow);
  watched.baseline_rate = baseline_rounds / std::chrono::duration<double>(Clock::now() - baseline_start).count();

  std::atomic<bool> opener_done{false};
  std::thread opener([&] {
    try {
      RawClient client(port);
      client.read_banner();
      for (Open& open : opens) {
        const auto start = Clock::now();
        open.granted = client.open(open.device, 'r');
        open.took = Clock::now() - start;
        client.open(open.device, 'c');
      }
    } catch (const std::exception& e) {
      watched.opener_error = e.what();
    }
    opener_done = true;
  });
  const auto window_start = Clock::now();
  watched.rounds_meanwhile = count_rounds(watcher, [&] { return opener_done.load(); }, 30s);
  watched.window_s = std::chrono::duration<double>(Clock::now() - window_start).count();
  opener.join();
  // In the XML report (--gtest_output=xml), for the record.
  ::testing::Test::RecordProperty("watcher_rounds_per_second_alone", std::to_string(watched.baseline_rate));
  ::testing::Test::RecordProperty("watcher_rounds_per_second_meanwhile",
                                  std::to_string(watched.rounds_meanwhile / watched.window_s));
  return watched;
}

// The watcher kept most of its rate: nobody else waited on the opens.
void expect_unhindered(const Watched& watched) {
  EXPECT_GT(watched.baseline_rate, 0.0);
  EXPECT_GE(watched.rounds_meanwhile, 0.7 * watched.baseline_rate * watched.window_s)
      << watched.rounds_meanwhile << " rounds in " << watched.window_s << " s; alone " << watched.baseline_rate
      << " per second";
}

TEST(PassthroughHangingRemote, OnlyTheClientOpeningItWaits) {
  HangingRemote silent(Behaviour::kSilent);
  HangingRemote banner_only(Behaviour::kBannerOnly);
  HangingRemote garbage(Behaviour::kGarbage);
  const std::string config = "laser:0 ( driver \"source\" )\n" + passthrough_to(1, silent.port()) +
                             passthrough_to(2, banner_only.port()) + passthrough_to(3, garbage.port());
  TestServer server(config, {}, 0, [](core::DriverRegistry& registry) { register_builtin_drivers(registry); });

  // Another client opens and closes the hanging remotes, one after the other.
  std::vector<Open> opens{{kSilent}, {kBannerOnly}, {kGarbage}, {kSilent}};
  const Watched watched = watch_while_opening(server.port(), opens);
  ASSERT_EQ(watched.opener_error, "");
  const auto answer_limit = PassthroughTimings{}.connect_timeout + kAnswerMargin;
  for (const Open& open : opens) {
    SCOPED_TRACE(protocol::to_string(open.device));
    EXPECT_EQ(open.granted, 'e');
    EXPECT_LE(open.took, answer_limit);
    // A silent remote is given up only when the timeout expires: the window
    // really had the opener waiting on it.
    if (open.device == kSilent) {
      EXPECT_GE(open.took, PassthroughTimings{}.connect_timeout * 9 / 10);
    }
  }
  expect_unhindered(watched);
  EXPECT_TRUE(server.logged("cannot use laser:0 on the remote server 127.0.0.1:" + std::to_string(silent.port())));
}

// A driver built on a hanging passthrough (here writelog recording it; amcl
// is the same) sets it up through the server too: the remote's setup runs off
// the event loop first, so again only the client opening the recorder waits.
TEST(PassthroughHangingRemote, ADriverBuiltOnItHoldsUpOnlyTheClientOpeningThatDriver) {
  HangingRemote silent(Behaviour::kSilent);
  playerkit::testing::ScratchDirectory scratch("hanging_remote_test");
  const std::string config = "laser:0 ( driver \"source\" )\n" + passthrough_to(1, silent.port()) +
                             "null:0 ( driver \"writelog\" filename \"" + scratch.file("run.log").string() +
                             "\" devices [\"laser:1\"] )\n";
  TestServer server(config, {}, 0, [](core::DriverRegistry& registry) { register_builtin_drivers(registry); });

  std::vector<Open> opens{{{protocol::kNullCode, 0}}};
  const Watched watched = watch_while_opening(server.port(), opens);
  ASSERT_EQ(watched.opener_error, "");
  // The recorder cannot record a device that never came up: 'e', once the
  // remote's connect timeout has expired.
  EXPECT_EQ(opens[0].granted, 'e');
  EXPECT_GE(opens[0].took, PassthroughTimings{}.connect_timeout * 9 / 10);
  EXPECT_LE(opens[0].took, PassthroughTimings{}.connect_timeout + kAnswerMargin);
  expect_unhindered(watched);
}

}  // namespace hanging_remote_test
}  // namespace playerkit::drivers
