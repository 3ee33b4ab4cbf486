#pragma once
// One line of `player-send --stdin`: a JSON object naming a device and what to
// send it. Two forms:
//
//   short:  {"device":"position:0","data":{"xspeed":200}}                    a command
//           {"device":"mcom:0","request":"push","data":{"channel":"news"}}  a request
//   full:   what message_to_json (player-cat --format json) prints:
//           {"type":"cmd","device":"position","index":0,"data":{...}}
//
// "type" is "cmd" or "req" (default: "req" when "request" is named, else
// "cmd"); "time" and "timestamp" are accepted and ignored; a missing "data" is
// all zeros; {"raw":[bytes]} as data sends those bytes. Other keys are errors,
// so a misspelt "dta" is not sent as zeros.

#include <string_view>

#include "protocol/message.hpp"

namespace playerkit::player_send {

// Throws UsageError saying what is wrong with the line (not its number: the
// caller knows it).
protocol::Message message_from_line(std::string_view line);

}  // namespace playerkit::player_send
