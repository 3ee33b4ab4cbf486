#include "links/exchange.hpp"

#include <gtest/gtest.h>
#include <poll.h>

#include <atomic>
#include <memory>
#include <mutex>
#include <stop_token>
#include <thread>

#include "links/fd_io.hpp"
#include "links/link_error.hpp"
#include "links/links_test_support.hpp"
#include "links/serial_link.hpp"

namespace playerkit::links {
namespace exchange_test {

using namespace test_support;

// A toy protocol: AA, N, N payload bytes, XOR of the payload. A request's
// payload is its id; a reply's is the id it answers and a status (0: yes).
constexpr std::size_t kRequestSize = 4;
constexpr std::uint8_t kYes = 0x00;
constexpr std::uint8_t kNo = 0xFF;

Bytes telegram(const Bytes& payload) {
  Bytes bytes{0xAA, static_cast<std::uint8_t>(payload.size())};
  std::uint8_t check = 0;
  for (const std::uint8_t byte : payload) {
    bytes.push_back(byte);
    check ^= byte;
  }
  bytes.push_back(check);
  return bytes;
}

Bytes reply(std::uint8_t id, std::uint8_t status = kYes) { return telegram({id, status}); }

class ToyFormat final : public framing::FrameFormat {
 public:
  [[nodiscard]] std::string_view name() const override { return "toy"; }
  [[nodiscard]] framing::FrameScan scan(std::span<const std::uint8_t> buffered) const override {
    if (buffered[0] != 0xAA) return framing::FrameScan::noise(1);
    if (buffered.size() < 2) return framing::FrameScan::need(2);
    const std::size_t size = std::size_t{buffered[1]} + 3;
    if (buffered.size() < size) return framing::FrameScan::need(size);
    std::uint8_t check = 0;
    for (std::size_t i = 2; i + 1 < size; ++i) check ^= buffered[i];
    return check == buffered[size - 1] ? framing::FrameScan::whole(size) : framing::FrameScan::corrupt(size);
  }
};

ExchangeRequest request(std::uint8_t id, LinkClock::duration timeout = kPatience, int attempts = 1) {
  return {.name = "toy request " + std::to_string(id),
          .bytes = telegram({id}),
          .matcher =
              [id](std::span<const std::uint8_t> t) {
                if (t.size() < 5 || t[2] != id) return ReplyMatch::not_mine;
                return t[3] == kYes ? ReplyMatch::mine : ReplyMatch::refusal;
              },
          .timeout = timeout,
          .attempts = attempts};
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// What the device does on receiving a request: the bytes to send back,
// and whether to vanish (close the pty) instead.
struct Answer {
  Bytes bytes;
  bool hang_up = false;
};
using Script = std::function<Answer(std::uint8_t id)>;

// The device end of a pty, on its own thread: cuts the host's writes into
// requests and answers each as the script says.
class ScriptedPeer {
 public:
  ScriptedPeer(std::unique_ptr<PseudoTerminal>& pty, Script script)
      : pty_(pty), script_(std::move(script)), thread_([this](const std::stop_token& stop) { run(stop); }) {}

 private:
  void run(const std::stop_token& stop) {
    Bytes pending;
    std::array<std::uint8_t, 64> buffer{};
    while (!stop.stop_requested()) {
      const auto got = pty_->read_some(buffer, deadline_in(50ms));
      pending.insert(pending.end(), buffer.begin(), buffer.begin() + static_cast<std::ptrdiff_t>(got.count));
      while (pending.size() >= kRequestSize) {
        const Answer answer = script_(pending[2]);
        pending.erase(pending.begin(), pending.begin() + kRequestSize);
        if (answer.hang_up) {
          pty_.reset();
          return;
        }
        if (!answer.bytes.empty()) pty_->write_all(answer.bytes, deadline_in(kPatience));
      }
    }
  }

  std::unique_ptr<PseudoTerminal>& pty_;
  Script script_;
  std::jthread thread_;  // last: started once the rest is ready
};

// A host link on a pty, a reader and an exchanger, and a peer playing the
// device. The exchanger stops once `stop` (when given) is set.
struct Line {
  explicit Line(Script script, const std::atomic<bool>* stop = nullptr)
      : pty(std::make_unique<PseudoTerminal>()),
        link(SerialLink::open(pty->path(), {.baud = 38400})),
        reader(*link, format, 64),
        exchanger(reader, [stop] { return stop != nullptr && stop->load(); }, "the toy"),
        peer(pty, std::move(script)) {}

  [[nodiscard]] LinkCounterSnapshot counters() const { return link->counters().snapshot(); }

  std::unique_ptr<PseudoTerminal> pty;
  std::unique_ptr<SerialLink> link;
  ToyFormat format;
  FramedReader reader;
  Exchanger exchanger;
  ScriptedPeer peer;
};

TEST(Exchanger, AReplyOnTheFirstTry) {
  Line line([](std::uint8_t id) { return Answer{reply(id)}; });
  const ExchangeOutcome outcome = line.exchanger.try_exchange(request(1));
  ASSERT_TRUE(outcome.replied()) << outcome.message;
  EXPECT_EQ(outcome.telegram, reply(1));
  EXPECT_EQ(line.counters().timeouts, 0u);
  EXPECT_EQ(line.counters().retries, 0u);
  EXPECT_NE(line.exchanger.last_arrival(), LinkClock::time_point{});
}

TEST(Exchanger, GarbageBeforeTheReplyIsSkippedAsOneResync) {
  Line line([](std::uint8_t id) {
    Bytes bytes{0x13, 0x37, 0x00, 0x42};
    const Bytes answer = reply(id);
    bytes.insert(bytes.end(), answer.begin(), answer.end());
    return Answer{bytes};
  });
  EXPECT_EQ(line.exchanger.exchange(request(2)), reply(2));
  EXPECT_EQ(line.counters().resyncs, 1u);
  EXPECT_EQ(line.counters().bytes_dropped, 4u);
}

TEST(Exchanger, ALateReplyToAnEarlierRequestIsSkipped) {
  Line line([](std::uint8_t id) {
    Bytes bytes = reply(static_cast<std::uint8_t>(id - 1));  // what the device still owed
    const Bytes answer = reply(id);
    bytes.insert(bytes.end(), answer.begin(), answer.end());
    return Answer{bytes};
  });
  EXPECT_EQ(line.exchanger.exchange(request(7)), reply(7));
  EXPECT_EQ(line.counters().telegrams, 2u);
}

TEST(Exchanger, SilenceUsesEveryAttemptThenFailsNamingTheRequest) {
  Line line([](std::uint8_t) { return Answer{}; });
  const ExchangeOutcome outcome = line.exchanger.try_exchange(request(3, 60ms, 3));
  ASSERT_EQ(outcome.failure, ExchangeFailure::no_reply);
  EXPECT_EQ(outcome.message, "no reply from the toy to toy request 3 in 3 tries of 60 ms");
  EXPECT_EQ(line.counters().bytes_out, 3 * kRequestSize);
  EXPECT_EQ(line.counters().timeouts, 3u);
  EXPECT_EQ(line.counters().retries, 2u);
}

TEST(Exchanger, ASecondAttemptGetsTheReplyTheFirstLost) {
  std::atomic<int> heard{0};
  Line line([&](std::uint8_t id) { return ++heard == 1 ? Answer{} : Answer{reply(id)}; });
  // The first wait is never answered; the second only needs to be long enough.
  EXPECT_EQ(line.exchanger.exchange(request(4, 1s, 2)), reply(4));
  EXPECT_EQ(line.counters().timeouts, 1u);
  EXPECT_EQ(line.counters().retries, 1u);
}

TEST(Exchanger, ARefusalIsAnAnswerNotARetry) {
  Line line([](std::uint8_t id) { return Answer{reply(id, kNo)}; });
  try {
    line.exchanger.exchange(request(5, kPatience, 3));
    FAIL() << "a refusal was taken for the reply";
  } catch (const ExchangeError& error) {
    EXPECT_EQ(error.kind(), ExchangeFailure::refused);
    EXPECT_STREQ(error.what(), "the toy refused toy request 5");
  }
  EXPECT_EQ(line.counters().bytes_out, kRequestSize);
  EXPECT_EQ(line.counters().retries, 0u);
}

TEST(Exchanger, TheRefusalComesBackAsTheOutcomesTelegram) {
  Line line([](std::uint8_t id) { return Answer{reply(id, kNo)}; });
  const ExchangeOutcome outcome = line.exchanger.try_exchange(request(6));
  EXPECT_EQ(outcome.failure, ExchangeFailure::refused);
  EXPECT_EQ(outcome.telegram, reply(6, kNo));
}

TEST(Exchanger, AStopRequestedMidWaitEndsItBeforeTheTimeout) {
  std::atomic<bool> stop{false};
  Line line(
      [&](std::uint8_t) {
        stop = true;  // the request has gone out; the host is waiting
        return Answer{};
      },
      &stop);
  const ExchangeOutcome outcome = line.exchanger.try_exchange(request(8, std::chrono::minutes(1)));
  // A wait that ran to its end would have been a no_reply and a timeout.
  EXPECT_EQ(outcome.failure, ExchangeFailure::stopped);
  EXPECT_TRUE(contains(outcome.message, "toy request 8")) << outcome.message;
  EXPECT_EQ(line.counters().timeouts, 0u);
}

TEST(Exchanger, NothingIsSentOnceStopped) {
  const std::atomic<bool> stop{true};
  Line line([](std::uint8_t id) { return Answer{reply(id)}; }, &stop);
  EXPECT_EQ(line.exchanger.try_exchange(request(9)).failure, ExchangeFailure::stopped);
  EXPECT_EQ(line.counters().bytes_out, 0u);
  EXPECT_THROW(line.exchanger.next(deadline_in(kPatience)), ExchangeError);
}

TEST(Exchanger, TheDeviceClosingPassesThroughAsADisconnectedLinkError) {
  Line line([](std::uint8_t) { return Answer{.bytes = {}, .hang_up = true}; });
  try {
    line.exchanger.exchange(request(10, std::chrono::minutes(1)));
    FAIL() << "an exchange with a vanished device succeeded";
  } catch (const LinkError& error) {
    EXPECT_EQ(error.kind(), LinkErrorKind::disconnected);
  }
}

TEST(Exchanger, StaleInputIsDroppedBeforeTheRequest) {
  Line line([](std::uint8_t id) { return Answer{reply(id)}; });
  // A refusal left over from before: read as the answer, it would end the exchange.
  ASSERT_TRUE(line.pty->write_all(reply(11, kNo), deadline_in(kPatience)));
  ASSERT_NE(wait_for_fd(line.link->native_handle(), POLLIN, deadline_in(kPatience)), 0);
  EXPECT_EQ(line.exchanger.exchange(request(11)), reply(11));
}

TEST(Exchanger, NextOnAnIdleLineCountsNoTimeoutButCallsTheIdleCallback) {
  Line line([](std::uint8_t) { return Answer{}; });
  int idle_calls = 0;
  line.exchanger.set_idle_callback([&] { ++idle_calls; });
  EXPECT_EQ(line.exchanger.next(deadline_in(120ms)), std::nullopt);
  EXPECT_GE(idle_calls, 1);
  EXPECT_EQ(line.counters().timeouts, 0u);
}

TEST(Exchanger, NextReturnsATelegramAndCountsOneThatStalledHalfWay) {
  Line line([](std::uint8_t) { return Answer{}; });
  ASSERT_TRUE(line.pty->write_all(reply(12), deadline_in(kPatience)));
  EXPECT_EQ(line.exchanger.next(deadline_in(kPatience)), reply(12));
  const Bytes half = {0xAA, 0x02, 0x0C};
  ASSERT_TRUE(line.pty->write_all(half, deadline_in(kPatience)));
  ASSERT_NE(wait_for_fd(line.link->native_handle(), POLLIN, deadline_in(kPatience)), 0);
  EXPECT_EQ(line.exchanger.next(deadline_in(100ms)), std::nullopt);
  EXPECT_EQ(line.counters().timeouts, 1u);
}

}  // namespace exchange_test
}  // namespace playerkit::links
