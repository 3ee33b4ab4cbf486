// SerialDeviceDriver with a toy line protocol against a device played by the
// test on a pseudo-terminal: the handshake at setup, a command waking the
// driver's thread (it has no timer at all, so nothing else could), the
// device vanishing and coming back, the goodbye at shutdown.
//
//   host "HI"        -> device "OK"     (the handshake)
//   device "D <n>"                      (data, published as is)
//   host "C <text>"                     (a command)
//   host "BYE"                          (stop_device)

#include "hardware_driver/serial_device_driver.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <future>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "core/device.hpp"
#include "framing/terminated_line_format.hpp"
#include "links/framed_reader.hpp"
#include "links/pseudo_terminal.hpp"
#include "protocol/interfaces.hpp"
#include "support/eventually.hpp"

namespace playerkit::hardware_driver {
namespace serial_device_driver_test {

using namespace std::chrono_literals;
using testing::eventually;

const framing::LineOptions kLines{
    .end = framing::LineEnd::lf, .max_length = 64, .prompt = std::nullopt, .skip_empty_lines = false, .name = "toy"};

class ToyDriver final : public SerialDeviceDriver {
 public:
  explicit ToyDriver(std::string port)
      : SerialDeviceDriver(std::move(port), {.baud = 9600}, {.interval = 50ms, .reopen_timeout = 1s}) {}

 protected:
  void start_device(links::ByteLink& link, bool /*recovering*/) override {
    reader_ = std::make_unique<links::FramedReader>(link, format_, kLines.max_length);
    link.write_all(framing::line_bytes("HI", kLines.end), links::deadline_in(1s));
    const auto deadline = links::deadline_in(2s);
    while (const auto line = reader_->next(deadline)) {
      if (framing::line_text(*line) == "OK") return;
    }
    throw std::runtime_error("no OK from " + port());
  }
  void serve(links::ByteLink& link, const core::Wakeup::Woken& woke) override {
    while (const auto command = device().take_command()) {
      link.write_all(framing::line_bytes("C " + std::string(command->payload.begin(), command->payload.end()),
                                         kLines.end),
                     links::deadline_in(1s));
    }
    if (!woke.readable) return;
    while (const auto line = reader_->next(links::Deadline{})) {
      const auto text = framing::line_text(*line);
      device().publish({text.begin(), text.end()});
    }
  }
  [[nodiscard]] Clock::time_point next_deadline() const override { return Clock::time_point::max(); }
  void stop_device(links::ByteLink& link) noexcept override {
    try {
      link.write_all(framing::line_bytes("BYE", kLines.end), links::deadline_in(1s));
      link.drain();
    } catch (const std::exception&) {
    }
  }
  void link_closing() noexcept override { reader_.reset(); }
  [[nodiscard]] std::string subject() const override { return "the toy on " + port(); }

 private:
  framing::TerminatedLineFormat format_{kLines};
  std::unique_ptr<links::FramedReader> reader_;
};

// The device's side of the line: lines in, lines out.
class ToyDevice {
 public:
  explicit ToyDevice(const std::filesystem::path& at) : pty_(at) {}

  // The next line the host wrote, or empty when none came by the deadline.
  std::string next_line(std::chrono::milliseconds limit = 5s) {
    const auto deadline = links::deadline_in(limit);
    for (;;) {
      if (const auto end = pending_.find('\n'); end != std::string::npos) {
        std::string line = pending_.substr(0, end);
        pending_.erase(0, end + 1);
        return line;
      }
      std::uint8_t buffer[256];
      const auto received = pty_.read_some(buffer, deadline);
      pending_.append(buffer, buffer + received.count);
      host_closed_ = host_closed_ || received.host_closed;
      if (received.count == 0 && links::LinkClock::now() >= deadline) return {};
    }
  }
  void say(const std::string& line) {
    ASSERT_TRUE(pty_.write_all(framing::line_bytes(line, kLines.end), links::deadline_in(1s)));
  }
  // Answers the host's HI.
  void greet() {
    EXPECT_EQ(next_line(), "HI");
    say("OK");
  }
  // The host closed its side, as of the last read (or waits until it does).
  bool host_closed(std::chrono::milliseconds limit = 5s) {
    const auto deadline = links::deadline_in(limit);
    while (!host_closed_ && links::LinkClock::now() < deadline) {
      std::uint8_t buffer[64];
      host_closed_ = pty_.read_some(buffer, deadline).host_closed;
    }
    return host_closed_;
  }

