#include "line_feed.hpp"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <string>
#include <thread>

#include "client/client.hpp"
#include "json_line.hpp"
#include "text/line_reader.hpp"
#include "text/printable.hpp"
#include "usage_error.hpp"

namespace playerkit::player_send {

namespace {

using Clock = std::chrono::steady_clock;

bool is_blank(const std::string& line) {
  return std::all_of(line.begin(), line.end(), [](char c) { return std::isspace(static_cast<unsigned char>(c)); });
}

void report_stop(std::ostream& diagnostics, std::size_t line_number, const std::string& why) {
  diagnostics << "player-send: line " << line_number << ": " << text::printable(why) << "\n"
              << "player-send: stopped at line " << line_number
              << ": the lines before it were sent, nothing after it was read\n";
}

}  // namespace

ExitCode send_lines(std::istream& in, Sender& sender, std::optional<double> rate_hz, std::ostream& diagnostics) {
  const auto period = rate_hz ? std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / *rate_hz))
                              : Clock::duration::zero();
  auto next_due = Clock::now();
  ExitCode result = ExitCode::kAck;
  std::string line;
  for (std::size_t line_number = 1;; ++line_number) {
    try {
      if (!text::read_line(in, line, "stdin", static_cast<long long>(line_number))) break;
    } catch (const text::LineTooLongError&) {
      report_stop(diagnostics, line_number, "line longer than " + std::to_string(text::kMaxLineBytes) + " bytes");
      return ExitCode::kUsage;
    }
    if (is_blank(line)) continue;
    protocol::Message message;
    try {
      message = message_from_line(line);
    } catch (const UsageError& e) {
      report_stop(diagnostics, line_number, e.what());
      return ExitCode::kUsage;
    }
    if (rate_hz) {
      std::this_thread::sleep_until(next_due);
      // A slow server is not caught up with a burst: the pace restarts from now.
      next_due = std::max(next_due + period, Clock::now());
    }
    ExitCode code = ExitCode::kAck;
    try {
      code = sender.send(message);
    } catch (const client::ClientError& e) {
      report_stop(diagnostics, line_number, e.what());
      return ExitCode::kConnection;
    }
    if (message.type() == protocol::MessageType::kCommand && code != ExitCode::kAck) {
      report_stop(diagnostics, line_number, "the command could not be delivered");
      return code;
    }
    result = combine(result, code);
  }
  return result;
}

}  // namespace playerkit::player_send
