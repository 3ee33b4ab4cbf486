#include "run_session.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>
#include <streambuf>
#include <thread>

#include "client/client.hpp"
#include "daemon/serve.hpp"
#include "emulators/catalog/emulator_catalog.hpp"
#include "families/builtin_families.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::player_drivers {
namespace run_session_test {

using namespace std::chrono_literals;

// An ostream other threads may write while the test reads what arrived.
class Capture {
 public:
  Capture() : stream_(&buffer_) {}
  std::ostream& stream() { return stream_; }
  std::string text() const { return buffer_.text(); }

 private:
  class Buffer final : public std::streambuf {
   public:
    std::string text() const {
      const std::lock_guard lock(mutex_);
      return text_;
    }

   protected:
    int_type overflow(int_type c) override {
      if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
      const std::lock_guard lock(mutex_);
      text_ += traits_type::to_char_type(c);
      return c;
    }
    std::streamsize xsputn(const char* s, std::streamsize n) override {
      const std::lock_guard lock(mutex_);
      text_.append(s, static_cast<std::size_t>(n));
      return n;
    }

   private:
    mutable std::mutex mutex_;
    std::string text_;
  };
  Buffer buffer_;
  std::ostream stream_;
};

// A pipe for --stdin: write the lines, then close.
class InputPipe {
 public:
  explicit InputPipe(const std::string& text) {
    if (::pipe(ends_) != 0) throw std::runtime_error("pipe failed");
    if (::write(ends_[1], text.data(), text.size()) != static_cast<ssize_t>(text.size())) {
      throw std::runtime_error("write failed");
    }
    ::close(ends_[1]);
  }
  ~InputPipe() { ::close(ends_[0]); }
  int fd() const { return ends_[0]; }

