// probe_port with toy families made here, each asking its own question over
// a line: the order of attempts, the port's problems, TCP, the budget and a
// stop. What the real families' probes find is tested with each family
// (lib/families/<name>/<name>_family_test.cpp).

#include "families/port_probe.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "emulators/runner/emulator_runner.hpp"
#include "framing/terminated_line_format.hpp"
#include "links/framed_reader.hpp"
#include "links/pseudo_terminal.hpp"
#include "links/serial_link.hpp"

namespace playerkit::families {
namespace port_probe_test {

using namespace std::chrono_literals;

constexpr std::size_t kLongestLine = 64;

// A telegram is one line up to and with its '\n'.
framing::TerminatedLineFormat line_format() {
  return framing::TerminatedLineFormat({.end = framing::LineEnd::lf, .max_length = kLongestLine, .name = "toy line"});
}

std::vector<std::uint8_t> line_bytes(const std::string& text) {
  std::vector<std::uint8_t> bytes(text.begin(), text.end());
  bytes.push_back('\n');
  return bytes;
}

// A device of family `family` ("ALPHA"): to the line "ALPHA?" it answers
// "ALPHA <name>"; every other line goes unanswered. With a baud, bytes sent
// at another speed are line noise, as on a real line.
class ToyDevice final : public emulators::DeviceEmulator {
 public:
  ToyDevice(std::string family, std::string name, int baud)
      : family_(std::move(family)), name_(std::move(name)), baud_(baud) {}

  void receive(std::span<const std::uint8_t> bytes, emulators::Duration, int host_baud) override {
    if (baud_ != 0 && host_baud != 0 && host_baud != baud_) return;
    for (const std::uint8_t byte : bytes) {
      if (byte != '\n') {
        pending_.push_back(static_cast<char>(byte));
        continue;
      }
      if (std::exchange(pending_, {}) == family_ + "?") out_.push_back({line_bytes(family_ + " " + name_), false});
    }
  }
  void advance(emulators::Duration) override {}
  [[nodiscard]] emulators::Duration next_deadline() const override { return emulators::Duration::max(); }
  std::vector<emulators::Telegram> take_output() override { return std::exchange(out_, {}); }
  [[nodiscard]] int baud() const override { return baud_; }
  [[nodiscard]] std::string describe() const override { return family_ + " " + name_; }

