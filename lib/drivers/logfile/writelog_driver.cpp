#include "drivers/logfile/writelog_driver.hpp"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <exception>
#include <filesystem>
#include <system_error>
#include <utility>

#include "config/errors.hpp"
#include "log/text_log_writer.hpp"
#include "protocol/device_address.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/message.hpp"
#include "text/printable.hpp"

namespace playerkit::drivers {

namespace {

// 1.5 wrote one sync line per 100 ms cycle; its readlog paced replay by them.
constexpr std::uint64_t kSyncPeriodMicroseconds = 100'000;
// How long the thread sleeps without data before checking for a due sync line.
constexpr std::chrono::milliseconds kIdleWait{20};

// What can be known about writing `filename` without creating or truncating
// it: not a directory, in a directory that exists and may be written to. So a
// configuration that could never record is refused when it is loaded (and by
// player-serve --check), not when a client subscribes.
void check_log_destination(const std::string& filename, const config::SourceLocation& where) {
  namespace fs = std::filesystem;
  const fs::path path(filename);
  const std::string shown = "writelog: filename \"" + text::excerpt(filename) + "\"";
  std::error_code error;
  if (fs::is_directory(path, error)) throw config::ConfigError(where, shown + " is a directory");
  const fs::path directory = path.has_parent_path() ? path.parent_path() : fs::path(".");
  const fs::file_status status = fs::status(directory, error);
  if (!fs::exists(status)) {
    throw config::ConfigError(where, shown + ": directory " + text::excerpt(directory.string()) + " does not exist");
  }
  if (!fs::is_directory(status)) {
    throw config::ConfigError(where, shown + ": " + text::excerpt(directory.string()) + " is not a directory");
  }
  if (::access(directory.c_str(), W_OK | X_OK) != 0) {
    throw config::ConfigError(where, shown + ": cannot create files in " + text::excerpt(directory.string()) +
                                         ": " + std::strerror(errno));
  }
  if (fs::exists(path, error) && ::access(path.c_str(), W_OK) != 0) {
    throw config::ConfigError(where, shown + ": cannot write it: " + std::strerror(errno));
  }
}

}  // namespace

std::string log_host_name() {
  std::array<char, 256> buffer{};
  if (gethostname(buffer.data(), buffer.size() - 1) != 0) return "localhost";
  std::string name(buffer.data());
  const bool usable = !name.empty() && std::none_of(name.begin(), name.end(), [](char c) {
    return std::isspace(static_cast<unsigned char>(c)) != 0 || std::iscntrl(static_cast<unsigned char>(c)) != 0;
  });
  return usable ? name : "localhost";
}

WritelogDriver::WritelogDriver(std::string filename, std::vector<core::DeviceKey> sources,
                               core::DeviceTable& devices, std::string host)
    : filename_(std::move(filename)),
      source_keys_(std::move(sources)),
      devices_(devices),
      host_(std::move(host)) {}

WritelogDriver::~WritelogDriver() {
  // Normally close() has run; never leave a listener pointing at a dead driver.
  sources_.clear();
}

void WritelogDriver::check() {
  for (const core::DeviceKey& key : source_keys_) {
    const core::Device* source = devices_.find(key.port, key.address);
    if (source == nullptr || source == &device()) {
      throw core::DriverError("writelog: no device " + core::to_string(key) + " to record");
    }
  }
}

void WritelogDriver::open() {
  std::vector<core::Device*> found;
  for (const core::DeviceKey& key : source_keys_) {
    core::Device* source = devices_.find(key.port, key.address);
    if (source == nullptr || source == &device()) {
      throw core::DriverError("writelog: no device " + core::to_string(key) + " to record");
    }
    found.push_back(source);
  }
  try {
    out_.emplace(filename_, files::OutputFileOptions{.mode = files::WriteMode::kStreaming});
  } catch (const std::exception& e) {
    throw core::DriverError(std::string("writelog: ") + e.what());
  }
  write_failed_ = false;
  unflushed_ = false;
  write_line(log::log_file_header());
  const protocol::Timestamp opened = device().clock().now();  // outside pending_mutex_, as everywhere
  {
    std::lock_guard lock(pending_mutex_);
    last_sync_us_ = core::to_microseconds(opened);
    pending_.clear();
    last_sequence_.clear();
    // Samples published before set-up are not new: record what comes next.
    for (core::Device* source : found) last_sequence_[source] = source->latest_data()->sequence;
    accepting_ = true;
  }
  // Listen before subscribing: a source may publish from its setup() on
  // (readlog sends its first line at once), and that sample must go in too.
  std::vector<core::SourceSubscription> subscribed;
  try {
    core::DeviceListener* listener = this;  // a private base: convert here
    for (core::Device* source : found) subscribed.emplace_back(*source, listener, "writelog");
  } catch (const core::DriverError&) {
    out_.reset();
    throw;  // `subscribed` undoes the ones taken
  }
  sources_ = std::move(subscribed);
}

void WritelogDriver::close() {
  // Stop listening first: after this, everything received is in pending_.
  for (core::SourceSubscription& source : sources_) source.stop_listening();
  {
    // A sample whose notification is still on its way is already in its
    // device: take it from there.
    const protocol::Timestamp now = device().clock().now();
    std::lock_guard lock(pending_mutex_);
    accepting_ = false;
    for (const core::SourceSubscription& source : sources_) collect_new_samples(*source.device(), now);
  }
  write_pending();
  try {
    out_->commit();  // the gzip trailer, flushed and synced
  } catch (const std::exception&) {
    report_write_failure();
  }
  out_.reset();
  sources_.clear();
}

void WritelogDriver::run(std::stop_token stop) {
  while (!stop.stop_requested()) {
    device().service_requests();
    {
      std::unique_lock lock(pending_mutex_);
      pending_ready_.wait_for(lock, stop, kIdleWait, [this] { return !pending_.empty(); });
    }
    // The clock is read outside pending_mutex_, which publishers take.
    const protocol::Timestamp now = device().clock().now();
    {
      std::lock_guard lock(pending_mutex_);
      queue_sync_if_due(now);
    }
    write_pending();
    flush_written(true);
  }
}

void WritelogDriver::data_published(const core::Device& source) {
  // On the publisher's thread, at the moment of publishing: a simulation's
  // clock still reads the step that produced the sample.
  const protocol::Timestamp now = device().clock().now();
  std::lock_guard lock(pending_mutex_);
  if (!accepting_) return;
  collect_new_samples(source, now);
  pending_ready_.notify_one();
}

void WritelogDriver::collect_new_samples(const core::Device& source, protocol::Timestamp now) {
  queue_sync_if_due(now);
  std::uint64_t& last = last_sequence_[&source];
  // A queued device keeps every sample; otherwise the newest is the one just published.
  const auto samples = source.queues_data() ? source.data_since(last)
                                            : std::vector{source.latest_data()};
  for (const auto& sample : samples) {
    if (sample->sequence <= last) continue;
    last = sample->sequence;
    pending_.push_back({now, source.address(), sample});
  }
}

void WritelogDriver::write_pending() {
  std::deque<Pending> batch;
  {
    std::lock_guard lock(pending_mutex_);
    batch.swap(pending_);
  }
  const std::uint16_t port = device().key().port;
  for (const Pending& entry : batch) {
    if (!entry.sample) {
      write_line(log::format_sync_line(entry.recorded.seconds(), host_, port));
      continue;
    }
    protocol::Message message;
    message.header = protocol::make_header(protocol::MessageType::kData, entry.address, entry.recorded,
                                           entry.sample->timestamp);
    message.header.size = static_cast<std::uint32_t>(entry.sample->payload.size());
    message.payload = entry.sample->payload;
    try {
      write_line(log::format_data_line(message, host_, port));
    } catch (const std::exception& e) {
      device().logger().warning(device().name() + ": sample of " + protocol::to_string(entry.address) +
                                " not recorded: " + e.what());
    }
  }
}

void WritelogDriver::queue_sync_if_due(protocol::Timestamp now) {
  const std::uint64_t now_us = core::to_microseconds(now);
  if (now_us < last_sync_us_ + kSyncPeriodMicroseconds) return;
  last_sync_us_ = now_us;
  pending_.push_back({now, {}, nullptr});
}

void WritelogDriver::write_line(const std::string& line) {
  out_->stream() << line;
  unflushed_ = true;
  flush_written(false);
}

void WritelogDriver::flush_written(bool periodic) {
  if (!unflushed_) return;
  const auto now = std::chrono::steady_clock::now();
  // A plain file: a crash or kill -9 loses at most the line being written.
  if (out_->compressed() && !(periodic && now - last_flush_ >= std::chrono::seconds(1))) return;
  last_flush_ = now;
  unflushed_ = false;
  out_->stream().flush();
  if (!out_->stream()) report_write_failure();
}

void WritelogDriver::report_write_failure() {
  if (write_failed_) return;
  write_failed_ = true;
  device().logger().error(device().name() + ": writing " + filename_ + " failed");
}

core::DriverSpec writelog_driver_spec() {
  core::DriverSpec spec;
  spec.name = "writelog";
  spec.interfaces = {protocol::kNullCode};
  spec.access = protocol::Access::kRead;
  spec.factory = [](const core::DriverContext& context) -> std::unique_ptr<core::Driver> {
    const config::Section& section = context.section;
    // A plain string, relative to the server's working directory, as in 1.5.
    std::string filename = section.read_string("filename", "writelog.log");
    if (filename.empty()) throw config::ConfigError(section.where(), "writelog: filename is empty");
    const config::Property* filename_property = section.property("filename");
    check_log_destination(filename, filename_property != nullptr && !filename_property->values.empty()
                                        ? filename_property->values.front().where
                                        : section.where());
    std::vector<core::DeviceKey> sources;
    const std::size_t count = section.tuple_size("devices");
    for (std::size_t i = 0; i < count; ++i) {
      const std::string text = section.read_tuple_string("devices", i, "");
      const auto address = protocol::parse_device_address(text);
      if (!address) {
        throw config::ConfigError(section.property("devices")->values[i].where,
                                  "writelog: devices entry \"" + text +
                                      "\" is not interface:index (e.g. \"laser:0\")");
      }
      sources.push_back({context.key.port, *address});
    }
    if (sources.empty()) {
      throw config::ConfigError(section.where(),
                                "writelog: no devices to record: give devices [\"laser:0\" ...]");
    }
    return std::make_unique<WritelogDriver>(std::move(filename), std::move(sources), context.devices,
                                            log_host_name());
  };
  spec.summary = "records the data of other devices into a Player text log";
  spec.doc.manual_section = "7.48";
  spec.doc.options = {
      {"filename", "string", "\"writelog.log\"", "", "the log to write (relative to the working directory)"},
      {"devices", "tuple", "(required)", "", "the devices to record: [\"position:0\" \"laser:0\"]"},
      {"alwayson", "int", "0", "", "1: record from start-up, without a client"}};
  spec.doc.requests = {"every request: NACK"};
  spec.doc.example = "null:0 ( driver \"writelog\" filename \"run.log\" devices [\"position:0\" \"laser:0\"] alwayson 1 )";
  return spec;
}

}  // namespace playerkit::drivers
