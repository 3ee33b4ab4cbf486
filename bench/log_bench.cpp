// Throughput of lib/log: Player text logs and CARMEN logs, read and written, in
// MB/s of log text (bytes_per_second), on one core.
//
//   ./build/bench/log_bench --benchmark_counters_tabular=true
//   ./build/bench/log_bench --log_mb=16         # smaller logs (default 64 MB each)
//
// The logs are generated once, in memory, before anything is timed: a Player
// 0.0.0 log of 10 Hz cycles (a 361-beam laser scan, a position line and a sync
// line each), once with 6-decimal times (the writer's default) and once with 3
// (byte-exact 1.5), and a CARMEN log of FLASER + ODOM pairs. The values follow
// a robot driving through a corridor-sized room, so the numbers have the digit
// counts of real logs. Each benchmark iteration is one whole pass over a log,
// and every benchmark stops after --benchmark_min_time (or kMinSeconds).
//
// The gzip benchmarks write the 6-decimal Player log to a temporary file, plain
// and gzip-compressed (zlib, default level), and read it through open_log_input;
// their bytes are the uncompressed text, so they compare with the in-memory
// figures directly.

#include <benchmark/benchmark.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <numbers>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "log/carmen_log.hpp"
#include "log/carmen_log_reader.hpp"
#include "log/carmen_log_writer.hpp"
#include "log/log_input.hpp"
#include "log/text_log_reader.hpp"
#include "log/text_log_writer.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/message.hpp"
#include "protocol/messages/laser.hpp"
#include "protocol/messages/position.hpp"

namespace playerkit::log {
namespace {

constexpr double kMinSeconds = 2.0;
constexpr const char* kHost = "robot1";
constexpr std::uint16_t kPort = 6665;
constexpr std::size_t kBeams = 361;
constexpr double kCycleSeconds = 0.1;
constexpr std::uint32_t kStartSecond = 1086000000;

std::size_t target_bytes = std::size_t{64} << 20;

// One step of the generated run: where the robot is and what its laser sees.
// The room is 12 m x 6 m; walls give 0.3-10 m ranges, a few beams are "no
// return" (8.183 m, the SICK LMS's max as 1.5 logs show it) and a few hit
// reflectors (intensity 1-3).
struct RobotState {
  double time = kStartSecond + 0.25;
  double x = 2.0;
  double y = 3.0;
  double theta = 0.0;
  double speed = 0.35;
  double turn_rate = 0.05;
  std::array<double, kBeams> ranges{};
  std::array<std::uint8_t, kBeams> intensity{};
};

class RunGenerator {
 public:
  RunGenerator() : random_(20261121) {}

  const RobotState& step() {
    // Microsecond jitter keeps the 6-decimal times from ending in zeros.
    state_.time += kCycleSeconds + jitter_(random_) * 1e-6;
    state_.turn_rate = std::clamp(state_.turn_rate + noise_(random_) * 0.02, -0.4, 0.4);
    state_.theta = std::remainder(state_.theta + state_.turn_rate * kCycleSeconds, 2 * std::numbers::pi);
    state_.x = std::clamp(state_.x + state_.speed * kCycleSeconds * std::cos(state_.theta), 0.5, 11.5);
    state_.y = std::clamp(state_.y + state_.speed * kCycleSeconds * std::sin(state_.theta), 0.5, 5.5);
    for (std::size_t i = 0; i < kBeams; ++i) {
      const double bearing = state_.theta + (static_cast<double>(i) * 0.5 - 90.0) * std::numbers::pi / 180.0;
      const double range = distance_to_wall(bearing) + noise_(random_) * 0.01;
      const bool no_return = unit_(random_) < 0.02;
      state_.ranges[i] = no_return ? 8.183 : std::clamp(range, 0.3, 8.0);
      state_.intensity[i] = unit_(random_) < 0.05 ? static_cast<std::uint8_t>(1 + i % 3) : 0;
    }
    return state_;
  }

 private:
  double distance_to_wall(double bearing) const {
    const double dx = std::cos(bearing);
    const double dy = std::sin(bearing);
    double best = 100.0;
    if (dx > 1e-9) best = std::min(best, (12.0 - state_.x) / dx);
    if (dx < -1e-9) best = std::min(best, -state_.x / dx);
    if (dy > 1e-9) best = std::min(best, (6.0 - state_.y) / dy);
    if (dy < -1e-9) best = std::min(best, -state_.y / dy);
    return best;
  }

