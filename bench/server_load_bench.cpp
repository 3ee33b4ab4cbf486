// Load on the TCP server: N clients x M devices x F Hz over loopback.
//
//   ./build/bench/server_load_bench                      # 100 clients x 4 lasers x 100 Hz, 10 s
//   ./build/bench/server_load_bench --clients 50 --json
//   ./build/bench/server_load_bench --clients 1000 --devices 1 --mode push-all    # fan-out
//   ./build/bench/server_load_bench --clients 1000 --devices 1 --seconds 600 --latency-samples 1000 --memory-every 10
//                                                                                 # a soak: RSS every 10 s
//
// The server, its drivers and the clients all run in this one process:
//
//  * M "bench-source" laser devices, each a ThreadedDriver publishing --payload
//    bytes every 1/--rate s (absolute deadlines), stamped with the wall clock.
//    The first 8 payload bytes carry a big-endian sequence number so that the
//    clients can tell samples they never got (overwritten before a round took
//    them) from samples that were simply not due yet.
//  * the server (playerkit::server::Server) on 127.0.0.1, port picked at run
//    time, in a thread of its own;
//  * N clients on one Boost.Asio io_context (--client-threads threads): each
//    reads the banner, asks DATAFREQ --client-frequency, opens laser:0..M-1 for
//    'r' and then only reads (--mode: PUSH_NEW, the default mode, or PUSH_ALL). Connects are spread
//    over one client period (--no-stagger: all at once), since each client's
//    rounds keep the phase of its connect.
//
// After every client has its devices, a 1 s warm-up, then --seconds measured:
// DATA and SYNCH messages received, latency = client receive time (wall clock)
// - header timestamp (when the driver published), split into "in the server"
// (header time, i.e. when the round was built, - timestamp) and "on the wire"
// (receive - header time); CPU time of the server's event-loop thread, of the
// driver threads, of the client threads and of the whole process; how the
// clients' rounds are spread over the period (SYNCH header times), since that
// moves both latency and server CPU. The clients share the machine's cores
// with the server: on a small machine they compete.
//
// Results and how to read them: docs/benchmarks/2026-11-21-server-load.md.

#include <pthread.h>
#include <sys/resource.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <CLI/CLI.hpp>
#include <boost/asio/buffer.hpp>
#include <boost/asio/connect.hpp>
#include <boost/asio/executor_work_guard.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/asio/strand.hpp>
#include <boost/asio/write.hpp>
#include <nlohmann/json.hpp>

#include "config/config_file.hpp"
#include "core/server_clock.hpp"
#include "core/clock.hpp"
#include "core/device_table.hpp"
#include "core/driver.hpp"
#include "core/driver_registry.hpp"
#include "core/instantiate.hpp"
#include "core/logger.hpp"
#include "protocol/constants.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/message.hpp"
#include "server/server.hpp"

namespace {

namespace asio = boost::asio;
using asio::ip::tcp;
using namespace playerkit;
using SteadyClock = std::chrono::steady_clock;

// ------------------------------------------------------------------ options

struct Options {
  unsigned clients = 100;
  unsigned devices = 4;
  double rate = 100.0;
  unsigned client_frequency = 0;  // 0: round(rate)
  double seconds = 10.0;
  std::size_t payload = 1213;
  unsigned client_threads = 1;
  bool stagger = true;  // spread the connects over one client period
  bool json = false;
  protocol::DataMode mode = protocol::DataMode::kPushNew;
  // Latency samples kept per client (0: every one). A long run keeps every
  // k-th so that its own memory stays flat while the server's is watched.
  std::size_t latency_samples = 0;
  double memory_every = 0;  // seconds between samples of the process's RSS (0: none)
};

// ------------------------------------------------------------------ CPU clocks

double seconds_of(const timespec& ts) { return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9; }

// CPU seconds a thread has used so far; NaN if its clock cannot be read.
double thread_cpu_seconds(clockid_t clock) {
  timespec ts{};
  if (clock_gettime(clock, &ts) != 0) return std::nan("");
  return seconds_of(ts);
}

double process_cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const auto tv = [](const timeval& t) {
    return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_usec) * 1e-6;
  };
  return tv(usage.ru_utime) + tv(usage.ru_stime);
}

// The machine as a whole (/proc/stat "cpu" line), in clock ticks.
struct MachineTicks {
  std::uint64_t busy = 0;
  std::uint64_t total = 0;
  std::uint64_t steal = 0;
};

MachineTicks machine_ticks() {
  std::ifstream stat("/proc/stat");
  std::string label;
  std::uint64_t user = 0, nice = 0, system = 0, idle = 0, iowait = 0, irq = 0, softirq = 0, steal = 0;
  stat >> label >> user >> nice >> system >> idle >> iowait >> irq >> softirq >> steal;
  if (!stat || label != "cpu") return {};
  const std::uint64_t total = user + nice + system + idle + iowait + irq + softirq + steal;
  return {total - idle - iowait, total, steal};
}