 private:
  links::PseudoTerminal pty_;
  std::string pending_;
  bool host_closed_ = false;
};

struct SerialDeviceDriverTest : ::testing::Test {
  std::filesystem::path port = std::filesystem::temp_directory_path() /
                               ("serial_device_driver_test_" + std::to_string(::getpid()));
  std::unique_ptr<ToyDevice> toy = std::make_unique<ToyDevice>(port);
  core::ManualClock clock{{100, 0}};
  core::Logger logger;
  std::mutex log_mutex;
  std::vector<std::string> log;
  std::unique_ptr<core::Device> device;

  void SetUp() override {
    logger.set_level(core::LogLevel::kInfo);
    logger.set_sink([this](core::LogLevel, std::string_view line) {
      std::lock_guard lock(log_mutex);
      log.emplace_back(line);
    });
    device = std::make_unique<core::Device>(
        core::DeviceKey{6665, {protocol::kCommsCode, 0}},
        core::DeviceInfo{"toy", "", protocol::Access::kAll, {}, false}, std::make_unique<ToyDriver>(port.string()),
        clock, logger);
  }
  void TearDown() override { device.reset(); }

  // Subscribes while the toy answers the handshake.
  bool subscribe() {
    auto subscribed = std::async(std::launch::async, [this] { return device->subscribe(); });
    toy->greet();
    return subscribed.get();
  }
  std::size_t logged(std::string_view text) {
    std::lock_guard lock(log_mutex);
    return static_cast<std::size_t>(
        std::count_if(log.begin(), log.end(), [&](const std::string& line) { return line.find(text) != std::string::npos; }));
  }
  std::uint64_t counter(std::string_view name) {
    for (const auto& c : device->driver().counters()) {
      if (c.name == name) return c.value;
    }
    ADD_FAILURE() << "no counter " << name;
    return 0;
  }
  std::string latest() {
    const auto sample = device->latest_data();
    return {sample->payload.begin(), sample->payload.end()};
  }
};

TEST_F(SerialDeviceDriverTest, ACommandWakesTheThreadThatHasNothingElseToWaitFor) {
  ASSERT_TRUE(subscribe());
  const std::vector<std::uint8_t> go{'g', 'o'};
  ASSERT_EQ(device->put_command(1, go), core::Device::CommandStatus::kAccepted);
  EXPECT_EQ(toy->next_line(), "C go");
  // And the line's input wakes it too.
  toy->say("D 1");
  EXPECT_TRUE(eventually([&] { return latest() == "D 1"; }));
}

TEST_F(SerialDeviceDriverTest, TheDeviceVanishingAndComingBackIsOneLineEachAndDataResumes) {
  ASSERT_TRUE(subscribe());
  toy->say("D 1");
  ASSERT_TRUE(eventually([&] { return latest() == "D 1"; }));
  const auto bytes_first = counter("bytes_in");

  toy.reset();  // unplugged
  ASSERT_TRUE(eventually([&] { return !device->available(); })) << "the loss was not noticed";
  EXPECT_EQ(logged("lost the toy on " + port.string()), 1u);

  toy = std::make_unique<ToyDevice>(port);  // plugged in again at the same name
  toy->greet();
  ASSERT_TRUE(eventually([&] { return device->available(); }));
  EXPECT_TRUE(eventually([&] { return logged("the toy on " + port.string() + " answers again") == 1u; }));
  toy->say("D 2");
  EXPECT_TRUE(eventually([&] { return latest() == "D 2"; }));
  EXPECT_EQ(counter("reconnects"), 1u);
  // The first link's bytes are still counted.
  EXPECT_GT(counter("bytes_in"), bytes_first);
  EXPECT_EQ(logged("lost the toy"), 1u);
}

TEST_F(SerialDeviceDriverTest, TheLastUnsubscriptionSaysGoodbyeThenClosesThePort) {
  ASSERT_TRUE(subscribe());
  device->unsubscribe();
  EXPECT_EQ(toy->next_line(), "BYE");
  EXPECT_TRUE(toy->host_closed());
}

TEST_F(SerialDeviceDriverTest, ADeviceThatDoesNotAnswerRefusesTheSubscriptionNamingThePort) {
  // Nobody answers HI: the handshake's own deadline refuses it.
  EXPECT_FALSE(device->subscribe());
  EXPECT_EQ(logged("no OK from " + port.string()), 1u);
  EXPECT_EQ(device->subscriptions(), 0);
}

}  // namespace serial_device_driver_test
}  // namespace playerkit::hardware_driver
