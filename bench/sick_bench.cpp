// The sicklms200 driver at full speed: an emulated LMS 200 on a real
// pseudo-terminal at 500000 baud streaming 361 values (180 deg at 0.5 deg)
// as fast as the line carries them, for a bounded time.
//
//   ./build/bench/sick_bench                 # 5 s at 500000 baud, 0.5 deg
//   ./build/bench/sick_bench --seconds 10 --resolution 100
//
// Everything runs in this process: the emulator in the EmulatorRunner's
// thread, the driver in its own thread, this thread waiting. Figures:
//
//  * scans delivered out of sent: telegrams the emulator handed to its
//    runner while the device was subscribed, and how many of them were
//    published. The emulator paces itself at the line rate (732 bytes x
//    10 bits at 500000 baud: 14.6 ms, 68.3 scans/s; its mirror would allow
//    75/s), so this is what a real LMS 200 on a 500 kbaud line delivers.
//  * driver thread CPU per scan: CLOCK_THREAD_CPUTIME_ID read inside the
//    DeviceListener, which the driver's thread calls right after each
//    publish, so it measures that thread alone (the listener's few
//    instructions included), between the first and the last scan.
//  * latency: from the emulator handing a scan telegram to its runner (which
//    writes it next, with one write()) to the sample being published, as
//    seen by the listener. Scans are matched by their values (seeded range
//    noise makes each one different), not by order, so a lost scan cannot
//    shift the others. Also split at the driver's byte trace: the emulator to
//    the read that completed the telegram (the pty and the thread waking
//    up), and that read to the publish (framing, CRC, conversion, publish).
//
// No assertions: this prints figures. Machine load (other builds) shows in
// the latency tail.

#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <mutex>
#include <numeric>
#include <string>
#include <thread>
#include <vector>

#include <CLI/CLI.hpp>

#include "algorithms/grid/occupancy_grid.hpp"
#include "config/config_file.hpp"
#include "core/server_clock.hpp"
#include "core/clock.hpp"
#include "core/device.hpp"
#include "core/device_table.hpp"
#include "core/driver_registry.hpp"
#include "core/instantiate.hpp"
#include "core/logger.hpp"
#include "families/sick/driver/sicklms200_driver.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "families/sick/emulator/sick_lms200_emulator.hpp"
#include "families/sick/protocol/scan.hpp"
#include "families/sick/protocol/telegram.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/laser.hpp"

namespace {

using namespace playerkit;
using SteadyClock = std::chrono::steady_clock;
namespace sick = hardware::sick;

constexpr std::uint16_t kPort = 6665;

// A fingerprint of a scan's distances, the same from the telegram's values
// and from the published millimetres (range_res 1: the same numbers).
std::uint64_t fingerprint(const std::vector<std::uint16_t>& distances) {
  std::uint64_t hash = 1469598103934665603ull;
  for (const std::uint16_t d : distances) {
    hash = (hash ^ d) * 1099511628211ull;
  }
  return hash;
}

// The LMS 200 emulator, noting when each scan telegram leaves it.
class TimedLaser final : public emulators::DeviceEmulator {
 public:
  explicit TimedLaser(emulators::SickEmulatorOptions options) : inner_(std::move(options)) {}

  void receive(std::span<const std::uint8_t> bytes, emulators::Duration now, int host_baud) override {
    inner_.receive(bytes, now, host_baud);
  }
  void advance(emulators::Duration now) override { inner_.advance(now); }
  [[nodiscard]] emulators::Duration next_deadline() const override { return inner_.next_deadline(); }
  std::vector<emulators::Telegram> take_output() override {
    auto output = inner_.take_output();
    const auto now = SteadyClock::now();
    for (const auto& telegram : output) {
      if (!telegram.has_checksum || telegram.bytes.size() < 5) continue;
      const std::uint8_t code = telegram.bytes[4];
      if (code != sick::kScanReply && code != sick::kSubrangeScanReply) continue;
      const sick::Scan scan = sick::parse_scan(sick::unframe_reply(telegram.bytes));
      std::vector<std::uint16_t> distances;
      distances.reserve(scan.values.size());
      for (const auto value : scan.values) distances.push_back(sick::distance_of(value));
      sent_.push_back({fingerprint(distances), now, telegram.bytes.size()});
    }
    return output;
  }
  void host_disconnected(emulators::Duration now) override { inner_.host_disconnected(now); }
  [[nodiscard]] int baud() const override { return inner_.baud(); }
  [[nodiscard]] std::string describe() const override { return inner_.describe(); }

  struct Sent {
    std::uint64_t fingerprint;
    SteadyClock::time_point at;
    std::size_t bytes;
  };
  std::vector<Sent> sent_;  // under the runner's lock (with_emulator)

