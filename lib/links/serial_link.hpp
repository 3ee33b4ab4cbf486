#pragma once
// A serial port (or the slave side of a pseudo-terminal) as a ByteLink:
// raw mode, any speed (termios2), 5-8 data bits, parity, 1-2 stop bits,
// speed changes while open, and exclusive use.
//
// It never uses TIOCGSERIAL/TIOCSSERIAL (Player 1.5's SICK driver did, and
// fails on a pty with ENOTTY): non-standard speeds go through termios2, so
// the same code runs on an FTDI adapter and on an emulator's pty.

#include <memory>
#include <string>

#include "links/byte_link.hpp"
#include "links/fd_io.hpp"
#include "links/serial_settings.hpp"
#include "links/terminal_line.hpp"

namespace playerkit::links {

class SerialLink final : public ByteLink {
 public:
  // Opens `path` read/write without becoming its controlling terminal, takes
  // it exclusively (unless settings.exclusive is false), configures it and
  // flushes stale input (unless settings.flush_on_open is false). Throws
  // LinkError naming the port: missing, permission_denied, busy,
  // not_a_terminal, bad_settings, io_error.
  static std::unique_ptr<SerialLink> open(const std::string& path, const SerialSettings& settings);

  ~SerialLink() override;

  void flush_input() override;
  void drain() override;
  void close() noexcept override;
  [[nodiscard]] bool is_open() const override { return fd_.valid(); }
  // Same path, the current settings (including a speed set since).
  void reopen(Deadline deadline) override;

  // Always true (or throws bad_settings / closed).
  bool set_baud(int baud) override;
  [[nodiscard]] int baud() const override { return settings_.baud; }

  // "/dev/ttyUSB0 at 38400 8N1"
  [[nodiscard]] std::string describe() const override;
  [[nodiscard]] int native_handle() const override { return fd_.get(); }

  [[nodiscard]] const std::string& path() const { return path_; }
  [[nodiscard]] const SerialSettings& settings() const { return settings_; }
  // The line as the port reports it now.
  [[nodiscard]] TerminalLine line() const;

  // Sets DTR and RTS (some devices use them as power or reset lines).
  // Returns false where the port has no modem lines (a pty).
  bool set_modem_lines(bool dtr, bool rts);

 protected:
  std::size_t read_available(std::span<std::uint8_t> buffer, Deadline deadline) override;
  std::size_t write_available(std::span<const std::uint8_t> bytes, Deadline deadline) override;

 private:
  SerialLink(std::string path, const SerialSettings& settings);
  void open_device();
  int checked_fd() const;

  std::string path_;
  SerialSettings settings_;
  UniqueFd fd_;
};

}  // namespace playerkit::links