// CPU seconds of the kernel's ksoftirqd threads (clock-tick resolution). On
// loopback the receiving side of TCP normally runs in the sender's context
// (and is charged to the server thread); when softirqs pile up the kernel
// hands them to ksoftirqd, and that work is then charged to no thread here.
double ksoftirqd_seconds() {
  double total = 0;
  const double tick = 1.0 / static_cast<double>(sysconf(_SC_CLK_TCK));
  for (const auto& entry : std::filesystem::directory_iterator("/proc")) {
    const std::string name = entry.path().filename().string();
    if (name.empty() || name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::ifstream stat(entry.path() / "stat");
    std::string line;
    if (!std::getline(stat, line)) continue;
    const auto open = line.find('(');
    const auto close = line.rfind(')');
    if (open == std::string::npos || close == std::string::npos) continue;
    if (line.compare(open + 1, 10, "ksoftirqd/") != 0) continue;
    std::istringstream rest(line.substr(close + 2));
    std::string field;
    std::uint64_t utime = 0, stime = 0;
    for (int i = 3; i <= 13; ++i) rest >> field;  // state .. cmajflt
    rest >> utime >> stime;
    total += static_cast<double>(utime + stime) * tick;
  }
  return total;
}

// Thread CPU clocks registered by threads themselves (drivers, clients).
class ThreadClocks {
 public:
  void add_current_thread() {
    clockid_t id{};
    if (pthread_getcpuclockid(pthread_self(), &id) != 0) return;
    std::lock_guard lock(mutex_);
    clocks_.push_back(id);
  }
  [[nodiscard]] double total_seconds() const {
    std::lock_guard lock(mutex_);
    double total = 0;
    for (const clockid_t id : clocks_) total += thread_cpu_seconds(id);
    return total;
  }
  [[nodiscard]] std::size_t count() const {
    std::lock_guard lock(mutex_);
    return clocks_.size();
  }

 private:
  mutable std::mutex mutex_;
  std::vector<clockid_t> clocks_;
};

// ------------------------------------------------------------------ driver

struct SourceShared {
  double rate = 100.0;
  std::size_t payload = 1213;
  std::atomic<std::uint64_t> published{0};
  std::atomic<std::uint64_t> late{0};  // deadlines the driver woke up a whole period past
  ThreadClocks clocks;
};

void put_u64(std::vector<std::uint8_t>& bytes, std::uint64_t value) {
  for (std::size_t i = 0; i < 8; ++i) bytes[i] = static_cast<std::uint8_t>(value >> (56 - 8 * i));
}

std::uint64_t get_u64(const std::uint8_t* bytes) {
  std::uint64_t value = 0;
  for (std::size_t i = 0; i < 8; ++i) value = (value << 8) | bytes[i];
  return value;
}

class BenchSourceDriver final : public core::ThreadedDriver {
 public:
  explicit BenchSourceDriver(SourceShared& shared) : shared_(shared) {}
  ~BenchSourceDriver() override = default;
  BenchSourceDriver(const BenchSourceDriver&) = delete;
  BenchSourceDriver& operator=(const BenchSourceDriver&) = delete;

 protected:
  void run(std::stop_token stop) override {
    pthread_setname_np(pthread_self(), "bench-source");
    shared_.clocks.add_current_thread();
    std::vector<std::uint8_t> bytes(shared_.payload);
    for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<std::uint8_t>(i * 37);
    const auto period = std::chrono::duration_cast<SteadyClock::duration>(
        std::chrono::duration<double>(1.0 / shared_.rate));
    auto deadline = SteadyClock::now();
    std::uint64_t sequence = 0;
    while (!stop.stop_requested()) {
      if (bytes.size() >= 8) put_u64(bytes, ++sequence);
      device().publish(bytes, device().clock().now());
      shared_.published.fetch_add(1, std::memory_order_relaxed);
      deadline += period;
      const auto now = SteadyClock::now();
      if (deadline + period < now) {  // lost a whole period (machine busy): restart the cadence
        shared_.late.fetch_add(1, std::memory_order_relaxed);
        deadline = now;
      }
      if (!sleep_for(stop, deadline - now)) return;
    }
  }

 private:
  SourceShared& shared_;
};

// ------------------------------------------------------------------ clients

// 0 before the measured interval, 1 during it, 2 after.
std::atomic<int> g_phase{0};

std::int64_t wall_microseconds() {
  return std::chrono::duration_cast<std::chrono::microseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

std::int64_t microseconds_of(std::uint32_t sec, std::uint32_t usec) {
  return static_cast<std::int64_t>(sec) * 1'000'000 + usec;
}

struct ClientCounters {
  std::uint64_t data = 0;
  std::uint64_t synch = 0;
  std::uint64_t empty_rounds = 0;  // SYNCH with no DATA before it
  std::uint64_t missed = 0;        // sequence numbers never received
  std::uint64_t repeated = 0;      // a sequence number not newer than the last one
  std::uint64_t bytes = 0;
  // Rounds as the server stamped them (SYNCH header time, server wall clock, us).
  std::uint64_t late_rounds = 0;   // more than 1.5 periods after the one before
  std::int64_t longest_gap_us = 0;
  std::int64_t first_round_us = 0;  // first and last round in the measured interval
  std::int64_t last_round_us = 0;
};

class BenchClient : public std::enable_shared_from_this<BenchClient> {
 public:
  BenchClient(asio::io_context& io, const Options& options, std::atomic<unsigned>& ready,
              std::atomic<unsigned>& failed)
      : socket_(asio::make_strand(io)), timer_(socket_.get_executor()), options_(options), ready_(ready), failed_(failed),
        buffer_(256 * 1024), last_sequence_(options.devices, 0) {
    const std::size_t expected = static_cast<std::size_t>(
        std::ceil(options.devices * std::max<double>(options.rate, options.client_frequency) *
                  (options.seconds + 1.0) * 1.2));
    std::size_t kept = expected;
    if (options.latency_samples > 0 && options.latency_samples < expected) {
      latency_stride_ = (expected + options.latency_samples - 1) / options.latency_samples;
      kept = options.latency_samples;
    }
    total_latency_.reserve(kept);
    server_latency_.reserve(kept);
    wire_latency_.reserve(kept);
  }

  // Connects after `delay` (the phase of this client's data rounds).
  void start(const tcp::endpoint& server, SteadyClock::duration delay) {
    timer_.expires_after(delay);
    timer_.async_wait([self = shared_from_this(), server](const boost::system::error_code& ec) {
      if (!ec) self->connect(server);
    });
  }

  void connect(const tcp::endpoint& server) {
    socket_.async_connect(server, [self = shared_from_this()](const boost::system::error_code& ec) {
      if (ec) {
        self->fail("connect: " + ec.message());
        return;
      }
      boost::system::error_code ignored;
      self->socket_.set_option(tcp::no_delay(true), ignored);
      self->send_setup();
      self->read_more();
    });
  }

  void close() {
    closing_ = true;
    timer_.cancel();
    boost::system::error_code ignored;
    socket_.close(ignored);
  }

  [[nodiscard]] tcp::socket::executor_type executor() { return socket_.get_executor(); }
  [[nodiscard]] const ClientCounters& counters() const { return counters_; }
  [[nodiscard]] const std::vector<std::int32_t>& total_latency() const { return total_latency_; }
  [[nodiscard]] const std::vector<std::int32_t>& server_latency() const { return server_latency_; }
  [[nodiscard]] const std::vector<std::int32_t>& wire_latency() const { return wire_latency_; }
  [[nodiscard]] bool disconnected() const { return disconnected_; }
  [[nodiscard]] const std::string& error() const { return error_; }

 private:
  static void append_request(std::vector<std::uint8_t>& out, const std::vector<std::uint8_t>& payload) {
    const auto message = protocol::encode_message(
        protocol::make_header(protocol::MessageType::kRequest, {protocol::kPlayerCode, 0}, {}, {}),
        payload);
    out.insert(out.end(), message.begin(), message.end());
  }

  static void put_u16(std::vector<std::uint8_t>& out, unsigned value) {
    out.push_back(static_cast<std::uint8_t>(value >> 8));
    out.push_back(static_cast<std::uint8_t>(value & 0xff));
  }

  void send_setup() {
    // DATAFREQ, DATAMODE, then a DEV request per laser; all replies are
    // counted in read order.
    std::vector<std::uint8_t> freq;
    put_u16(freq, protocol::kPlayerDatafreqReq);
    put_u16(freq, options_.client_frequency);
    append_request(setup_, freq);
    std::vector<std::uint8_t> mode;
    put_u16(mode, protocol::kPlayerDatamodeReq);
    mode.push_back(static_cast<std::uint8_t>(options_.mode));
    append_request(setup_, mode);
    for (unsigned i = 0; i < options_.devices; ++i) {
      std::vector<std::uint8_t> dev;
      put_u16(dev, protocol::kPlayerDevReq);
      put_u16(dev, protocol::kLaserCode);
      put_u16(dev, i);
      dev.push_back(static_cast<std::uint8_t>(protocol::Access::kRead));
      append_request(setup_, dev);
    }
    replies_pending_ = options_.devices + 2;
    asio::async_write(socket_, asio::buffer(setup_),
                      [self = shared_from_this()](const boost::system::error_code& ec, std::size_t) {
                        if (ec) self->fail("sending the requests: " + ec.message());
                      });
  }

  void read_more() {
    if (end_ == buffer_.size()) {  // compact (never happens with whole messages below 8 KiB)
      std::memmove(buffer_.data(), buffer_.data() + begin_, end_ - begin_);
      end_ -= begin_;
      begin_ = 0;
    }
    socket_.async_read_some(
        asio::buffer(buffer_.data() + end_, buffer_.size() - end_),
        [self = shared_from_this()](const boost::system::error_code& ec, std::size_t n) {
          if (ec) {
            if (!self->closing_) {
              self->disconnected_ = true;
              self->fail(ec == asio::error::eof ? "the server closed the connection"
                                                : "read: " + ec.message());
            }
            return;
          }
          self->end_ += n;
          if (g_phase.load(std::memory_order_relaxed) == 1) self->counters_.bytes += n;
          if (!self->consume(wall_microseconds())) return;
          self->read_more();
        });
  }

  // Handles every whole message in the buffer; false on a protocol problem.
  bool consume(std::int64_t received_us) {
    const bool measuring = g_phase.load(std::memory_order_relaxed) == 1;
    while (end_ - begin_ >= protocol::kHeaderSize) {
      if (!banner_read_) {
        banner_read_ = true;
        begin_ += protocol::kBannerSize;
        continue;
      }
      const auto header = protocol::decode_header(
          std::span<const std::uint8_t, protocol::kHeaderSize>(buffer_.data() + begin_, protocol::kHeaderSize));
      if (header.stx != protocol::kStx || header.size > protocol::kMaxPayloadSize) {
        fail("bad message header from the server");
        return false;
      }
      const std::size_t total = protocol::kHeaderSize + header.size;
      if (end_ - begin_ < total) break;
      if (!handle(header, buffer_.data() + begin_ + protocol::kHeaderSize, received_us, measuring)) return false;
      begin_ += total;
    }
    if (begin_ == end_) {
      begin_ = end_ = 0;
    } else if (buffer_.size() - end_ < protocol::kMaxMessageSize) {
      std::memmove(buffer_.data(), buffer_.data() + begin_, end_ - begin_);
      end_ -= begin_;
      begin_ = 0;
    }
    return true;
  }

  bool handle(const protocol::MessageHeader& header, const std::uint8_t* payload, std::int64_t received_us,
              bool measuring) {
    switch (static_cast<protocol::MessageType>(header.type)) {
      case protocol::MessageType::kData: {
        ++data_in_round_;
        const std::size_t index = header.device_index;
        if (header.device != protocol::kLaserCode || index >= last_sequence_.size()) {
          fail("data from an unexpected device");
          return false;
        }
        if (header.size >= 8) {
          const std::uint64_t sequence = get_u64(payload);
          std::uint64_t& last = last_sequence_[index];
          if (measuring && last != 0) {
            if (sequence <= last) {
              ++counters_.repeated;
            } else {
              counters_.missed += sequence - last - 1;
            }
          }
          last = std::max(last, sequence);
        }
        if (measuring) {
          ++counters_.data;
          const std::int64_t published = microseconds_of(header.timestamp_sec, header.timestamp_usec);
          const std::int64_t sent = microseconds_of(header.time_sec, header.time_usec);
          const bool keep = counters_.data % latency_stride_ == 0 &&
                            (options_.latency_samples == 0 || total_latency_.size() < options_.latency_samples);
          if (keep) {
            total_latency_.push_back(clamp32(received_us - published));
            server_latency_.push_back(clamp32(sent - published));
            wire_latency_.push_back(clamp32(received_us - sent));
          }
        }
        return true;
      }
      case protocol::MessageType::kSynch:
        if (measuring) {
          ++counters_.synch;
          if (data_in_round_ == 0) ++counters_.empty_rounds;
          const std::int64_t built = microseconds_of(header.time_sec, header.time_usec);
          if (counters_.first_round_us == 0) {
            counters_.first_round_us = built;
          } else {
            const std::int64_t gap = built - counters_.last_round_us;
            counters_.longest_gap_us = std::max(counters_.longest_gap_us, gap);
            if (static_cast<double>(gap) > 1.5e6 / options_.client_frequency) ++counters_.late_rounds;
          }
          counters_.last_round_us = built;
        }
        data_in_round_ = 0;
        return true;
      case protocol::MessageType::kAck:
      case protocol::MessageType::kNack:
      case protocol::MessageType::kError: {
        if (replies_pending_ == 0) {
          fail("an unexpected reply");
          return false;
        }
        if (header.type != static_cast<std::uint16_t>(protocol::MessageType::kAck)) {
          fail("a setup request was refused (type " + std::to_string(header.type) + ")");
          return false;
        }
        const bool is_dev_reply = replies_pending_ <= options_.devices;  // the first two: DATAFREQ's, DATAMODE's
        if (is_dev_reply && (header.size < 7 || payload[6] != static_cast<std::uint8_t>(protocol::Access::kRead))) {
          fail("a laser was not opened for reading");
          return false;
        }
        if (--replies_pending_ == 0) ready_.fetch_add(1);
        return true;
      }
      default:
        fail("a message of unexpected type " + std::to_string(header.type));
        return false;
    }
  }

  static std::int32_t clamp32(std::int64_t value) {
    return static_cast<std::int32_t>(std::clamp<std::int64_t>(value, INT32_MIN, INT32_MAX));
  }

  void fail(std::string message) {
    if (!error_.empty()) return;
    error_ = std::move(message);
    failed_.fetch_add(1);
  }

  tcp::socket socket_;
  asio::steady_timer timer_;
  const Options& options_;
  std::atomic<unsigned>& ready_;
  std::atomic<unsigned>& failed_;
  std::vector<std::uint8_t> setup_;
  std::vector<std::uint8_t> buffer_;
  std::size_t begin_ = 0;
  std::size_t end_ = 0;
  bool banner_read_ = false;
  bool closing_ = false;
  bool disconnected_ = false;
  unsigned replies_pending_ = 0;
  unsigned data_in_round_ = 0;
  std::vector<std::uint64_t> last_sequence_;
  ClientCounters counters_;
  std::vector<std::int32_t> total_latency_;
  std::vector<std::int32_t> server_latency_;
  std::vector<std::int32_t> wire_latency_;
  std::uint64_t latency_stride_ = 1;
  std::string error_;
};

// ------------------------------------------------------------------ results

struct Percentiles {
  double p50 = 0, p99 = 0, max = 0;  // milliseconds
  std::size_t samples = 0;
};

Percentiles percentiles(std::vector<std::int32_t> samples) {
  Percentiles result;
  result.samples = samples.size();
  if (samples.empty()) return result;
  std::sort(samples.begin(), samples.end());
  const auto at = [&](double q) {
    const auto index = static_cast<std::size_t>(std::ceil(q * static_cast<double>(samples.size()))) - 1;
    return samples[std::min(index, samples.size() - 1)] / 1000.0;
  };
  result.p50 = at(0.50);
  result.p99 = at(0.99);
  result.max = samples.back() / 1000.0;
  return result;
}

nlohmann::json to_json(const Percentiles& p) {
  return {{"p50_ms", p.p50}, {"p99_ms", p.p99}, {"max_ms", p.max}, {"samples", p.samples}};
}

// The most clients whose rounds fall within one tenth of a period of each
// other (phase of the round times modulo the period). Staggered connects start
// near N/10; a value near N means every client gets its round at the same moment.
std::size_t largest_phase_cluster(const std::vector<std::int64_t>& round_times_us, unsigned frequency) {
  if (round_times_us.empty()) return 0;
  const double period = 1e6 / frequency;
  std::vector<double> phases;
  for (const std::int64_t t : round_times_us) phases.push_back(std::fmod(static_cast<double>(t), period));
  std::sort(phases.begin(), phases.end());
  const std::size_t n = phases.size();
  for (std::size_t i = 0; i < n; ++i) phases.push_back(phases[i] + period);  // wrap around
  std::size_t best = 0;
  std::size_t end = 0;
  for (std::size_t begin = 0; begin < n; ++begin) {
    end = std::max(end, begin);
    while (end < phases.size() && phases[end] - phases[begin] < period / 10) ++end;
    best = std::max(best, end - begin);
  }
  return std::min(best, n);
}

struct Snapshot {
  SteadyClock::time_point when;
  double server_thread = 0;
  double driver_threads = 0;
  double client_threads = 0;
  double process = 0;
  double ksoftirqd = 0;
  MachineTicks machine;
  std::uint64_t published = 0;
  std::uint64_t late = 0;
};

// The process's resident memory in MB (VmRSS of /proc/self/status), 0 if unreadable.
double resident_megabytes() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmRSS:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
  }
  return 0.0;
}

