#pragma once
// A hardware family that exists only in tests, made of kit pieces alone: an
// "echo box" on a serial line that greets and repeats lines. It proves that a
// family registered in a FamilyRegistry is known to list, info, probe,
// emulate and run --trace with no edit anywhere else.
//
// The protocol (lines ending in '\n'):
//   host "HELLO"      -> device "HELLO echo-box <greeting>"
//   host "SAY <text>" -> device "<text>"
//   anything else     -> device "ERR"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "core/device.hpp"
#include "core/driver.hpp"
#include "core/driver_registry.hpp"
#include "emulators/emulator_option_reader.hpp"
#include "families/family_spec.hpp"
#include "framing/terminated_line_format.hpp"
#include "hardware_driver/serial_device_driver.hpp"
#include "links/framed_reader.hpp"
#include "links/link_error.hpp"
#include "links/open_link.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::echo_family_test_support {

constexpr std::size_t kLongestLine = 128;

// A telegram is one line up to and with its '\n'; a longer run is noise.
framing::LineOptions echo_lines() {
  return {.end = framing::LineEnd::lf, .max_length = kLongestLine, .name = "echo"};
}

std::vector<std::uint8_t> line_bytes(const std::string& text) {
  std::vector<std::uint8_t> bytes(text.begin(), text.end());
  bytes.push_back('\n');
  return bytes;
}

class EchoBox final : public emulators::DeviceEmulator {
 public:
  explicit EchoBox(std::string greeting) : greeting_(std::move(greeting)) {}

  void receive(std::span<const std::uint8_t> bytes, emulators::Duration, int) override {
    for (const std::uint8_t byte : bytes) {
      if (byte != '\n') {
        pending_.push_back(static_cast<char>(byte));
        continue;
      }
      const std::string line = std::exchange(pending_, {});
      ++lines_;
      if (line == "HELLO") {
        out_.push_back({line_bytes("HELLO echo-box " + greeting_), false});
      } else if (line.starts_with("SAY ")) {
        out_.push_back({line_bytes(line.substr(4)), false});
      } else {
        out_.push_back({line_bytes("ERR"), false});
      }
    }
  }
  void advance(emulators::Duration) override {}
  [[nodiscard]] emulators::Duration next_deadline() const override { return emulators::Duration::max(); }
  std::vector<emulators::Telegram> take_output() override { return std::exchange(out_, {}); }
  [[nodiscard]] std::string describe() const override { return "echo box, " + std::to_string(lines_) + " lines"; }

 private:
  std::string greeting_;
  std::string pending_;
  std::vector<emulators::Telegram> out_;
  int lines_ = 0;
};

// Sends `line` and returns the first line heard that starts with `reply`,
// nullopt by the deadline. A newline goes first: it ends whatever noise the
// device has buffered as a line of its own, which it answers and we skip.
std::optional<std::string> ask_line(links::ByteLink& link, links::FramedReader& reader, const std::string& line,
                                    const std::string& reply, links::Deadline deadline) {
  link.write_all(line_bytes("\n" + line), deadline);
  while (const auto heard = reader.next(deadline)) {
    std::string text(heard->begin(), heard->end() - 1);
    if (text.starts_with(reply)) return text;
  }
  return std::nullopt;
}

// The comms device of an echo box: each command is said, each line heard is
// published. The port, its loss and recovery, the counters, the trace and
// the thread's sleep come from the base.
class EchoLineDriver final : public hardware_driver::SerialDeviceDriver {
 public:
  explicit EchoLineDriver(std::string port) : SerialDeviceDriver(std::move(port), {.baud = 9600}, {}) {}

 protected:
  void start_device(links::ByteLink& link, bool /*recovering*/) override {
    reader_ = std::make_unique<links::FramedReader>(link, format_, kLongestLine);
  }
  void serve(links::ByteLink& link, const core::Wakeup::Woken& woke) override {
    device().service_requests();
    while (const auto command = device().take_command()) {
      link.write_all(line_bytes("SAY " + std::string(command->payload.begin(), command->payload.end())),
                     links::deadline_in(std::chrono::seconds(1)));
    }
    if (!woke.readable) return;
    // Every whole line there is, without waiting for the rest of one.
    while (const auto line = reader_->next(links::Deadline{})) device().publish({line->begin(), line->end() - 1});
    ++looks_;
  }
  [[nodiscard]] Clock::time_point next_deadline() const override { return Clock::time_point::max(); }
  void link_closing() noexcept override { reader_.reset(); }
  [[nodiscard]] std::uint64_t own_timeouts() const override { return looks_.load(); }

 private:
  framing::TerminatedLineFormat format_{echo_lines()};
  std::unique_ptr<links::FramedReader> reader_;
  std::atomic<std::uint64_t> looks_{0};  // reads that found no whole line: not timeouts
};

std::optional<families::Identification> probe_echo(const families::ProbeContext& line) {
  const framing::TerminatedLineFormat format(echo_lines());
  links::FramedReader reader(line.link, format, kLongestLine);
  reader.flush();
  const auto reply = ask_line(line.link, reader, "HELLO", "HELLO echo-box ", line.first_reply);
  if (!reply) return std::nullopt;
  return families::Identification{.driver = "echoline",
                                  .model = reply->substr(6),
                                  .interface_name = "comms",
                                  .config_driver = "echoline",
                                  .note = ""};
}

families::FamilySpec echo_family() {
  core::DriverSpec driver;
  driver.name = "echoline";
  driver.interfaces = {protocol::kCommsCode};
  driver.access = protocol::Access::kAll;
  driver.factory = [](const core::DriverContext& context) {
    return std::make_unique<EchoLineDriver>(context.section.read_string("port", "/dev/ttyS0"));
  };
  driver.summary = "an echo box on a serial line (a test family)";
  return {
      .name = "echo",
      .summary = "echo boxes: a family made in a test",
      .probes = {{.label = "ECHO", .bauds = {9600}, .line = {}, .ask = probe_echo}},
      .framing = {std::make_shared<framing::TerminatedLineFormat>(echo_lines()),
                  std::make_shared<framing::TerminatedLineFormat>(echo_lines())},
      .emulators = {{.name = "echobox",
                     .summary = "an echo box that greets and repeats lines",
                     .interface_name = "comms",
                     .driver = "echoline",
                     .mount = emulators::EmulatorMount::standalone,
                     .options = {{"greeting", "v1", "what it says after HELLO echo-box"}},
                     .make = [](const emulators::EmulatorOptionReader& options, const emulators::EmulatorWorld&) {
                       return std::unique_ptr<emulators::DeviceEmulator>(
                           std::make_unique<EchoBox>(options.text("greeting", "v1")));
                     }}},
      .drivers = {driver},
      .examples = {"player-drivers emulate echobox greeting=hi --link /tmp/echo"},
  };
}

}  // namespace playerkit::echo_family_test_support
