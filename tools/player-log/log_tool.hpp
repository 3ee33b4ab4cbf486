#pragma once
// What the player-log subcommands share: exit codes, usage errors, the two
// log formats, device lists, output files (tools/common) and progress on a
// terminal.

#include <chrono>
#include <cstdint>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "exit_status.hpp"
#include "log/log_format_detection.hpp"
#include "output_file.hpp"
#include "protocol/device_address.hpp"

namespace playerkit::plog {

// 1: unreadable file, malformed line with --strict, server problems.
using tools::kExitFailure;
using tools::kExitOk;
using tools::kExitUsage;
using tools::UsageError;

// The two log formats, told apart by content (lib/log/log_format_detection).
using log::detect_log_format;
using log::LogFormat;

// "laser:0,position:0" (a bare interface is index 0). Throws UsageError.
std::vector<protocol::DeviceAddress> parse_device_list(const std::string& text);

using tools::OutputFile;

// "\rplayer-log: N messages" on stderr a few times a second, when enabled
// (main enables it when stderr is a terminal); cleared at the end.
class Progress {
 public:
  Progress(std::ostream& err, bool enabled) : err_(err), enabled_(enabled) {}
  ~Progress();
  void tick() {
    ++count_;
    if (enabled_ && (count_ & 1023u) == 0) show();
  }

 private:
  void show();
  std::ostream& err_;
  bool enabled_;
  std::uint64_t count_ = 0;
  std::chrono::steady_clock::time_point last_{};
  bool shown_ = false;
};

}  // namespace playerkit::plog