struct MemorySample {
  double seconds = 0;  // since the measured interval began
  double rss_mb = 0;
};

std::string fixed(double value, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

int run(const Options& options) {
  core::ServerClock clock;  // the wall clock: no driver here claims it
  core::Logger logger("server_load_bench");
  logger.set_level(core::LogLevel::kWarning);

  SourceShared shared;
  shared.rate = options.rate;
  shared.payload = options.payload;
  core::DriverRegistry registry;
  registry.add({"bench-source",
                {protocol::kLaserCode},
                protocol::Access::kRead,
                [&shared](const core::DriverContext&) -> std::unique_ptr<core::Driver> {
                  return std::make_unique<BenchSourceDriver>(shared);
                },
                {},
                "server_load_bench data source"});

  server::ServerOptions server_options;
  server_options.bind_address = "127.0.0.1";
  core::DeviceTable devices;
  server::Server server(devices, clock, logger, server_options);
  const std::uint16_t port = server.listen(0);

  std::string config_text;
  for (unsigned i = 0; i < options.devices; ++i) {
    config_text += "laser:" + std::to_string(i) + " ( driver \"bench-source\" )\n";
  }
  const auto config = config::ConfigFile::parse(config_text, "bench.cfg", core::load_options_for(registry, port));
  core::instantiate_devices(config, registry, devices, clock, logger);
  devices.prepare_all();

  std::thread server_thread([&server] {
    pthread_setname_np(pthread_self(), "pk-server");  // for top -H and perf
    server.run();
  });
  clockid_t server_clock{};
  if (pthread_getcpuclockid(server_thread.native_handle(), &server_clock) != 0) {
    std::cerr << "server_load_bench: cannot read the server thread's CPU clock\n";
    server.stop();
    server_thread.join();
    devices.shutdown_all();
    return 1;
  }

  // Clients.
  asio::io_context io;
  auto work = asio::make_work_guard(io);
  std::atomic<unsigned> ready{0};
  std::atomic<unsigned> failed{0};
  std::vector<std::shared_ptr<BenchClient>> clients;
  const tcp::endpoint endpoint(asio::ip::make_address("127.0.0.1"), port);
  // A client's data rounds keep the phase of its connect; the drivers' phase is
  // that of the first subscription. Spreading the connects evenly over one
  // client period makes the wait for the next round uniform across clients
  // instead of depending on how the connects happened to bunch up.
  const double client_period = 1.0 / options.client_frequency;
  for (unsigned i = 0; i < options.clients; ++i) {
    clients.push_back(std::make_shared<BenchClient>(io, options, ready, failed));
    const double delay = options.stagger ? client_period * i / options.clients : 0.0;
    clients.back()->start(endpoint, std::chrono::duration_cast<SteadyClock::duration>(
                                        std::chrono::duration<double>(delay)));
  }
  ThreadClocks client_clocks;
  std::vector<std::thread> client_threads;
  for (unsigned i = 0; i < options.client_threads; ++i) {
    client_threads.emplace_back([&io, &client_clocks] {
      pthread_setname_np(pthread_self(), "bench-clients");
      client_clocks.add_current_thread();
      io.run();
    });
  }

  const auto shut_down = [&] {
    work.reset();
    for (auto& client : clients) asio::post(client->executor(), [client] { client->close(); });
    for (auto& thread : client_threads) thread.join();
    server.stop();
    server_thread.join();
    devices.shutdown_all();
  };

  const auto setup_deadline = SteadyClock::now() + std::chrono::seconds(30);
  while (ready.load() + failed.load() < options.clients && SteadyClock::now() < setup_deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  if (ready.load() < options.clients) {
    shut_down();
    std::cerr << "server_load_bench: only " << ready.load() << " of " << options.clients
              << " clients got their devices";
    for (const auto& client : clients) {
      if (!client->error().empty()) {
        std::cerr << " (first error: " << client->error() << ")";
        break;
      }
    }
    std::cerr << "\n";
    return 1;
  }

  std::this_thread::sleep_for(std::chrono::seconds(1));  // warm-up, not measured

  const auto snapshot = [&] {
    Snapshot s;
    s.when = SteadyClock::now();
    s.server_thread = thread_cpu_seconds(server_clock);
    s.driver_threads = shared.clocks.total_seconds();
    s.client_threads = client_clocks.total_seconds();
    s.process = process_cpu_seconds();
    s.ksoftirqd = ksoftirqd_seconds();
    s.machine = machine_ticks();
    s.published = shared.published.load();
    s.late = shared.late.load();
    return s;
  };
  g_phase.store(1);
  const Snapshot before = snapshot();
  std::vector<MemorySample> memory;
  const auto measure_end = before.when + std::chrono::duration_cast<SteadyClock::duration>(
                                             std::chrono::duration<double>(options.seconds));
  if (options.memory_every > 0) {
    // A soak: the RSS at the start and every --memory-every seconds. The
    // clients keep bounded latency samples (--latency-samples), so growth
    // is the server's (or a leak).
    const auto every = std::chrono::duration_cast<SteadyClock::duration>(
        std::chrono::duration<double>(options.memory_every));
    for (auto next = before.when;; next += every) {
      memory.push_back({std::chrono::duration<double>(SteadyClock::now() - before.when).count(), resident_megabytes()});
      if (next + every >= measure_end) break;
      std::this_thread::sleep_until(next + every);
    }
  }
  std::this_thread::sleep_until(measure_end);
  g_phase.store(2);
  const Snapshot after = snapshot();
  const std::size_t driver_thread_count = shared.clocks.count();

  shut_down();

  // Aggregate (client threads have stopped: their counters are final).
  const double elapsed = std::chrono::duration<double>(after.when - before.when).count();
  ClientCounters sum;
  std::vector<std::int32_t> total, in_server, on_wire;
  double min_client_rate = 1e300, max_client_rate = 0;
  unsigned disconnected = 0, errors = 0;
  std::vector<std::int64_t> first_rounds, last_rounds;
  std::int64_t longest_gap_us = 0;
  std::string first_error;
  for (const auto& client : clients) {
    const ClientCounters& c = client->counters();
    sum.data += c.data;
    sum.synch += c.synch;
    sum.empty_rounds += c.empty_rounds;
    sum.missed += c.missed;
    sum.repeated += c.repeated;
    sum.bytes += c.bytes;
    sum.late_rounds += c.late_rounds;
    longest_gap_us = std::max(longest_gap_us, c.longest_gap_us);
    if (c.first_round_us != 0) {
      first_rounds.push_back(c.first_round_us);
      last_rounds.push_back(c.last_round_us);
    }
    min_client_rate = std::min(min_client_rate, static_cast<double>(c.data) / elapsed);
    max_client_rate = std::max(max_client_rate, static_cast<double>(c.data) / elapsed);
    total.insert(total.end(), client->total_latency().begin(), client->total_latency().end());
    in_server.insert(in_server.end(), client->server_latency().begin(), client->server_latency().end());
    on_wire.insert(on_wire.end(), client->wire_latency().begin(), client->wire_latency().end());
    if (client->disconnected()) ++disconnected;
    if (!client->error().empty()) {
      ++errors;
      if (first_error.empty()) first_error = client->error();
    }
  }
  const std::size_t cluster_before = largest_phase_cluster(first_rounds, options.client_frequency);
  const std::size_t cluster_after = largest_phase_cluster(last_rounds, options.client_frequency);
  const Percentiles latency = percentiles(std::move(total));
  const Percentiles latency_in_server = percentiles(std::move(in_server));
  const Percentiles latency_on_wire = percentiles(std::move(on_wire));

  const double published = static_cast<double>(after.published - before.published);
  const double offered = published * options.clients;  // each client should get every sample
  const double pct = 100.0 / elapsed;
  const double server_cpu = (after.server_thread - before.server_thread) * pct;
  const double driver_cpu = (after.driver_threads - before.driver_threads) * pct;
  const double client_cpu = (after.client_threads - before.client_threads) * pct;
  const double process_cpu = (after.process - before.process) * pct;
  const double ksoftirqd_cpu = (after.ksoftirqd - before.ksoftirqd) * pct;
  const auto machine_total = static_cast<double>(after.machine.total - before.machine.total);
  const double cores = static_cast<double>(std::thread::hardware_concurrency());
  const double machine_busy =
      machine_total > 0 ? static_cast<double>(after.machine.busy - before.machine.busy) / machine_total * 100.0 * cores : 0.0;
  const double machine_steal =
      machine_total > 0 ? static_cast<double>(after.machine.steal - before.machine.steal) / machine_total * 100.0 * cores : 0.0;

  if (options.json) {
    nlohmann::json out = {
        {"clients", options.clients},
        {"devices", options.devices},
        {"rate_hz", options.rate},
        {"client_frequency_hz", options.client_frequency},
        {"payload_bytes", options.payload},
        {"client_threads", options.client_threads},
        {"staggered_connects", options.stagger},
        {"seconds", elapsed},
        {"published_per_s", published / elapsed},
        {"offered_data_per_s", offered / elapsed},
        {"data_per_s", static_cast<double>(sum.data) / elapsed},
        {"data_per_s_per_client_min", min_client_rate},
        {"data_per_s_per_client_max", max_client_rate},
        {"synch_per_s", static_cast<double>(sum.synch) / elapsed},
        {"empty_rounds", sum.empty_rounds},
        {"late_rounds", sum.late_rounds},
        {"longest_round_gap_ms", static_cast<double>(longest_gap_us) / 1000.0},
        {"phase_cluster_start", cluster_before},
        {"phase_cluster_end", cluster_after},
        {"samples_missed", sum.missed},
        {"samples_repeated", sum.repeated},
        {"received_mb_per_s", static_cast<double>(sum.bytes) / elapsed / 1e6},
        {"driver_late_deadlines", after.late - before.late},
        {"clients_disconnected", disconnected},
        {"client_errors", errors},
        {"cpu_percent_of_one_core",
         {{"server_thread", server_cpu},
          {"driver_threads", driver_cpu},
          {"client_threads", client_cpu},
          {"process", process_cpu},
          {"ksoftirqd", ksoftirqd_cpu},
          {"machine_busy", machine_busy},
          {"machine_steal", machine_steal}}},
        {"cores", cores},
        {"latency", to_json(latency)},
        {"latency_in_server", to_json(latency_in_server)},
        {"latency_on_wire", to_json(latency_on_wire)},
        {"mode", std::string(protocol::to_string(options.mode))},
    };
    if (!memory.empty()) {
      nlohmann::json series = nlohmann::json::array();
      for (const MemorySample& m : memory) series.push_back({{"seconds", m.seconds}, {"rss_mb", m.rss_mb}});
      out["memory"] = series;
    }
    if (!first_error.empty()) out["first_client_error"] = first_error;
    std::cout << out.dump(2) << "\n";
  } else {
    std::ostringstream o;
    o << "server_load_bench: " << options.clients << " clients x " << options.devices << " devices x "
      << fixed(options.rate, 1) << " Hz, client DATAFREQ " << options.client_frequency << " Hz, "
      << options.payload << "-byte payload, " << options.client_threads << " client thread(s), "
      << (options.stagger ? "staggered" : "simultaneous") << " connects, "
      << protocol::to_string(options.mode) << ", " << fixed(elapsed, 2) << " s measured\n";
    o << "  published by drivers      " << fixed(published / elapsed, 0) << " /s  ("
      << after.late - before.late << " late deadlines)\n";
    o << "  offered (x clients)       " << fixed(offered / elapsed, 0) << " data msgs/s\n";
    o << "  delivered DATA            " << fixed(static_cast<double>(sum.data) / elapsed, 0)
      << " msgs/s  (" << fixed(static_cast<double>(sum.data) / std::max(offered, 1.0) * 100.0, 1)
      << " % of offered; per client " << fixed(min_client_rate, 1) << " .. " << fixed(max_client_rate, 1)
      << " /s)\n";
    o << "  SYNCH rounds              " << fixed(static_cast<double>(sum.synch) / elapsed, 0)
      << " /s  (" << sum.empty_rounds << " without data; " << sum.late_rounds
      << " more than 1.5 periods after the previous one, longest gap "
      << fixed(static_cast<double>(longest_gap_us) / 1000.0, 1) << " ms)\n";
    o << "  clients with rounds within 1/10 period of each other, most: " << cluster_before
      << " at the start, " << cluster_after << " at the end\n";
    o << "  samples missed / repeated " << sum.missed << " / " << sum.repeated << "\n";
    o << "  received                  " << fixed(static_cast<double>(sum.bytes) / elapsed / 1e6, 2)
      << " MB/s\n";
    o << "  clients disconnected      " << disconnected << "  (errors: " << errors
      << (first_error.empty() ? "" : ", first: " + first_error) << ")\n";
    o << "  CPU, % of one core        server thread " << fixed(server_cpu, 1) << "  drivers ("
      << driver_thread_count << " threads) " << fixed(driver_cpu, 1) << "  clients "
      << fixed(client_cpu, 1) << "  process " << fixed(process_cpu, 1) << "  (kernel ksoftirqd "
      << fixed(ksoftirqd_cpu, 1) << ")\n";
    o << "  whole machine, % of 1 core busy " << fixed(machine_busy, 0) << " of " << fixed(cores * 100.0, 0)
      << ", steal " << fixed(machine_steal, 0)
      << "  (/proc/stat, tick-sampled, every process: shows other load)\n";
    const auto line = [&o](const char* name, const Percentiles& p) {
      o << "  " << name << "p50 " << fixed(p.p50, 3) << " ms  p99 " << fixed(p.p99, 3) << " ms  max "
        << fixed(p.max, 3) << " ms  (" << p.samples << " samples)\n";
    };
    line("latency publish->client  ", latency);
    line("  publish->round built   ", latency_in_server);
    line("  round built->client    ", latency_on_wire);
    if (!memory.empty()) {
      double peak = 0;
      for (const MemorySample& m : memory) peak = std::max(peak, m.rss_mb);
      o << "  process RSS               " << fixed(memory.front().rss_mb, 1) << " MB at the start, "
        << fixed(memory.back().rss_mb, 1) << " MB after " << fixed(memory.back().seconds, 0) << " s, peak "
        << fixed(peak, 1) << " MB  (" << memory.size() << " samples; --json has them all)\n";
    }
    std::cout << o.str();
  }
  return errors > 0 || disconnected > 0 ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"server_load_bench: N clients x M devices x F Hz against the playerkit TCP server on\n"
               "127.0.0.1 (server, drivers and clients in this one process)."};
  Options options;
  app.add_option("--clients", options.clients, "number of clients")->capture_default_str()->check(CLI::Range(1u, 5000u));
  app.add_option("--devices", options.devices, "laser devices, each opened by every client")
      ->capture_default_str()
      ->check(CLI::Range(1u, 64u));
  app.add_option("--rate", options.rate, "Hz at which each device publishes")
      ->capture_default_str()
      ->check(CLI::Range(0.1, 10000.0));
  auto* frequency = app.add_option("--client-frequency", options.client_frequency,
                                   "DATAFREQ each client asks for (default: --rate)")
                        ->check(CLI::Range(1u, 65535u));
  app.add_option("--seconds", options.seconds, "measured duration, after a 1 s warm-up")
      ->capture_default_str()
      ->check(CLI::Range(0.1, 3600.0));
  app.add_option("--payload", options.payload, "bytes per data message (1213: a laser scan)")
      ->capture_default_str()
      ->check(CLI::Range(std::size_t{0}, protocol::kMaxPayloadSize));
  app.add_option("--client-threads", options.client_threads, "threads running the clients' io_context")
      ->capture_default_str()
      ->check(CLI::Range(1u, 64u));
  app.add_flag("!--no-stagger", options.stagger,
               "connect all clients at once instead of spreading them over one client period");
  app.add_flag("--json", options.json, "print one JSON object instead of a table");
  std::string mode_name(protocol::to_string(options.mode));
  app.add_option("--mode", mode_name, "data mode each client asks for: push-new (1.5's default) or push-all")
      ->capture_default_str()
      ->check(CLI::IsMember({std::string(protocol::to_string(protocol::DataMode::kPushNew)),
                             std::string(protocol::to_string(protocol::DataMode::kPushAll))}));
  app.add_option("--latency-samples", options.latency_samples,
                 "latency samples kept per client, evenly spread (default: all; a soak keeps its memory flat with "
                 "e.g. 1000)");
  app.add_option("--memory-every", options.memory_every,
                 "sample the process's RSS every this many seconds while measuring (a soak)")
      ->check(CLI::NonNegativeNumber);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  options.mode = *protocol::parse_data_mode(mode_name);
  if (frequency->count() == 0) {
    options.client_frequency = static_cast<unsigned>(std::max(1.0, std::round(options.rate)));
  }
  try {
    return run(options);
  } catch (const std::exception& e) {
    std::cerr << "server_load_bench: " << e.what() << "\n";
    return 1;
  }
}
