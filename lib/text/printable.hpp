#pragma once
// Input quoted in a message, made safe for a terminal. Config files, logs and
// command-line arguments may hold any bytes; copied raw into an error message
// they can move the cursor, recolour or clear the screen, or hide the rest of
// the message. Every message that quotes input passes it through here.
//
//   throw Error("unknown driver '" + text::excerpt(name) + "'");
//   std::cerr << text::printable(error.what()) << '\n';

#include <cstddef>
#include <string>
#include <string_view>

namespace playerkit::text {

// The longest excerpt of input a message quotes, in bytes of escaped text: a
// line's worth, enough to recognise what was written.
inline constexpr std::size_t kMaxExcerptBytes = 80;

// `text` with every character a terminal would act on shown escaped:
// \n \r \t, \xHH for other C0 controls, DEL and bytes that are not UTF-8,
// \uHHHH for C1 controls, bidirectional overrides and line separators.
// Printable ASCII and valid UTF-8 stay as they are, and backslashes are not
// doubled, so that escaping twice changes nothing.
std::string printable(std::string_view text);

// printable(text) cut to at most max_bytes (never inside a character or an
// escape), with "…" appended when something was cut.
std::string excerpt(std::string_view text, std::size_t max_bytes = kMaxExcerptBytes);

// One character a lexer did not expect, for its syntax error: "character ','"
// when printable ASCII, else "byte 0x1B".
std::string describe_character(char c);

}  // namespace playerkit::text
