#pragma once
// The whitespace-separated tokens of one Player text log line with their
// byte offsets, so that a token can be read as a number or replaced in place
// (the rest of the line kept byte for byte), and where the columns of a data
// line are (logfile-format.md): for programs that edit logs as text
// (odometry perturbation) or read a pose without decoding the whole line.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace playerkit::log {

struct LineToken {
  std::size_t offset = 0;  // byte offset in the line
  std::string_view text;
};

std::vector<LineToken> split_line_tokens(std::string_view line);

// The token as a number ("+01.250" and "1.13486e+09" alike). Throws
// std::runtime_error naming `what` when it is not one.
double token_number(const LineToken& token, std::string_view what);

// Replaces tokens [first, first + replacements.size()) of `line` with
// `replacements`, keeping every other byte. `tokens` must be those of `line`.
std::string replace_tokens(std::string_view line, const std::vector<LineToken>& tokens, std::size_t first,
                           const std::vector<std::string>& replacements);

// The columns of a data line: time host robot interface index data_time,
// then the data fields.
inline constexpr std::size_t kInterfaceColumn = 3;
inline constexpr std::size_t kIndexColumn = 4;
inline constexpr std::size_t kDataTimeColumn = 5;
inline constexpr std::size_t kFirstFieldColumn = 6;

// A pose as the text of a position or truth line writes it (metres, radians).
struct TextPose {
  double x = 0;
  double y = 0;
  double yaw = 0;
};

// Where x, y and yaw are: the first three fields, except in format 0.2.0's
// 3-D truth (x y z roll pitch yaw).
struct PoseColumns {
  std::size_t x = kFirstFieldColumn;
  std::size_t y = kFirstFieldColumn + 1;
  std::size_t yaw = kFirstFieldColumn + 2;
};
PoseColumns pose_columns(bool truth_0_2_0);

// The pose of a position or truth line's tokens. Throws std::runtime_error
// when the line is too short or a column is not a number.
TextPose read_text_pose(const std::vector<LineToken>& tokens, bool truth_0_2_0);

// printf-style into a std::string.
std::string format_text(const char* format, double value);

}  // namespace playerkit::log
