#pragma once
// The PTU-46's answers (ptu46.md §1, §2.1), one line each: `*` done, `* <n>`
// a query's value in terse feedback, `* Current Pan position is 583` in
// verbose feedback, `! <message>` refused. The reset's `!T!T!P!P*` is the
// one line that starts with `!` and still means success.

#include <optional>
#include <string>
#include <string_view>

namespace playerkit::hardware::ptu46 {

struct Reply {
  enum class Kind {
    done,     // "*", "* <text>" with no number
    value,    // "* 583", "* 185.1428", "* Current Pan position is 583"
    refused,  // "! Maximum allowable Pan position is 3090"
    reset,    // "!T!T!P!P*": both axes recalibrated
  };
  Kind kind = Kind::done;
  std::optional<double> number;  // value: the number the reply ends with
  std::string text;              // refused: the message after "! "

  [[nodiscard]] bool ok() const { return kind != Kind::refused; }
};

// nullopt for a line that is no reply (empty, or neither `*` nor `!` first).
[[nodiscard]] std::optional<Reply> parse_reply(std::string_view line);

// The terse reply lines the unit writes (without their CR LF).
[[nodiscard]] std::string done_line();                        // "*"
[[nodiscard]] std::string value_line(double number);          // "* 583", "* 185.1428"
[[nodiscard]] std::string refusal_line(std::string_view why);  // "! <why>"
[[nodiscard]] std::string reset_line();                       // "!T!T!P!P*"

}  // namespace playerkit::hardware::ptu46
