#pragma once
// FIELD=VALUE arguments into the JSON object the protocol's codecs read:
//
//   xspeed=200 yawspeed=10      {"xspeed":200,"yawspeed":10}
//   pose=[1,2,3]                {"pose":[1,2,3]}
//   pose.1=90                   {"pose":[0,90]}          (missing elements are zero)
//   id.code=26 id.port=6665     {"id":{"code":26,"port":6665}}
//   channel=news                {"channel":"news"}       (not JSON: taken as text)
//   channel='"42"'              {"channel":"42"}         (JSON quotes force text)
//
// Field names are checked later, by the struct's codec; here only the form is.

#include <span>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace playerkit::player_send {

// A JSON value (number, string, list, object, true/false/null); any other text
// is a string as written. Never throws.
nlohmann::json parse_value(std::string_view text);

// Throws UsageError naming the argument: no '=', an empty or malformed field
// path, a field given twice, a path that treats a list as a struct or back.
nlohmann::json parse_field_assignments(std::span<const std::string> assignments);

}  // namespace playerkit::player_send
