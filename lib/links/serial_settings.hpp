#pragma once
// How a serial line is driven: speed, character framing, flow control, and
// how the port is opened. Defaults are what nearly every robot here uses
// (raw 8N1, no flow control) at the speed most of them power up with.

#include <string>
#include <string_view>

namespace playerkit::links {

enum class Parity { none, even, odd };
enum class FlowControl { none, hardware };  // hardware: RTS/CTS

struct SerialSettings {
  int baud = 9600;  // any positive rate; non-standard ones (500000 on FTDI) via termios2
  int data_bits = 8;  // 5..8
  Parity parity = Parity::none;
  int stop_bits = 1;  // 1 or 2
  FlowControl flow_control = FlowControl::none;
  // TIOCEXCL plus flock(LOCK_EX|LOCK_NB): a second opener, in this process or
  // another, gets a `busy` error instead of stealing half the bytes.
  bool exclusive = true;
  // Discard whatever the device sent before we opened (a pty keeps bytes
  // written while nobody had it open; Player's drivers flush at open too).
  bool flush_on_open = true;

  friend bool operator==(const SerialSettings&, const SerialSettings&) = default;
};

// "8N1", "8E1", "7O2": data bits, parity letter (N/E/O, either case), stop bits.
// Returns `base` with those three replaced; throws LinkError(bad_settings).
SerialSettings with_framing(std::string_view framing, SerialSettings base = {});

// "8N1"
std::string framing_name(const SerialSettings& settings);
// "38400 8N1", "115200 8N1 rtscts"
std::string to_string(const SerialSettings& settings);

// Throws LinkError(bad_settings) naming `port` when a field is out of range.
void validate(const SerialSettings& settings, std::string_view port);

// True for the rates termios has a B-constant for (50 .. 4000000).
bool is_standard_baud(int baud);

}  // namespace playerkit::links
