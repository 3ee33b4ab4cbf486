// One line of JSON a person wrote, through player_send::message_from_line:
// what `player-send --stdin` reads, short form or player-cat's full form. A
// line it accepts must go on the wire as bytes that read back as the same
// message, and survive player-cat's JSON and player-send's reading of it
// twice unchanged (player-cat --format json | player-send --stdin). The
// first pass may normalise (a {"raw":[...]} payload that decodes as its
// struct comes back as fields); from then on nothing may change.

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "fuzz_support.hpp"
#include "fuzz_targets.hpp"
#include "json_line.hpp"
#include "protocol/errors.hpp"
#include "protocol/message.hpp"
#include "protocol/message_json.hpp"
#include "usage_error.hpp"

namespace playerkit::fuzz {
namespace json_line_detail {

// message_to_json, then what player-send does with that line; nullopt when
// the payload does not decode as its struct (raw bytes sent on purpose).
std::optional<protocol::Message> through_json(const protocol::Message& message) {
  nlohmann::json j;
  try {
    j = protocol::message_to_json(message);
  } catch (const protocol::DecodeError&) {
    return std::nullopt;
  }
  try {
    return player_send::message_from_line(j.dump());
  } catch (const player_send::UsageError& error) {
    invariant_failed("json_line", ("player-cat's JSON of an accepted line is refused: " + std::string(error.what())).c_str());
  }
}

}  // namespace json_line_detail

int json_line(const std::uint8_t* data, std::size_t size) {
  protocol::Message message;
  try {
    message = player_send::message_from_line(as_text({data, size}));
  } catch (const player_send::UsageError&) {
    return 0;
  }

  const auto bytes = protocol::encode_message(message);
  std::optional<protocol::ParsedMessage> parsed;
  try {
    parsed = protocol::parse_message(bytes);
  } catch (const protocol::DecodeError&) {
    invariant_failed("json_line", "an accepted line encodes to a message the frame reader refuses");
  }
  if (!parsed || parsed->consumed != bytes.size() || parsed->message != message) {
    invariant_failed("json_line", "an accepted line's bytes do not read back as the same message");
  }

  const auto once = json_line_detail::through_json(message);
  if (!once) return 0;
  const auto twice = json_line_detail::through_json(*once);
  if (!twice || *twice != *once) {
    invariant_failed("json_line", "a message changed on its second trip through JSON");
  }
  return 0;
}

}  // namespace playerkit::fuzz
