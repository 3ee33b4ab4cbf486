#pragma once
// A terminal's line settings through termios2 (TCGETS2/TCSETS2), the only
// interface that takes and reports any numeric speed: 500000 for a SICK LMS
// on an FTDI adapter, which the B-constant API cannot express portably.
// <asm/termbits.h> clashes with <termios.h>, so only terminal_line.cpp
// includes it and this header speaks in our own types.
//
// On Linux a pty master reports (and sets) its slave's settings, so these
// functions on a master fd show what the program on the slave asked for:
// speed, stop bits, flow control and raw mode. Not data bits or parity: the
// pty driver forces CS8 without PARENB on every change.

#include <string_view>

#include "links/serial_settings.hpp"

namespace playerkit::links {

struct TerminalLine {
  int input_baud = 0;   // c_ispeed: numeric, also for B-constants
  int output_baud = 0;  // c_ospeed
  bool custom_speed = false;  // set as BOTHER + number rather than a B-constant
  int data_bits = 8;
  Parity parity = Parity::none;
  int stop_bits = 1;
  FlowControl flow_control = FlowControl::none;
  bool raw = false;  // no echo, no line editing, no signals, no byte translation
};

// Raw mode (as cfmakeraw), the settings' speed and framing, receiver on,
// modem lines ignored, one byte satisfies a read. Throws LinkError naming
// `port`: bad_settings when the port refuses (or visibly rounds) the speed,
// not_a_terminal when fd is not a tty, io_error otherwise.
void configure_terminal(int fd, const SerialSettings& settings, std::string_view port);

// Changes only the speed, at once (bytes still queued may leave at the new
// speed: drain first when that matters). Throws like configure_terminal.
void set_terminal_speed(int fd, int baud, std::string_view port);

// Raw mode keeping the current speed and framing (a fresh pty).
void make_terminal_raw(int fd, std::string_view port);

// Throws LinkError(not_a_terminal / io_error).
TerminalLine read_terminal_line(int fd, std::string_view port);

}  // namespace playerkit::links