  std::mt19937 random_;
  std::normal_distribution<double> noise_{0.0, 1.0};
  std::uniform_real_distribution<double> unit_{0.0, 1.0};
  std::uniform_int_distribution<int> jitter_{-900, 900};
  RobotState state_;
};

protocol::Message data_message(std::uint16_t interface_code, double time,
                               std::vector<std::uint8_t> payload) {
  const auto stamp = protocol::Timestamp::from_seconds(time);
  protocol::Message message;
  message.header = protocol::make_header(protocol::MessageType::kData, {interface_code, 0}, stamp, stamp);
  message.payload = std::move(payload);
  message.header.size = static_cast<std::uint32_t>(message.payload.size());
  return message;
}

protocol::Message laser_message(const RobotState& state) {
  protocol::LaserData scan;
  scan.min_angle = -9000;
  scan.max_angle = 9000;
  scan.resolution = 50;
  scan.range_res = 1;
  scan.range_count = kBeams;
  for (std::size_t i = 0; i < kBeams; ++i) {
    scan.ranges[i] = static_cast<std::uint16_t>(std::lround(state.ranges[i] * 1000.0));
    scan.intensity[i] = state.intensity[i];
  }
  return data_message(protocol::kLaserCode, state.time, protocol::encode(scan));
}

protocol::Message position_message(const RobotState& state) {
  protocol::PositionData odometry;
  odometry.xpos = static_cast<std::int32_t>(std::lround(state.x * 1000.0));
  odometry.ypos = static_cast<std::int32_t>(std::lround(state.y * 1000.0));
  odometry.yaw = static_cast<std::int32_t>(std::lround(state.theta * 180.0 / std::numbers::pi));
  odometry.xspeed = static_cast<std::int32_t>(std::lround(state.speed * 1000.0));
  odometry.yawspeed = static_cast<std::int32_t>(std::lround(state.turn_rate * 180.0 / std::numbers::pi));
  return data_message(protocol::kPositionCode, state.time + 0.004, protocol::encode(odometry));
}

// What a writer is handed: the messages of one run, in order, and its sync times.
struct PlayerRun {
  std::vector<protocol::Message> messages;  // laser, position, laser, position, ...
  std::vector<protocol::Timestamp> sync_times;  // one after each pair
};

PlayerRun make_player_run(std::size_t cycles) {
  PlayerRun run;
  RunGenerator generator;
  run.messages.reserve(2 * cycles);
  run.sync_times.reserve(cycles);
  for (std::size_t i = 0; i < cycles; ++i) {
    const RobotState& state = generator.step();
    run.messages.push_back(laser_message(state));
    run.messages.push_back(position_message(state));
    run.sync_times.push_back(protocol::Timestamp::from_seconds(state.time + 0.01));
  }
  return run;
}

std::string write_player_log(const PlayerRun& run, int time_decimals) {
  const TextLogWriterOptions options{.time_decimals = time_decimals};
  std::string text = log_file_header(options);
  for (std::size_t i = 0; i < run.sync_times.size(); ++i) {
    text += format_data_line(run.messages[2 * i], kHost, kPort, options);
    text += format_data_line(run.messages[2 * i + 1], kHost, kPort, options);
    text += format_sync_line(run.sync_times[i], kHost, kPort, options);
  }
  return text;
}

std::vector<CarmenRecord> make_carmen_run(std::size_t cycles) {
  std::vector<CarmenRecord> records;
  records.reserve(2 * cycles);
  RunGenerator generator;
  const double start = kStartSecond;
  for (std::size_t i = 0; i < cycles; ++i) {
    const RobotState& state = generator.step();
    const CarmenPose pose{state.x, state.y, state.theta};
    CarmenOdometry odometry;
    odometry.pose = pose;
    odometry.tv = state.speed;
    odometry.rv = state.turn_rate;
    odometry.stamp = {state.time, "nebula", state.time - start};
    CarmenLaser laser;
    laser.kind = CarmenLaserKind::kFlaser;
    laser.ranges.assign(state.ranges.begin(), state.ranges.end());
    laser.laser_pose = pose;
    laser.robot_pose = pose;
    laser.stamp = {state.time + 0.004, "nebula", state.time + 0.004 - start};
    records.emplace_back(std::move(odometry));
    records.emplace_back(std::move(laser));
  }
  return records;
}

std::string write_carmen_log(const std::vector<CarmenRecord>& records) {
  std::string text = carmen_log_header();
  for (const auto& record : records) {
    if (const auto* odometry = std::get_if<CarmenOdometry>(&record)) text += format_odom(*odometry);
    if (const auto* laser = std::get_if<CarmenLaser>(&record)) text += format_flaser(*laser);
  }
  return text;
}

// Cycles whose 6-decimal Player text comes to about target_bytes.
std::size_t player_cycles() {
  const PlayerRun sample = make_player_run(100);
  return std::max<std::size_t>(1, target_bytes * 100 / write_player_log(sample, 6).size());
}

std::size_t carmen_cycles() {
  return std::max<std::size_t>(1, target_bytes * 100 / write_carmen_log(make_carmen_run(100)).size());
}

// Everything the benchmarks read, made once on first use.
struct Corpus {
  PlayerRun player_run;
  std::string player_log_6;
  std::string player_log_3;
  std::vector<CarmenRecord> carmen_run;
  std::string carmen_log;
  std::filesystem::path plain_file;
  std::filesystem::path gzip_file;

