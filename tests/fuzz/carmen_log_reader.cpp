// A CARMEN log through log::CarmenLogReader as `player-log` and
// `amcl-offline` read one: times audited into a LogClock, read again with
// it, lenient and strict, and every record turned into Player messages
// (carmen_to_player, what `player-log convert` and readlog replay do).

#include <algorithm>
#include <sstream>
#include <stdexcept>
#include <string>
#include <variant>

#include "fuzz_support.hpp"
#include "fuzz_targets.hpp"
#include "log/carmen_log_reader.hpp"
#include "log/log_clock.hpp"
#include "log/log_conversion.hpp"
#include "log/log_parse_error.hpp"
#include "protocol/errors.hpp"
#include "protocol/payload_json.hpp"

namespace playerkit::fuzz {
namespace carmen_log_reader_detail {

constexpr const char* kName = "fuzz.clf";

std::vector<double> logged_times(const std::string& text) {
  std::istringstream in(text);
  log::CarmenLogReader reader(in, kName);
  std::vector<double> times;
  while (auto record = reader.next()) {
    if (std::holds_alternative<log::CarmenParam>(*record)) continue;
    times.push_back(std::visit([](const auto& r) { return r.stamp.logger_timestamp; }, *record));
  }
  return times;
}

void convert(const log::CarmenRecord& record) {
  log::PlayerMessages converted;
  try {
    converted = log::carmen_to_player(record);
  } catch (const std::invalid_argument&) {
    return;  // a scan Player cannot carry: documented
  }
  for (const auto& message : converted.messages) {
    try {
      (void)protocol::payload_to_json(message.header.device, message.type(), message.payload);
    } catch (const protocol::DecodeError&) {
      invariant_failed("carmen_log_reader", "carmen_to_player built a payload its struct does not decode");
    }
  }
}

void read_strict(const std::string& text) {
  std::istringstream in(text);
  log::CarmenLogReader reader(in, kName, {.strict = true});
  const auto calls = static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) + 2;
  for (std::size_t i = 0; i < calls; ++i) {
    try {
      if (!reader.next()) return;
    } catch (const log::LogParseError&) {
    }
  }
  invariant_failed("carmen_log_reader", "strict reading did not reach the end after a call per line");
}

}  // namespace carmen_log_reader_detail

int carmen_log_reader(const std::uint8_t* data, std::size_t size) {
  using namespace carmen_log_reader_detail;
  const std::string text(as_text({data, size}));
  auto clock = std::make_shared<const log::LogClock>(log::LogClock::audit(logged_times(text)));
  (void)clock->describe();
  std::istringstream in(text);
  log::CarmenLogReader reader(in, kName, {.clock = clock});
  while (auto record = reader.next()) convert(*record);
  if (reader.unknown_keywords().size() > log::CarmenLogReader::kMaxKeywords + 1) {
    invariant_failed("carmen_log_reader", "more unknown keywords kept than kMaxKeywords");
  }
  read_strict(text);
  return 0;
}

}  // namespace playerkit::fuzz