 private:
  emulators::SickLms200Emulator inner_;
};

// Called by the driver's thread after each publish: the time, that thread's
// CPU clock, and the sample (decoded after the run, not here).
class PublishRecorder final : public core::DeviceListener {
 public:
  struct Published {
    SteadyClock::time_point at;
    std::chrono::nanoseconds thread_cpu;
    std::shared_ptr<const core::DataSample> sample;
  };

  void data_published(const core::Device& device) override {
    timespec cpu{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &cpu);
    const auto now = SteadyClock::now();
    auto sample = device.latest_data();
    std::lock_guard lock(mutex_);
    published_.push_back({now, std::chrono::seconds(cpu.tv_sec) + std::chrono::nanoseconds(cpu.tv_nsec),
                          std::move(sample)});
  }
  void replies_ready(const core::Device&) override {}

  std::vector<Published> take() {
    std::lock_guard lock(mutex_);
    return std::move(published_);
  }

 private:
  std::mutex mutex_;
  std::vector<Published> published_;
};

// Times the driver's link read bytes: the end of each read, with the total
// read so far, to find the read that completed a telegram.
class ReadTimes {
 public:
  void add(std::size_t count, SteadyClock::time_point at) {
    std::lock_guard lock(mutex_);
    total_ += count;
    reads_.push_back({total_, at});
  }
  struct Read {
    std::uint64_t total;
    SteadyClock::time_point at;
  };
  std::vector<Read> take() {
    std::lock_guard lock(mutex_);
    return std::move(reads_);
  }

 private:
  std::mutex mutex_;
  std::uint64_t total_ = 0;
  std::vector<Read> reads_;
};

grid::OccupancyGrid box_room() {
  // 8 m x 6 m of 5 cm cells, walls on the border.
  grid::OccupancyGrid room(160, 120, 0.05, Eigen::Vector2d::Zero(), grid::CellState::free);
  for (int c = 0; c < 160; ++c) {
    room.set(c, 0, grid::CellState::occupied);
    room.set(c, 119, grid::CellState::occupied);
  }
  for (int r = 0; r < 120; ++r) {
    room.set(0, r, grid::CellState::occupied);
    room.set(159, r, grid::CellState::occupied);
  }
  return room;
}

double percentile(std::vector<double> values, double p) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const auto index = static_cast<std::size_t>(p / 100.0 * static_cast<double>(values.size() - 1) + 0.5);
  return values[std::min(index, values.size() - 1)];
}

double microseconds(SteadyClock::duration d) {
  return std::chrono::duration<double, std::micro>(d).count();
}