  const std::string& player_log(std::int64_t decimals) const {
    return decimals == 3 ? player_log_3 : player_log_6;
  }
};

void write_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

void write_gzip_file(const std::filesystem::path& path, const std::string& text) {
  gzFile file = gzopen(path.c_str(), "wb");
  if (file == nullptr) throw std::runtime_error("cannot open " + path.string() + " for gzip");
  constexpr std::size_t kChunk = std::size_t{1} << 20;
  for (std::size_t done = 0; done < text.size(); done += kChunk) {
    const auto length = static_cast<unsigned>(std::min(kChunk, text.size() - done));
    if (gzwrite(file, text.data() + done, length) != static_cast<int>(length)) {
      gzclose(file);
      throw std::runtime_error("gzwrite failed on " + path.string());
    }
  }
  if (gzclose(file) != Z_OK) throw std::runtime_error("gzclose failed on " + path.string());
}

double megabytes(std::uintmax_t bytes) { return static_cast<double>(bytes) / 1e6; }

Corpus make_corpus() {
  Corpus corpus;
  corpus.player_run = make_player_run(player_cycles());
  corpus.player_log_6 = write_player_log(corpus.player_run, 6);
  corpus.player_log_3 = write_player_log(corpus.player_run, 3);
  corpus.carmen_run = make_carmen_run(carmen_cycles());
  corpus.carmen_log = write_carmen_log(corpus.carmen_run);
  const auto directory = std::filesystem::temp_directory_path();
  const std::string stem = "playerkit-log-bench-" + std::to_string(::getpid());
  corpus.plain_file = directory / (stem + ".log");
  corpus.gzip_file = directory / (stem + ".log.gz");
  write_file(corpus.plain_file, corpus.player_log_6);
  write_gzip_file(corpus.gzip_file, corpus.player_log_6);
  std::cerr << "log_bench: Player log " << corpus.player_run.sync_times.size() << " cycles, "
            << megabytes(corpus.player_log_6.size()) << " MB (6 decimals), "
            << megabytes(corpus.player_log_3.size()) << " MB (3 decimals); gzip "
            << megabytes(std::filesystem::file_size(corpus.gzip_file)) << " MB; CARMEN log "
            << corpus.carmen_run.size() << " records, " << megabytes(corpus.carmen_log.size()) << " MB\n";
  return corpus;
}

const Corpus& corpus() {
  static const Corpus made = make_corpus();
  return made;
}

// Lines as the reader sees them (with their '\n'), split outside the timed loop.
std::vector<std::string_view> split_lines(const std::string& text) {
  std::vector<std::string_view> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = text.find('\n', start);
    const std::size_t stop = end == std::string::npos ? text.size() : end + 1;
    lines.emplace_back(text.data() + start, stop - start);
    start = stop;
  }
  return lines;
}

void set_bytes(benchmark::State& state, std::size_t bytes_per_pass) {
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(bytes_per_pass));
}

