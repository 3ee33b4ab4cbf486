// A Player text log through log::TextLogReader as `player-log` reads one:
// its format detected, its times audited (the LogClock the file's readers
// get), then read again with that clock, lenient and strict, and its data
// turned into CARMEN records (`player-log convert`). A payload the reader
// builds must be one its interface's struct decodes.

#include <algorithm>
#include <sstream>
#include <string>
#include <variant>

#include "fuzz_support.hpp"
#include "fuzz_targets.hpp"
#include "log/log_clock.hpp"
#include "log/log_conversion.hpp"
#include "log/log_format_detection.hpp"
#include "log/log_parse_error.hpp"
#include "log/text_log_reader.hpp"
#include "protocol/errors.hpp"
#include "protocol/payload_json.hpp"

namespace playerkit::fuzz {
namespace player_log_reader_detail {

constexpr const char* kName = "fuzz.log";

std::vector<double> logged_times(const std::string& text) {
  std::istringstream in(text);
  log::TextLogReader reader(in, kName);
  std::vector<double> times;
  while (auto line = reader.next()) {
    times.push_back(std::visit([](const auto& l) { return l.server_time.seconds(); }, *line));
  }
  return times;
}

void check_data(const log::DataLine& line, log::PlayerToCarmen& converter) {
  const auto& message = line.message;
  if (message.header.size != message.payload.size()) {
    invariant_failed("player_log_reader", "a message whose header size is not its payload's");
  }
  if (!message.payload.empty()) {
    try {
      (void)protocol::payload_to_json(message.header.device, protocol::MessageType::kData, message.payload);
    } catch (const protocol::DecodeError&) {
      invariant_failed("player_log_reader", "the reader built a payload its struct does not decode");
    }
  }
  try {
    converter.feed(message, line.host);
  } catch (const protocol::DecodeError&) {
    // A line without fields has an empty payload: convert refuses it too.
  }
}

// Strict reading throws per malformed line and keeps its place: at most one
// call per line and one for the end.
void read_strict(const std::string& text) {
  std::istringstream in(text);
  log::TextLogReader reader(in, kName, {.strict = true});
  const auto calls = static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) + 2;
  for (std::size_t i = 0; i < calls; ++i) {
    try {
      if (!reader.next()) return;
    } catch (const log::LogParseError&) {
    }
  }
  invariant_failed("player_log_reader", "strict reading did not reach the end after a call per line");
}

}  // namespace player_log_reader_detail

int player_log_reader(const std::uint8_t* data, std::size_t size) {
  using namespace player_log_reader_detail;
  const std::string text(as_text({data, size}));
  {
    std::istringstream in(text);
    try {
      (void)log::detect_log_format(in, kName);
    } catch (const std::runtime_error&) {
    }
  }
  try {
    auto clock = std::make_shared<const log::LogClock>(log::LogClock::audit(logged_times(text)));
    (void)clock->describe();
    std::istringstream in(text);
    log::TextLogReader reader(in, kName, {.clock = clock});
    log::PlayerToCarmen converter;
    while (auto line = reader.next()) {
      if (const auto* data_line = std::get_if<log::DataLine>(&*line)) check_data(*data_line, converter);
    }
    converter.finish();
    (void)converter.take_records();
  } catch (const log::LogParseError&) {
    // An unknown file version, which ends reading strict or not.
  }
  read_strict(text);
  return 0;
}

}  // namespace playerkit::fuzz