 private:
  int ends_[2] = {-1, -1};
};

struct Outcome {
  int status = -1;
  std::string out;
  std::string err;
};

RunCommandLine line_of(std::vector<std::string> words) {
  RunCommandLine line;
  line.words = std::move(words);
  line.timeout = 10;
  return line;
}

Outcome run(const RunCommandLine& line, int input_fd = -1, const std::function<bool()>& stop = [] { return false; }) {
  Capture out, err;
  Outcome outcome;
  outcome.status = run_driver(make_run_options(line), families::builtin_families(), {out.stream(), err.stream(), input_fd}, stop);
  outcome.out = out.text();
  outcome.err = err.text();
  return outcome;
}

std::vector<nlohmann::json> json_lines(const std::string& text) {
  std::vector<nlohmann::json> lines;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) lines.push_back(nlohmann::json::parse(line));
  return lines;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::filesystem::path scratch(const std::string& name) {
  return std::filesystem::temp_directory_path() / ("player_drivers_run_test_" + std::to_string(::getpid()) + "_" + name);
}

// Twenty position samples 50 ms apart, replayed over and over.
std::string position_log() {
  const auto path = scratch("positions.log");
  std::ofstream log(path);
  log << "## Player version 1.5 \n## File version 0.0.0 \n";
  for (int i = 0; i < 20; ++i) {
    const double t = 1000.0 + 0.05 * i;
    log << std::fixed << t << " robot 6665 position 00 " << t << " +" << 0.1 * i << " +0.200 +1.571 +0.000 +0.000 +0.000 0\n";
  }
  return path.string();
}

bool registered(std::string_view driver) {
  core::Logger logger("test");
  logger.set_level(core::LogLevel::kError);
  return daemon::load_drivers({}, logger).contains(driver);
}

TEST(RunSession, ARequestIsAnsweredAndItsReplyPrinted) {
  auto line = line_of({"lifomcom"});
  line.request = {"push", "channel=news", "data.data=hello"};
  const Outcome pushed = run(line);
  EXPECT_EQ(pushed.status, kExitOk) << pushed.err;
  const auto replies = json_lines(pushed.out);
  ASSERT_EQ(replies.size(), 1u) << pushed.out;
  EXPECT_EQ(replies[0]["type"], "ack");
  EXPECT_EQ(replies[0]["device"], "mcom");
  // A new run is a new device: nothing to pop, and lifomcom says NACK.
  line.request = {"pop", "channel=news"};
  const Outcome popped = run(line);
  EXPECT_EQ(popped.status, kExitNack) << popped.err;
  EXPECT_EQ(json_lines(popped.out).at(0)["type"], "nack");
}

TEST(RunSession, StdinLinesAreSentInOrderAndTheRunEndsWithThem) {
  InputPipe input(
      "{\"device\":\"mcom:0\",\"request\":\"push\",\"data\":{\"channel\":\"news\",\"data\":{\"data\":\"hi\"}}}\n"
      "{\"device\":\"mcom:0\",\"request\":\"pop\",\"data\":{\"channel\":\"news\"}}\n");
  auto line = line_of({"lifomcom"});
  line.from_stdin = true;
  const Outcome outcome = run(line, input.fd());
  EXPECT_EQ(outcome.status, kExitOk) << outcome.err;
  const auto replies = json_lines(outcome.out);
  ASSERT_EQ(replies.size(), 2u) << outcome.out;
  EXPECT_EQ(replies[0]["request"], "push");
  EXPECT_EQ(replies[1]["request"], "pop");
  EXPECT_EQ(replies[1]["type"], "ack");
}

TEST(RunSession, DataInPlayerCatsFormats) {
  auto line = line_of({"readlog", "filename=" + position_log(), "autorewind=1"});
  line.device = "position:0";
  line.count = 3;
  line.format = "json";
  line.si = true;
  const Outcome outcome = run(line);
  EXPECT_EQ(outcome.status, kExitOk) << outcome.err;
  const auto lines = json_lines(outcome.out);
  ASSERT_EQ(lines.size(), 3u) << outcome.out;
  EXPECT_EQ(lines[0]["device"], "position");
  EXPECT_EQ(lines[0]["type"], "data");
  EXPECT_DOUBLE_EQ(lines[0]["data"]["ypos"].get<double>(), 0.2) << lines[0].dump();
}

TEST(RunSession, DeviceChoosesTheInterfaceOfADriverOfSeveral) {
  auto line = line_of({"readlog", "filename=" + position_log()});
  line.device = "laser:0";
  line.duration = 0.3;
  const Outcome outcome = run(line);
  // The log has no laser: nothing to print, and no error either.
  EXPECT_EQ(outcome.status, kExitOk) << outcome.err;
  EXPECT_EQ(outcome.out, "");
}

TEST(RunSession, AnOptionTheDriverRefusesIsNamedAsTyped) {
  auto line = line_of({"readlog", "filename=" + position_log(), "speed=-2"});
  line.device = "position:0";
  line.duration = 1;
  const Outcome outcome = run(line);
  EXPECT_EQ(outcome.status, kExitUsage);
  EXPECT_TRUE(contains(outcome.err, "player-drivers: error: option speed=-2: readlog: ")) << outcome.err;
  EXPECT_FALSE(contains(outcome.err, kGeneratedConfigName)) << outcome.err;
}

TEST(RunSession, AnOptionNoDriverReadsIsAnError) {
  auto line = line_of({"null", "colour=red"});
  line.duration = 1;
  const Outcome outcome = run(line);
  EXPECT_EQ(outcome.status, kExitUsage);
  EXPECT_TRUE(contains(outcome.err, "option colour=red: null does not read 'colour'")) << outcome.err;
}

TEST(RunSession, UnknownDriver) {
  const Outcome outcome = run(line_of({"nul"}));
  EXPECT_EQ(outcome.status, kExitUsage);
  EXPECT_TRUE(contains(outcome.err, "no driver or driver family 'nul'; did you mean 'null'?")) << outcome.err;
}

TEST(RunSession, NothingToReadServesUntilTheDuration) {
  auto line = line_of({"null"});
  line.duration = 0.2;
  line.trace = true;
  const Outcome outcome = run(line);
  EXPECT_EQ(outcome.status, kExitOk) << outcome.err;
  EXPECT_TRUE(contains(outcome.err, "--trace: null has no link to trace")) << outcome.err;
}

TEST(RunSession, StatsEverySecond) {
  auto line = line_of({"readlog", "filename=" + position_log(), "autorewind=1"});
  line.device = "position:0";
  line.duration = 2.5;
  line.stats = true;
  const Outcome outcome = run(line);
  EXPECT_EQ(outcome.status, kExitOk) << outcome.err;
  EXPECT_TRUE(contains(outcome.err, "stats position:0 readlog: ")) << outcome.err;
  EXPECT_TRUE(contains(outcome.err, " Hz (")) << outcome.err;
}

TEST(RunSession, RecordWritesAPlayerLog) {
  const auto record = scratch("record.log");
  auto line = line_of({"readlog", "filename=" + position_log(), "autorewind=1"});
  line.device = "position:0";
  line.count = 5;
  line.record = record.string();
  const Outcome outcome = run(line);
  EXPECT_EQ(outcome.status, kExitOk) << outcome.err;
  std::ifstream written(record);
  std::string text((std::istreambuf_iterator<char>(written)), std::istreambuf_iterator<char>());
  EXPECT_TRUE(contains(text, "## Player version 1.5")) << text;
  EXPECT_TRUE(contains(text, " position 00 ")) << text;
  std::filesystem::remove(record);
}

TEST(RunSession, ServeLetsOtherClientsIn) {
  auto line = line_of({"lifomcom"});
  line.serve_port = 0;
  line.bind = "127.0.0.1";
  Capture out, err;
  std::atomic<bool> stop{false};
  std::thread runner([&] {
    run_driver(make_run_options(line), families::builtin_families(), {out.stream(), err.stream(), -1}, [&] { return stop.load(); });
  });
  std::uint16_t port = 0;
  for (int i = 0; i < 200 && port == 0; ++i) {
    const std::string text = err.text();
    const auto at = text.find("listening on port ");
    if (at != std::string::npos) port = static_cast<std::uint16_t>(std::stoi(text.substr(at + 18)));
    std::this_thread::sleep_for(10ms);
  }
  ASSERT_NE(port, 0) << err.text();
  auto client = client::Client::connect("127.0.0.1", port, 5000ms);
  const auto devices = client.device_list();
  stop = true;
  runner.join();
  ASSERT_EQ(devices.size(), 1u);
  EXPECT_EQ(devices[0].driver_name, "lifomcom");
  EXPECT_TRUE(contains(err.text(), "(127.0.0.1): mcom:0 (lifomcom)")) << err.text();
}

TEST(RunSession, ALaserOnAnEmulatorWhenTheDriverIsBuilt) {
  if (!registered("sicklms200")) GTEST_SKIP() << "sicklms200 is not built yet";
  emulators::EmulatorRunner laser(families::builtin_families().emulator_catalog().make("sicklms200", {}), emulators::PtyEndpoint{});
  auto line = line_of({"sicklms200", "port=" + laser.device_path()});
  line.count = 2;
  line.format = "json";
  line.trace = true;
  line.stats = true;
  const Outcome outcome = run(line);
  EXPECT_EQ(outcome.status, kExitOk) << outcome.err;
  const auto lines = json_lines(outcome.out);
  ASSERT_EQ(lines.size(), 2u) << outcome.out;
  EXPECT_EQ(lines[0]["device"], "laser");
  // The installation-mode request, framed, host to laser.
  EXPECT_TRUE(contains(outcome.err, "trace laser:0 ")) << outcome.err;
  EXPECT_TRUE(contains(outcome.err, " > 02 00 0A 00 20 00 53 49 43 4B 5F 4C 4D 53")) << outcome.err;
}

TEST(RunSession, ADriverThatCannotSetUpSaysWhyOnce) {
  if (!registered("sicklms200")) GTEST_SKIP() << "sicklms200 is not built yet";
  const std::string missing = scratch("no-such-port").string();
  auto line = line_of({"sicklms200", "port=" + missing});
  line.count = 1;
  const Outcome outcome = run(line);
  EXPECT_EQ(outcome.status, kExitFailure);
  EXPECT_TRUE(contains(outcome.err, "player-drivers: error: laser:0 (sicklms200): setup failed: no such port " + missing))
      << outcome.err;
  // player-cat's own account of the refusal adds nothing to that line.
  EXPECT_FALSE(contains(outcome.err, "could not be opened")) << outcome.err;
  EXPECT_FALSE(contains(outcome.err, "player-cat")) << outcome.err;
}

TEST(RunSession, APioneerFamilyOnAnEmulatorWhenItsDriversAreBuilt) {
  if (!registered("p2os_position")) GTEST_SKIP() << "the p2os drivers are not built yet";
  emulators::EmulatorRunner robot(families::builtin_families().emulator_catalog().make("p2os", {}), emulators::PtyEndpoint{});
  auto line = line_of({"p2os", "port=" + robot.device_path()});
  line.device = "position:0";
  line.count = 2;
  line.format = "json";
  const Outcome outcome = run(line);
  EXPECT_EQ(outcome.status, kExitOk) << outcome.err;
  const auto lines = json_lines(outcome.out);
  ASSERT_EQ(lines.size(), 2u) << outcome.out;
  EXPECT_EQ(lines[0]["device"], "position");
  EXPECT_EQ(lines[0]["index"], 0);
}

}  // namespace run_session_test
}  // namespace playerkit::player_drivers