// The whole log through TextLogReader, as player-log and readlog read it.
void BM_TextLogReader(benchmark::State& state) {
  const std::string& text = corpus().player_log(state.range(0));
  std::istringstream in(text);
  std::size_t lines = 0;
  for (auto _ : state) {
    in.clear();
    in.seekg(0);
    TextLogReader reader(in, "bench.log");
    while (auto line = reader.next()) {
      benchmark::DoNotOptimize(&*line);
      ++lines;
    }
    if (reader.malformed_count() != 0) state.SkipWithError("generated log has malformed lines");
  }
  set_bytes(state, text.size());
  state.counters["lines/s"] = benchmark::Counter(static_cast<double>(lines), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_TextLogReader)->ArgName("decimals")->Arg(6)->Arg(3)->MinTime(kMinSeconds)->Unit(benchmark::kMillisecond);

// parse_log_line alone over lines already split: the reader minus its stream.
void BM_ParseLogLine(benchmark::State& state) {
  const std::string& text = corpus().player_log(state.range(0));
  const auto lines = split_lines(text);
  for (auto _ : state) {
    int number = 0;
    for (const auto line : lines) {
      auto parsed = parse_log_line(line, "bench.log", ++number);
      benchmark::DoNotOptimize(&parsed);
    }
  }
  set_bytes(state, text.size());
}
BENCHMARK(BM_ParseLogLine)->ArgName("decimals")->Arg(6)->Arg(3)->MinTime(kMinSeconds)->Unit(benchmark::kMillisecond);

// One kind of line at a time (laser, position, sync), to see which one costs.
void parse_lines_of_kind(benchmark::State& state, std::string_view marker) {
  std::vector<std::string_view> lines;
  std::size_t bytes = 0;
  for (const auto line : split_lines(corpus().player_log_6)) {
    if (line.find(marker) != std::string_view::npos) {
      lines.push_back(line);
      bytes += line.size();
    }
  }
  for (auto _ : state) {
    for (const auto line : lines) {
      auto parsed = parse_log_line(line, "bench.log", 1);
      benchmark::DoNotOptimize(&parsed);
    }
  }
  set_bytes(state, bytes);
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(lines.size()));
}
void BM_ParseLaserLines(benchmark::State& state) { parse_lines_of_kind(state, " laser 00 "); }
void BM_ParsePositionLines(benchmark::State& state) { parse_lines_of_kind(state, " position 00 "); }
void BM_ParseSyncLines(benchmark::State& state) { parse_lines_of_kind(state, " sync 00 "); }
BENCHMARK(BM_ParseLaserLines)->MinTime(kMinSeconds)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ParsePositionLines)->MinTime(kMinSeconds)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ParseSyncLines)->MinTime(kMinSeconds)->Unit(benchmark::kMillisecond);

// format_data_line + format_sync_line for the whole run, into a reused string
// (as writelog does, minus the file).
void BM_FormatPlayerLog(benchmark::State& state) {
  const PlayerRun& run = corpus().player_run;
  const TextLogWriterOptions options{.time_decimals = static_cast<int>(state.range(0))};
  std::size_t bytes = 0;
  std::string out;
  for (auto _ : state) {
    bytes = 0;
    for (std::size_t i = 0; i < run.sync_times.size(); ++i) {
      out = format_data_line(run.messages[2 * i], kHost, kPort, options);
      bytes += out.size();
      out = format_data_line(run.messages[2 * i + 1], kHost, kPort, options);
      bytes += out.size();
      out = format_sync_line(run.sync_times[i], kHost, kPort, options);
      bytes += out.size();
      benchmark::DoNotOptimize(out.data());
    }
  }
  set_bytes(state, bytes);
}
BENCHMARK(BM_FormatPlayerLog)->ArgName("decimals")->Arg(6)->Arg(3)->MinTime(kMinSeconds)->Unit(benchmark::kMillisecond);