void print_latency(const char* name, const std::vector<double>& us) {
  std::printf("  %-34s p50 %8.1f us   p99 %8.1f us   max %8.1f us   (%zu scans)\n", name, percentile(us, 50),
              percentile(us, 99), us.empty() ? 0.0 : *std::max_element(us.begin(), us.end()), us.size());
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"sicklms200 driver against an emulated LMS 200 on a pty"};
  double seconds = 5.0;
  int rate = 500000;
  int resolution = 50;
  app.add_option("--seconds", seconds, "measured time")->check(CLI::Range(0.5, 600.0));
  app.add_option("--rate", rate, "line speed")->check(CLI::IsMember({9600, 38400, 500000}));
  app.add_option("--resolution", resolution, "0.01 deg: 50 (361 values) or 100 (181)")
      ->check(CLI::IsMember({50, 100}));
  CLI11_PARSE(app, argc, argv);

  const grid::OccupancyGrid room = box_room();
  emulators::SickEmulatorOptions laser_options;
  laser_options.map = &room;
  laser_options.pose = {3.0, 2.5, 0.3};
  laser_options.range_noise_sigma_m = 0.01;  // every scan different: matched by value
  laser_options.power_up_baud = 38400;
  auto laser = std::make_unique<TimedLaser>(laser_options);
  emulators::EmulatorRunner runner(std::move(laser), emulators::PtyEndpoint{});

  core::ServerClock clock;  // the wall clock: no driver here claims it
  core::Logger logger("sick_bench");
  logger.set_level(core::LogLevel::kWarning);
  core::DriverRegistry registry;
  registry.add(drivers::sicklms200_driver_spec());
  core::DeviceTable devices;
  const std::string text = "laser:0 ( driver \"sicklms200\" port \"" + runner.device_path() + "\" rate " +
                           std::to_string(rate) + " resolution " + std::to_string(resolution) + " )\n";
  const auto config = config::ConfigFile::parse(text, "bench.cfg", core::load_options_for(registry, kPort));
  core::instantiate_devices(config, registry, devices, clock, logger);
  core::Device& device = *devices.find(kPort, {protocol::kLaserCode, 0});

  ReadTimes reads;
  device.driver().set_byte_trace([&](bool outgoing, std::span<const std::uint8_t> bytes, SteadyClock::time_point when) {
    if (!outgoing) reads.add(bytes.size(), when);
  });
  PublishRecorder recorder;
  device.add_listener(&recorder);

  const auto setup_start = SteadyClock::now();
  if (!device.subscribe()) {
    std::cerr << "sick_bench: the driver did not set up (see the log above)\n";
    return 1;
  }
  const auto setup_time = SteadyClock::now() - setup_start;
  const std::size_t sent_before =
      runner.with_emulator<TimedLaser>([](TimedLaser& l) { return l.sent_.size(); });
  std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
  const auto counters = device.driver().counters();
  device.unsubscribe();
  device.remove_listener(&recorder);
  device.driver().set_byte_trace({});

  const auto sent = runner.with_emulator<TimedLaser>([](TimedLaser& l) { return l.sent_; });
  const auto published = recorder.take();
  const auto read_list = reads.take();

  // Telegram bytes before the first scan of the window, to place each
  // scan's last byte in the driver's cumulative read count.
  std::map<std::uint64_t, std::size_t> by_fingerprint;
  for (std::size_t i = sent_before; i < sent.size(); ++i) by_fingerprint[sent[i].fingerprint] = i;

  std::vector<double> total_us;
  std::vector<double> line_us;
  std::vector<double> driver_us;
  std::size_t matched = 0;
  for (const auto& p : published) {
    const auto data = protocol::decode<protocol::LaserData>(p.sample->payload);
    std::vector<std::uint16_t> ranges(data.ranges.begin(), data.ranges.begin() + data.range_count);
    const auto found = by_fingerprint.find(fingerprint(ranges));
    if (found == by_fingerprint.end()) continue;
    ++matched;
    const auto& s = sent[found->second];
    total_us.push_back(microseconds(p.at - s.at));
    // The read that completed this telegram: the first read after the
    // emulator sent it whose end lies at or past the telegram's size worth
    // of bytes since the last read before it was sent.
    const auto after = std::find_if(read_list.begin(), read_list.end(), [&](const auto& r) { return r.at >= s.at; });
    if (after == read_list.end()) continue;
    const std::uint64_t start = after == read_list.begin() ? 0 : std::prev(after)->total;
    const auto done = std::find_if(after, read_list.end(), [&](const auto& r) { return r.total >= start + s.bytes; });
    if (done == read_list.end() || done->at > p.at) continue;
    line_us.push_back(microseconds(done->at - s.at));
    driver_us.push_back(microseconds(p.at - done->at));
  }

  const std::size_t window_sent = sent.size() - sent_before;
  const double cpu_per_scan_us =
      published.size() < 2
          ? 0.0
          : std::chrono::duration<double, std::micro>(published.back().thread_cpu - published.front().thread_cpu)
                    .count() /
                static_cast<double>(published.size() - 1);
  const double span_s =
      published.size() < 2 ? 0.0
                           : std::chrono::duration<double>(published.back().at - published.front().at).count();

  const int values = resolution == 50 ? 361 : 181;
  const double telegram_bytes = static_cast<double>(sick::scan_telegram_size(static_cast<std::size_t>(values)));
  std::printf("sicklms200 on a pty at %d baud, %d values (180 deg at %.1f deg), %.1f s\n", rate, values,
              resolution / 100.0, seconds);
  std::printf("  setup (find, switch to %d, type, variant, configuration, stream): %.0f ms\n", rate,
              std::chrono::duration<double, std::milli>(setup_time).count());
  const double line_rate = rate / (telegram_bytes * 10.0);
  std::printf("  pacing: the line carries %.0f bytes x 10 bits / %d baud = %.1f scans/s, the mirror 75/s;\n"
              "          the emulator sends at the slower, %.1f scans/s\n",
              telegram_bytes, rate, line_rate, std::min(line_rate, 75.0));
  std::printf("  scans sent %zu, published %zu, matched to a sent one %zu (%.1f scans/s published)\n", window_sent,
              published.size(), matched, span_s > 0 ? static_cast<double>(published.size() - 1) / span_s : 0.0);
  std::printf("  driver thread CPU: %.1f us per scan (%.2f %% of one core at this rate)\n", cpu_per_scan_us,
              span_s > 0 ? cpu_per_scan_us * static_cast<double>(published.size() - 1) / (span_s * 1e4) : 0.0);
  print_latency("latency, emulator -> published", total_us);
  print_latency("  emulator -> telegram read", line_us);
  print_latency("  telegram read -> published", driver_us);
  std::printf("  link:");
  for (const auto& c : counters) std::printf(" %s %llu", c.name.c_str(), static_cast<unsigned long long>(c.value));
  std::printf("\n");
  return 0;
}
