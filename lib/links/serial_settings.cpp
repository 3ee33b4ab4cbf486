#include "links/serial_settings.hpp"

#include <algorithm>
#include <array>

#include "links/link_error.hpp"

namespace playerkit::links {

namespace {

constexpr std::array kStandardBauds = {50,     75,     110,    134,     150,     200,     300,     600,
                                       1200,   1800,   2400,   4800,    9600,    19200,   38400,   57600,
                                       115200, 230400, 460800, 500000,  576000,  921600,  1000000, 1152000,
                                       1500000, 2000000, 2500000, 3000000, 3500000, 4000000};

// Far above any UART this toolkit will meet; catches typos like 1152000O.
constexpr int kMaximumBaud = 20'000'000;

char parity_letter(Parity parity) {
  switch (parity) {
    case Parity::none: return 'N';
    case Parity::even: return 'E';
    case Parity::odd: return 'O';
  }
  return '?';
}

[[noreturn]] void reject(std::string_view port, const std::string& why) {
  throw LinkError(LinkErrorKind::bad_settings, std::string(port), std::string(port) + ": " + why);
}

}  // namespace

SerialSettings with_framing(std::string_view framing, SerialSettings base) {
  const auto bad = [&]() {
    throw LinkError(LinkErrorKind::bad_settings, "",
                    "bad serial framing '" + std::string(framing) + "': expected data bits, parity, stop bits "
                    "like 8N1, 8E1 or 7O2");
  };
  if (framing.size() != 3) bad();
  if (framing[0] < '5' || framing[0] > '8') bad();
  if (framing[2] != '1' && framing[2] != '2') bad();
  switch (framing[1]) {
    case 'N': case 'n': base.parity = Parity::none; break;
    case 'E': case 'e': base.parity = Parity::even; break;
    case 'O': case 'o': base.parity = Parity::odd; break;
    default: bad();
  }
  base.data_bits = framing[0] - '0';
  base.stop_bits = framing[2] - '0';
  return base;
}

std::string framing_name(const SerialSettings& settings) {
  return std::to_string(settings.data_bits) + parity_letter(settings.parity) + std::to_string(settings.stop_bits);
}

std::string to_string(const SerialSettings& settings) {
  std::string text = std::to_string(settings.baud) + " " + framing_name(settings);
  if (settings.flow_control == FlowControl::hardware) text += " rtscts";
  return text;
}

void validate(const SerialSettings& settings, std::string_view port) {
  if (settings.baud <= 0 || settings.baud > kMaximumBaud) {
    reject(port, "baud rate " + std::to_string(settings.baud) + " is out of range (1.." +
                     std::to_string(kMaximumBaud) + ")");
  }
  if (settings.data_bits < 5 || settings.data_bits > 8) {
    reject(port, std::to_string(settings.data_bits) + " data bits; a serial line carries 5 to 8");
  }
  if (settings.stop_bits != 1 && settings.stop_bits != 2) {
    reject(port, std::to_string(settings.stop_bits) + " stop bits; use 1 or 2");
  }
}

bool is_standard_baud(int baud) {
  return std::find(kStandardBauds.begin(), kStandardBauds.end(), baud) != kStandardBauds.end();
}

}  // namespace playerkit::links
