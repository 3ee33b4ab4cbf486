// The only file that includes <asm/termbits.h> (see terminal_line.hpp).
#include "links/terminal_line.hpp"

#include <asm/ioctls.h>
#include <asm/termbits.h>
#include <sys/ioctl.h>

#include <cerrno>
#include <cstdlib>
#include <string>

#include "links/link_error.hpp"

namespace playerkit::links {

namespace {

struct SpeedCode {
  int baud;
  tcflag_t code;
};

constexpr SpeedCode kSpeedCodes[] = {
    {50, B50},           {75, B75},           {110, B110},         {134, B134},         {150, B150},
    {200, B200},         {300, B300},         {600, B600},         {1200, B1200},       {1800, B1800},
    {2400, B2400},       {4800, B4800},       {9600, B9600},       {19200, B19200},     {38400, B38400},
    {57600, B57600},     {115200, B115200},   {230400, B230400},   {460800, B460800},   {500000, B500000},
    {576000, B576000},   {921600, B921600},   {1000000, B1000000}, {1152000, B1152000}, {1500000, B1500000},
    {2000000, B2000000}, {2500000, B2500000}, {3000000, B3000000}, {3500000, B3500000}, {4000000, B4000000},
};

tcflag_t speed_code(int baud) {
  for (const auto& entry : kSpeedCodes) {
    if (entry.baud == baud) return entry.code;
  }
  return BOTHER;
}

termios2 get(int fd, std::string_view port) {
  termios2 settings{};
  if (::ioctl(fd, TCGETS2, &settings) != 0) {
    if (errno == ENOTTY || errno == EINVAL) {
      throw LinkError(LinkErrorKind::not_a_terminal, std::string(port),
                      std::string(port) + " is not a terminal (a serial port or pseudo-terminal was expected)");
    }
    throw system_error(port, "reading the line settings failed", errno);
  }
  return settings;
}

void put(int fd, const termios2& settings, std::string_view port, int baud) {
  if (::ioctl(fd, TCSETS2, &settings) == 0) return;
  if (errno == EINVAL) {
    throw LinkError(LinkErrorKind::bad_settings, std::string(port),
                    std::string(port) + " refuses these line settings (" + std::to_string(baud) + " baud)");
  }
  if (errno == ENOTTY) get(fd, port);  // throws the not-a-terminal error
  throw system_error(port, "setting the line failed", errno);
}

void put_speed(termios2& settings, int baud) {
  const tcflag_t code = speed_code(baud);
  settings.c_cflag &= ~(CBAUD | (CBAUD << IBSHIFT));
  settings.c_cflag |= code | (code << IBSHIFT);
  settings.c_ispeed = static_cast<speed_t>(baud);
  settings.c_ospeed = static_cast<speed_t>(baud);
}

// A UART whose clock cannot make the rate rounds it and reports the rate it
// made; more than 2 % off garbles every byte, so say so at open.
void check_speed(int fd, int baud, std::string_view port) {
  const termios2 actual = get(fd, port);
  const long made = static_cast<long>(actual.c_ospeed);
  if (std::labs(made - baud) * 50 > baud) {
    throw LinkError(LinkErrorKind::bad_settings, std::string(port),
                    std::string(port) + " cannot run at " + std::to_string(baud) + " baud (it set " +
                        std::to_string(made) + ")");
  }
}

void make_raw(termios2& settings) {
  settings.c_iflag &= ~(IGNBRK | BRKINT | PARMRK | ISTRIP | INLCR | IGNCR | ICRNL | IXON | IXOFF | IXANY | INPCK);
  settings.c_oflag &= ~OPOST;
  settings.c_lflag &= ~(ECHO | ECHONL | ICANON | ISIG | IEXTEN);
  settings.c_cflag |= CREAD | CLOCAL;
  settings.c_cc[VMIN] = 1;
  settings.c_cc[VTIME] = 0;
}

}  // namespace

void configure_terminal(int fd, const SerialSettings& settings, std::string_view port) {
  validate(settings, port);
  termios2 line = get(fd, port);
  make_raw(line);
  line.c_cflag &= ~(CSIZE | PARENB | PARODD | CMSPAR | CSTOPB | CRTSCTS);
  switch (settings.data_bits) {
    case 5: line.c_cflag |= CS5; break;
    case 6: line.c_cflag |= CS6; break;
    case 7: line.c_cflag |= CS7; break;
    default: line.c_cflag |= CS8; break;
  }
  if (settings.parity != Parity::none) line.c_cflag |= PARENB;
  if (settings.parity == Parity::odd) line.c_cflag |= PARODD;
  if (settings.stop_bits == 2) line.c_cflag |= CSTOPB;
  if (settings.flow_control == FlowControl::hardware) line.c_cflag |= CRTSCTS;
  put_speed(line, settings.baud);
  put(fd, line, port, settings.baud);
  check_speed(fd, settings.baud, port);
}

void set_terminal_speed(int fd, int baud, std::string_view port) {
  SerialSettings check;
  check.baud = baud;
  validate(check, port);
  termios2 line = get(fd, port);
  put_speed(line, baud);
  put(fd, line, port, baud);
  check_speed(fd, baud, port);
}

void make_terminal_raw(int fd, std::string_view port) {
  termios2 line = get(fd, port);
  make_raw(line);
  put(fd, line, port, static_cast<int>(line.c_ospeed));
}

TerminalLine read_terminal_line(int fd, std::string_view port) {
  const termios2 line = get(fd, port);
  TerminalLine decoded;
  decoded.input_baud = static_cast<int>(line.c_ispeed);
  decoded.output_baud = static_cast<int>(line.c_ospeed);
  decoded.custom_speed = (line.c_cflag & CBAUD) == BOTHER;
  switch (line.c_cflag & CSIZE) {
    case CS5: decoded.data_bits = 5; break;
    case CS6: decoded.data_bits = 6; break;
    case CS7: decoded.data_bits = 7; break;
    default: decoded.data_bits = 8; break;
  }
  if ((line.c_cflag & PARENB) != 0) decoded.parity = (line.c_cflag & PARODD) != 0 ? Parity::odd : Parity::even;
  decoded.stop_bits = (line.c_cflag & CSTOPB) != 0 ? 2 : 1;
  decoded.flow_control = (line.c_cflag & CRTSCTS) != 0 ? FlowControl::hardware : FlowControl::none;
  decoded.raw = (line.c_lflag & (ICANON | ECHO | ISIG | IEXTEN)) == 0 && (line.c_oflag & OPOST) == 0 &&
                (line.c_iflag & (ICRNL | INLCR | IGNCR | ISTRIP | IXON)) == 0;
  return decoded;
}

}  // namespace playerkit::links
