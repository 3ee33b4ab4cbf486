#pragma once
// A pseudo-terminal pair for emulators and tests: the emulator holds the
// master, a driver opens the slave (or a symlink to it) as if it were
// /dev/ttyUSB0. Both sides raw; the kernel's initial speed is 38400 until
// the driver sets its own.
//
// What the driver does to its side is visible here: on Linux the master
// reports the slave's termios, so slave_baud() and slave_line() show the
// speed and framing the driver asked for (an emulator can drop bytes sent
// at the wrong speed, as a real device would).
//
// The driver closing and reopening the slave is normal (a driver restart).
// We keep no slave descriptor of our own, so the driver's close is seen
// exactly: the master then polls as hung up and reads EIO. Bytes written to
// the master meanwhile are kept by the kernel for the next opener (who
// usually flushes them), and the pty itself lives as long as the master.
// While nobody has the slave open, read_some() waits on an inotify watch of
// the slave device for the next open instead of polling the hung-up master
// in a loop. Without inotify it falls back to checking every 20 ms.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>

#include "links/deadline.hpp"
#include "links/fd_io.hpp"
#include "links/terminal_line.hpp"

namespace playerkit::links {

class PseudoTerminal {
 public:
  // Creates the pair. With `symlink`, also a symbolic link to the slave at
  // that path (replacing a stale symlink, refusing to replace anything else:
  // LinkError(busy)), removed again on destruction.
  explicit PseudoTerminal(std::optional<std::filesystem::path> symlink = std::nullopt);
  PseudoTerminal(const PseudoTerminal&) = delete;
  PseudoTerminal& operator=(const PseudoTerminal&) = delete;
  ~PseudoTerminal();

  // "/dev/pts/7"
  [[nodiscard]] const std::string& slave_path() const { return slave_path_; }
  // The path to give a driver: the symlink if there is one, else slave_path().
  [[nodiscard]] std::string path() const;
  [[nodiscard]] int master_fd() const { return master_.get(); }

  // The speed the slave's user set (c_ospeed through TCGETS2: numeric, also
  // for speeds set with BOTHER).
  [[nodiscard]] int slave_baud() const;
  [[nodiscard]] TerminalLine slave_line() const;

  struct Received {
    std::size_t count = 0;     // bytes the host wrote, now in the buffer
    bool host_opened = false;  // the host opened the slave during this call
    bool host_closed = false;  // the host closed it (after writing `count` bytes)
    // Both of the above, the close first: one session ended and the next one
    // began before this call, so `count` bytes belong to the new session.
    bool host_reopened = false;
  };
  // Waits until the host writes, opens or closes the slave, or until the
  // deadline; returns at once with any of those.
  Received read_some(std::span<std::uint8_t> buffer, Deadline deadline);

  // True while some program has the slave open (as of the last read_some).
  [[nodiscard]] bool host_connected() const { return host_connected_; }

  // Writes every byte to the host; false when the pty's buffer stayed full
  // until the deadline (nobody reading: a real line would drop them too).
  bool write_all(std::span<const std::uint8_t> bytes, Deadline deadline);

 private:
  void watch_slave();
  // Applies queued inotify events; sets the flags on transitions.
  void take_open_events(Received& received);
  void mark_closed(Received& received);

  UniqueFd master_;
  UniqueFd inotify_;  // invalid when inotify is unavailable
  std::string slave_path_;
  std::optional<std::filesystem::path> symlink_;
  int open_descriptions_ = 0;  // host opens minus closes, from inotify
  bool master_hung_up_ = false;
  bool host_connected_ = false;
};

}  // namespace playerkit::links