 private:
  std::string family_;
  std::string name_;
  int baud_;
  std::string pending_;
  std::vector<emulators::Telegram> out_;
};

emulators::EmulatorRunner device(const std::string& family, const std::string& name, int baud,
                                 emulators::Endpoint endpoint = emulators::PtyEndpoint{}) {
  return emulators::EmulatorRunner(std::make_unique<ToyDevice>(family, name, baud), endpoint);
}

// The probe of family `family`: asks "<FAMILY>?" and waits for its answer.
ProbeMethod toy_probe(const std::string& family, std::vector<int> bauds, links::SerialSettings line) {
  std::string lower = family;
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return {.label = family,
          .bauds = std::move(bauds),
          .line = line,
          .ask = [family, lower](const ProbeContext& context) -> std::optional<Identification> {
            const auto format = line_format();
            links::FramedReader reader(context.link, format, kLongestLine);
            reader.flush();
            context.link.write_all(line_bytes(family + "?"),
                                   std::max(context.first_reply, links::deadline_in(100ms)));
            while (const auto reply = reader.next(context.first_reply)) {
              const std::string text(reply->begin(), reply->end() - 1);
              if (!text.starts_with(family + " ")) continue;
              return Identification{.driver = lower + "d",
                                    .model = text.substr(family.size() + 1),
                                    .interface_name = "comms",
                                    .config_driver = lower + "_comms",
                                    .note = ""};
            }
            return std::nullopt;
          }};
}

FamilySpec toy_family(const std::string& name, std::vector<ProbeMethod> probes) {
  return {.name = name,
          .summary = "a toy family",
          .probes = std::move(probes),
          .framing = {},
          .emulators = {},
          .drivers = {},
          .examples = {}};
}

// alpha: 8N1 at 9600 or 38400. beta: 8E1 at 19200, 9600 or 57600. gamma:
// nothing to probe.
FamilyRegistry toys() {
  FamilyRegistry registry;
  registry.add(toy_family("alpha", {toy_probe("ALPHA", {9600, 38400}, {})}));
  registry.add(toy_family("gamma", {}));
  registry.add(toy_family("beta", {toy_probe("BETA", {19200, 9600, 57600}, {.parity = links::Parity::even})}));
  return registry;
}

// Settings for a quick test that keep every progress line.
struct Recorded {
  std::vector<std::string> progress;
  ProbeSettings settings;
  Recorded() {
    settings.first_reply = 100ms;
    settings.progress = [this](std::string_view line) { progress.emplace_back(line); };
  }
};

ProbeResult probe(const std::string& port, const FamilyRegistry& registry, const ProbeSettings& settings) {
  return probe_port(port, registry, settings, [] { return false; });
}

std::string described(const ProbeAttempt& attempt) {
  return attempt.family + " " + attempt.method->label + " " + std::to_string(attempt.baud);
}

TEST(PortProbe, AttemptsTakeEveryProbesLikeliestRateFirst) {
  const auto registry = toys();
  std::vector<std::string> serial;
  for (const auto& attempt : probe_attempts(registry, true)) serial.push_back(described(attempt));
  EXPECT_EQ(serial, (std::vector<std::string>{"alpha ALPHA 9600", "beta BETA 19200", "alpha ALPHA 38400",
                                              "beta BETA 9600", "beta BETA 57600"}));
  std::vector<std::string> tcp;
  for (const auto& attempt : probe_attempts(registry, false)) tcp.push_back(described(attempt));
  EXPECT_EQ(tcp, (std::vector<std::string>{"alpha ALPHA 0", "beta BETA 0"}));
  // The methods are the registry's own.
  EXPECT_EQ(probe_attempts(registry, true).front().method, &registry.find("alpha")->probes.front());
  EXPECT_TRUE(probe_attempts(FamilyRegistry{}, true).empty());
}

TEST(PortProbe, FindsADeviceAtTheRateItListensAt) {
  const auto registry = toys();
  auto beta = device("BETA", "b-7", 57600);
  Recorded recorded;
  const ProbeResult result = probe(beta.device_path(), registry, recorded.settings);
  ASSERT_TRUE(result.found) << result.problem;
  EXPECT_EQ(result.port, beta.device_path());
  EXPECT_EQ(result.found->driver, "betad");
  EXPECT_EQ(result.found->model, "b-7");
  EXPECT_EQ(result.baud, 57600);
  EXPECT_EQ(result.config_line, "comms:0 ( driver \"beta_comms\" port \"" + beta.device_path() + "\" )");
  EXPECT_FALSE(result.port_unusable);
  EXPECT_FALSE(result.interrupted);
  // Every attempt before it, each line speed and framing set as its probe wants.
  ASSERT_EQ(recorded.progress.size(), 5u);
  EXPECT_EQ(recorded.progress[0], beta.device_path() + ": ALPHA at 9600 8N1: no answer");
  EXPECT_EQ(recorded.progress[1], beta.device_path() + ": BETA at 19200 8E1: no answer");
  EXPECT_EQ(recorded.progress[4], beta.device_path() + ": BETA at 57600 8E1: betad");
}

TEST(PortProbe, StopsAtTheFirstAnswer) {
  const auto registry = toys();
  auto alpha = device("ALPHA", "a-1", 38400);
  Recorded recorded;
  const ProbeResult result = probe(alpha.device_path(), registry, recorded.settings);
  ASSERT_TRUE(result.found) << result.problem;
  EXPECT_EQ(result.found->driver, "alphad");
  EXPECT_EQ(result.baud, 38400);
  ASSERT_EQ(recorded.progress.size(), 3u);
  EXPECT_EQ(recorded.progress.back(), alpha.device_path() + ": ALPHA at 38400 8N1: alphad");
}

TEST(PortProbe, NothingBehindAPortIsNotAPortProblem) {
  const auto registry = toys();
  links::PseudoTerminal silent;
  Recorded recorded;
  recorded.settings.first_reply = 50ms;
  const ProbeResult result = probe(silent.slave_path(), registry, recorded.settings);
  EXPECT_FALSE(result.found);
  EXPECT_FALSE(result.port_unusable);
  EXPECT_FALSE(result.interrupted);
  EXPECT_EQ(result.problem, "no supported device answered on " + silent.slave_path() +
                                " (tried ALPHA at 9600, 38400 baud; BETA at 19200, 9600, 57600 baud); is it powered, "
                                "cabled to this port, and not in use by a program that ignores locks?");
  EXPECT_EQ(recorded.progress.size(), probe_attempts(registry, true).size());
  EXPECT_EQ(recorded.progress.front(), silent.slave_path() + ": ALPHA at 9600 8N1: no answer");
}

TEST(PortProbe, WithoutProbesNothingIsTried) {
  FamilyRegistry registry;
  registry.add(toy_family("gamma", {}));
  links::PseudoTerminal silent;
  Recorded recorded;
  const ProbeResult result = probe(silent.slave_path(), registry, recorded.settings);
  EXPECT_FALSE(result.found);
  EXPECT_FALSE(result.port_unusable);
  EXPECT_EQ(result.problem.rfind("no supported device answered on " + silent.slave_path() +
                                     " (tried no probes: no family that can be probed is built)",
                                 0),
            0u)
      << result.problem;
  EXPECT_TRUE(recorded.progress.empty());
}

TEST(PortProbe, AsksOnceOverTcp) {
  const auto registry = toys();
  auto beta = device("BETA", "b-9", 57600, emulators::TcpEndpoint{});
  Recorded recorded;
  const ProbeResult result = probe(beta.device_path(), registry, recorded.settings);
  ASSERT_TRUE(result.found) << result.problem;
  EXPECT_EQ(result.found->driver, "betad");
  EXPECT_EQ(result.baud, 0);
  EXPECT_EQ(result.config_line, "comms:0 ( driver \"beta_comms\" port \"" + beta.device_path() + "\" )");
  EXPECT_EQ(recorded.progress, (std::vector<std::string>{beta.device_path() + ": ALPHA: no answer",
                                                         beta.device_path() + ": BETA: betad"}));
}

TEST(PortProbe, NothingAnsweringOverTcpSaysEachWasAskedOnce) {
  const auto registry = toys();
  auto other = device("DELTA", "d-1", 0, emulators::TcpEndpoint{});
  Recorded recorded;
  recorded.settings.first_reply = 50ms;
  const ProbeResult result = probe(other.device_path(), registry, recorded.settings);
  EXPECT_FALSE(result.found);
  EXPECT_FALSE(result.port_unusable);
  EXPECT_EQ(result.problem.rfind("no supported device answered on " + other.device_path() +
                                     " (tried ALPHA at once; BETA at once)",
                                 0),
            0u)
      << result.problem;
  EXPECT_EQ(recorded.progress.size(), probe_attempts(registry, false).size());
}

TEST(PortProbe, AMissingPortSaysSoWithoutOpeningAnything) {
  const std::string missing = "/tmp/families_port_probe_test_" + std::to_string(::getpid()) + "_nothing";
  Recorded recorded;
  const ProbeResult result = probe(missing, toys(), recorded.settings);
  EXPECT_FALSE(result.found);
  EXPECT_TRUE(result.port_unusable);
  EXPECT_EQ(result.problem.rfind("no such port " + missing, 0), 0u) << result.problem;
  EXPECT_TRUE(recorded.progress.empty());
}

TEST(PortProbe, ABadAddressIsAPortProblem) {
  Recorded recorded;
  const ProbeResult result = probe("tcp:robot", toys(), recorded.settings);
  EXPECT_FALSE(result.found);
  EXPECT_TRUE(result.port_unusable);
  EXPECT_EQ(result.port, "tcp:robot");
  EXPECT_EQ(result.problem.rfind("bad port 'tcp:robot': ", 0), 0u) << result.problem;
  EXPECT_TRUE(recorded.progress.empty());
}

TEST(PortProbe, AFileIsNoPort) {
  const auto file = std::filesystem::temp_directory_path() /
                    ("families_port_probe_test_" + std::to_string(::getpid()) + "_file");
  std::ofstream(file) << "not a terminal\n";
  Recorded recorded;
  const ProbeResult result = probe(file.string(), toys(), recorded.settings);
  std::filesystem::remove(file);
  EXPECT_FALSE(result.found);
  EXPECT_TRUE(result.port_unusable);
  EXPECT_EQ(result.problem.rfind(file.string() + " is ", 0), 0u) << result.problem;
  EXPECT_NE(result.problem.find(", not a serial port"), std::string::npos) << result.problem;
  EXPECT_TRUE(recorded.progress.empty());
}

TEST(PortProbe, ABusyPortNamesItsHolder) {
  auto alpha = device("ALPHA", "a-1", 0);
  const auto holder = links::SerialLink::open(alpha.device_path(), {.baud = 9600});
  Recorded recorded;
  const ProbeResult result = probe(alpha.device_path(), toys(), recorded.settings);
  EXPECT_FALSE(result.found);
  EXPECT_TRUE(result.port_unusable);
  EXPECT_NE(result.problem.find("is busy: held by pid " + std::to_string(::getpid())), std::string::npos)
      << result.problem;
  EXPECT_TRUE(recorded.progress.empty());
}

TEST(PortProbe, AStopEndsTheProbe) {
  links::PseudoTerminal silent;
  const ProbeResult result = probe_port(silent.slave_path(), toys(), {}, [] { return true; });
  EXPECT_TRUE(result.interrupted);
  EXPECT_FALSE(result.found);
  EXPECT_FALSE(result.port_unusable);
  EXPECT_EQ(result.problem, "interrupted");
}

TEST(PortProbe, AStopIsCheckedBetweenAttempts) {
  links::PseudoTerminal silent;
  Recorded recorded;
  recorded.settings.first_reply = 50ms;
  int asked = 0;
  const ProbeResult result =
      probe_port(silent.slave_path(), toys(), recorded.settings, [&asked] { return ++asked > 2; });
  EXPECT_TRUE(result.interrupted);
  EXPECT_FALSE(result.found);
  EXPECT_EQ(recorded.progress.size(), 2u);
}

TEST(PortProbe, TheBudgetBoundsThePort) {
  links::PseudoTerminal silent;
  Recorded recorded;
  recorded.settings.budget = 0ms;
  const ProbeResult result = probe(silent.slave_path(), toys(), recorded.settings);
  EXPECT_FALSE(result.found);
  EXPECT_FALSE(result.interrupted);
  EXPECT_FALSE(result.port_unusable);
  EXPECT_EQ(result.problem.rfind("no supported device answered on " + silent.slave_path(), 0), 0u) << result.problem;
  EXPECT_TRUE(recorded.progress.empty());
}

}  // namespace port_probe_test
}  // namespace playerkit::families