void BM_CarmenLogReader(benchmark::State& state) {
  const std::string& text = corpus().carmen_log;
  std::istringstream in(text);
  for (auto _ : state) {
    in.clear();
    in.seekg(0);
    CarmenLogReader reader(in, "bench.carmen");
    while (auto record = reader.next()) benchmark::DoNotOptimize(&*record);
    if (reader.malformed_lines() != 0) state.SkipWithError("generated CARMEN log has malformed lines");
  }
  set_bytes(state, text.size());
}
BENCHMARK(BM_CarmenLogReader)->MinTime(kMinSeconds)->Unit(benchmark::kMillisecond);

void BM_FormatCarmenLog(benchmark::State& state) {
  const auto& records = corpus().carmen_run;
  std::size_t bytes = 0;
  std::string out;
  for (auto _ : state) {
    bytes = 0;
    for (const auto& record : records) {
      if (const auto* odometry = std::get_if<CarmenOdometry>(&record)) out = format_odom(*odometry);
      if (const auto* laser = std::get_if<CarmenLaser>(&record)) out = format_flaser(*laser);
      bytes += out.size();
      benchmark::DoNotOptimize(out.data());
    }
  }
  set_bytes(state, bytes);
}
BENCHMARK(BM_FormatCarmenLog)->MinTime(kMinSeconds)->Unit(benchmark::kMillisecond);

// open_log_input alone: the bytes of the file, plain or gzip, read in blocks.
void BM_LogInputRead(benchmark::State& state) {
  const bool gzip = state.range(0) != 0;
  const auto& path = gzip ? corpus().gzip_file : corpus().plain_file;
  std::vector<char> block(std::size_t{1} << 16);
  std::size_t bytes = 0;
  for (auto _ : state) {
    bytes = 0;
    auto in = open_log_input(path);
    while (in->read(block.data(), static_cast<std::streamsize>(block.size())) || in->gcount() > 0) {
      bytes += static_cast<std::size_t>(in->gcount());
      if (in->eof()) break;
    }
    if (in->error()) state.SkipWithError(in->error()->c_str());
  }
  set_bytes(state, bytes);
}
BENCHMARK(BM_LogInputRead)->ArgName("gzip")->Arg(0)->Arg(1)->MinTime(kMinSeconds)->Unit(benchmark::kMillisecond);

// The whole Player log from the file through open_log_input and TextLogReader:
// what player-log info pays on a .log and a .log.gz.
void BM_TextLogReaderFromFile(benchmark::State& state) {
  const bool gzip = state.range(0) != 0;
  const auto& path = gzip ? corpus().gzip_file : corpus().plain_file;
  for (auto _ : state) {
    auto in = open_log_input(path);
    TextLogReader reader(*in, path.string());
    while (auto line = reader.next()) benchmark::DoNotOptimize(&*line);
    if (reader.malformed_count() != 0 || in->error()) state.SkipWithError("file read with errors");
  }
  set_bytes(state, corpus().player_log_6.size());
}
BENCHMARK(BM_TextLogReaderFromFile)->ArgName("gzip")->Arg(0)->Arg(1)->MinTime(kMinSeconds)->Unit(benchmark::kMillisecond);

// Takes "--log_mb=N" out of argv (Google Benchmark refuses flags it does not know).
void take_own_flags(int& argc, char** argv) {
  constexpr std::string_view kFlag = "--log_mb=";
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg.starts_with(kFlag)) {
      const long megabytes = std::strtol(argv[i] + kFlag.size(), nullptr, 10);
      if (megabytes < 1 || megabytes > 4096) {
        std::cerr << "log_bench: --log_mb wants 1..4096, got '" << arg.substr(kFlag.size()) << "'\n";
        std::exit(2);
      }
      target_bytes = static_cast<std::size_t>(megabytes) << 20;
    } else {
      argv[kept++] = argv[i];
    }
  }
  argc = kept;
}

}  // namespace
}  // namespace playerkit::log

int main(int argc, char** argv) {
  playerkit::log::take_own_flags(argc, argv);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  // The corpus exists only if a benchmark ran (not with --benchmark_list_tests).
  std::error_code ignored;
  const auto directory = std::filesystem::temp_directory_path();
  const std::string stem = "playerkit-log-bench-" + std::to_string(::getpid());
  std::filesystem::remove(directory / (stem + ".log"), ignored);
  std::filesystem::remove(directory / (stem + ".log.gz"), ignored);
  return 0;
}
