#include "log_tool.hpp"

#include <cerrno>
#include <cstring>
#include <sstream>

#include "log/log_input.hpp"

namespace playerkit::plog {

const char* to_string(LogFormat format) { return format == LogFormat::kPlayer ? "player" : "carmen"; }

LogFormat detect_log_format(const std::filesystem::path& path) {
  auto in = log::open_log_input(path);
  std::string line;
  bool player_header = false;
  // Bounded: a file of nothing but comments is not worth reading to the end.
  for (int read = 0; read < 1000 && std::getline(*in, line); ++read) {
    if (line.starts_with("## ")) player_header = true;
    std::istringstream fields(line);
    std::string first;
    if (!(fields >> first) || first.starts_with('#')) continue;
    const bool numeric = first.find_first_not_of("0123456789.+-eE") == std::string::npos;
    return numeric ? LogFormat::kPlayer : LogFormat::kCarmen;
  }
  if (const auto error = in->error()) throw std::runtime_error(path.string() + ": " + *error);
  if (player_header) return LogFormat::kPlayer;
  throw std::runtime_error(path.string() +
                           ": neither a Player log (\"## Player version\" header, or lines starting with a "
                           "time) nor a CARMEN log (lines starting with a keyword such as FLASER)");
}

std::vector<protocol::DeviceAddress> parse_device_list(const std::string& text) {
  std::vector<protocol::DeviceAddress> devices;
  std::istringstream items(text);
  std::string item;
  while (std::getline(items, item, ',')) {
    const auto device = protocol::parse_device_address(item);
    if (!device) throw UsageError("--devices: '" + item + "' is not a device (laser:0, position, 6:1)");
    devices.push_back(*device);
  }
  if (devices.empty()) throw UsageError("--devices: no device named");
  return devices;
}

Output::Output(const std::string& path, std::ostream& standard_out) : path_(path), out_(&standard_out) {
  if (path == "-") {
    path_ = "stdout";
    return;
  }
  file_ = std::make_unique<std::ofstream>(path, std::ios::out | std::ios::trunc | std::ios::binary);
  if (!*file_) throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
  out_ = file_.get();
}

void Output::check() const {
  if (!*out_) throw std::runtime_error("cannot write " + path_ + ": " + std::strerror(errno));
}

void Output::flush_and_check() {
  out_->flush();
  check();
}

void Progress::show() {
  const auto now = std::chrono::steady_clock::now();
  if (shown_ && now - last_ < std::chrono::milliseconds(250)) return;
  last_ = now;
  shown_ = true;
  err_ << "\rplayer-log: " << count_ << " messages" << std::flush;
}

Progress::~Progress() {
  if (shown_) err_ << "\r\033[K" << std::flush;
}

}  // namespace playerkit::plog
