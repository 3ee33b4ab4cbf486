#include "links/pseudo_terminal.hpp"

#include <fcntl.h>
#include <poll.h>
#include <stdlib.h>
#include <sys/inotify.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>

#include "links/link_error.hpp"

namespace playerkit::links {

namespace {

namespace fs = std::filesystem;

constexpr std::string_view kPtyMultiplexer = "/dev/ptmx";
// Only without inotify: how often a hung-up master is checked for a reopen.
constexpr auto kReopenCheckInterval = std::chrono::milliseconds(20);

timespec remaining_until(Deadline deadline) {
  const auto remaining = std::max(deadline - LinkClock::now(), LinkClock::duration::zero());
  const auto nanoseconds = std::chrono::duration_cast<std::chrono::nanoseconds>(remaining).count();
  return {static_cast<time_t>(nanoseconds / 1'000'000'000), static_cast<long>(nanoseconds % 1'000'000'000)};
}

bool master_hangs_up(int master) {
  pollfd entry{.fd = master, .events = POLLIN, .revents = 0};
  return ::poll(&entry, 1, 0) > 0 && (entry.revents & POLLHUP) != 0;
}

}  // namespace

PseudoTerminal::PseudoTerminal(std::optional<fs::path> symlink) {
  master_.reset(::posix_openpt(O_RDWR | O_NOCTTY | O_CLOEXEC));
  if (!master_.valid()) throw system_error(kPtyMultiplexer, "cannot create a pseudo-terminal", errno);
  if (::grantpt(master_.get()) != 0 || ::unlockpt(master_.get()) != 0) {
    throw system_error(kPtyMultiplexer, "cannot unlock the pseudo-terminal", errno);
  }
  std::array<char, 128> name{};
  if (::ptsname_r(master_.get(), name.data(), name.size()) != 0) {
    throw system_error(kPtyMultiplexer, "cannot name the pseudo-terminal", errno);
  }
  slave_path_ = name.data();
  const int flags = ::fcntl(master_.get(), F_GETFL);
  if (flags < 0 || ::fcntl(master_.get(), F_SETFL, flags | O_NONBLOCK) != 0) {
    throw system_error(slave_path_, "cannot make the master non-blocking", errno);
  }
  // Through the master this sets the slave: no echo of what we write, no
  // line editing, no CR/LF translation before the driver ever opens it.
  make_terminal_raw(master_.get(), slave_path_);
  watch_slave();
  if (symlink) {
    std::error_code error;
    if (fs::is_symlink(*symlink, error)) {
      fs::remove(*symlink, error);
    } else if (fs::exists(*symlink, error)) {
      throw LinkError(LinkErrorKind::busy, symlink->string(),
                      symlink->string() + " exists and is not a symlink; refusing to replace it");
    }
    fs::create_symlink(slave_path_, *symlink, error);
    if (error) {
      throw LinkError(LinkErrorKind::io_error, symlink->string(),
                      "cannot create symlink " + symlink->string() + " -> " + slave_path_ + ": " + error.message());
    }
    symlink_ = std::move(symlink);
  }
}

PseudoTerminal::~PseudoTerminal() {
  if (!symlink_) return;
  // Only our own: another emulator may have taken the name over since.
  std::error_code error;
  if (fs::read_symlink(*symlink_, error) == fs::path(slave_path_) && !error) fs::remove(*symlink_, error);
}

void PseudoTerminal::watch_slave() {
  UniqueFd watcher(::inotify_init1(IN_NONBLOCK | IN_CLOEXEC));
  if (!watcher.valid()) return;
  if (::inotify_add_watch(watcher.get(), slave_path_.c_str(), IN_OPEN | IN_CLOSE_WRITE | IN_CLOSE_NOWRITE) < 0) {
    return;
  }
  inotify_ = std::move(watcher);
}

std::string PseudoTerminal::path() const { return symlink_ ? symlink_->string() : slave_path_; }

int PseudoTerminal::slave_baud() const { return slave_line().output_baud; }

TerminalLine PseudoTerminal::slave_line() const { return read_terminal_line(master_.get(), slave_path_); }

void PseudoTerminal::mark_closed(Received& received) {
  open_descriptions_ = 0;
  if (host_connected_) {
    received.host_closed = true;
    received.host_reopened = false;  // whatever opened before is closed again
  }
  host_connected_ = false;
}

void PseudoTerminal::take_open_events(Received& received) {
  if (!inotify_.valid()) return;
  alignas(inotify_event) std::array<char, 4096> events{};
  while (true) {
    const ssize_t count = ::read(inotify_.get(), events.data(), events.size());
    if (count <= 0) return;  // EAGAIN: nothing queued
    for (std::size_t offset = 0; offset < static_cast<std::size_t>(count);) {
      inotify_event event{};
      std::memcpy(&event, events.data() + offset, sizeof event);
      offset += sizeof event + event.len;
      if ((event.mask & IN_OPEN) != 0 && open_descriptions_++ == 0) {
        host_connected_ = true;
        master_hung_up_ = false;
        received.host_opened = true;
        received.host_reopened = received.host_closed;
      }
      if ((event.mask & (IN_CLOSE_WRITE | IN_CLOSE_NOWRITE)) != 0 && open_descriptions_ > 0 &&
          --open_descriptions_ == 0) {
        mark_closed(received);
      }
      if ((event.mask & IN_Q_OVERFLOW) != 0) {
        // Lost count: the master's hang-up state is the truth for "anyone".
        open_descriptions_ = master_hangs_up(master_.get()) ? 0 : std::max(open_descriptions_, 1);
        if (open_descriptions_ == 0) mark_closed(received);
      }
      if ((event.mask & IN_IGNORED) != 0) inotify_.reset();
    }
    if (!inotify_.valid()) return;
  }
}

PseudoTerminal::Received PseudoTerminal::read_some(std::span<std::uint8_t> buffer, Deadline deadline) {
  Received received;
  while (true) {
    take_open_events(received);
    if (!master_hung_up_ && !buffer.empty()) {
      const ssize_t count = ::read(master_.get(), buffer.data(), buffer.size());
      if (count > 0) {
        received.count = static_cast<std::size_t>(count);
        if (!inotify_.valid() && !host_connected_) {
          host_connected_ = true;
          received.host_opened = true;
        }
        return received;
      }
      if (count == 0 || errno == EIO) {
        // Every slave descriptor is closed. The inotify close event was
        // queued before this became visible; take it first.
        take_open_events(received);
        master_hung_up_ = true;
        mark_closed(received);
      } else if (errno == EINTR) {
        continue;
      } else if (errno != EAGAIN && errno != EWOULDBLOCK) {
        throw system_error(slave_path_, "reading the pty master failed", errno);
      }
    }
    if (received.host_opened || received.host_closed || LinkClock::now() >= deadline) return received;

    std::array<pollfd, 2> watched{};
    nfds_t count = 0;
    if (!master_hung_up_) watched[count++] = {.fd = master_.get(), .events = POLLIN, .revents = 0};
    if (inotify_.valid()) watched[count++] = {.fd = inotify_.get(), .events = POLLIN, .revents = 0};
    Deadline until = deadline;
    const bool check_for_reopen = master_hung_up_ && !inotify_.valid();
    if (check_for_reopen) until = std::min(deadline, LinkClock::now() + kReopenCheckInterval);
    const timespec timeout = remaining_until(until);
    if (::ppoll(watched.data(), count, &timeout, nullptr) < 0 && errno != EINTR) {
      throw system_error(slave_path_, "waiting on the pty failed", errno);
    }
    if (check_for_reopen && !master_hangs_up(master_.get())) {
      master_hung_up_ = false;
      host_connected_ = true;
      received.host_opened = true;
      received.host_reopened = received.host_closed;
    }
  }
}

bool PseudoTerminal::write_all(std::span<const std::uint8_t> bytes, Deadline deadline) {
  return write_with_deadline(master_.get(), bytes, deadline, slave_path_, false) == bytes.size();
}

}  // namespace playerkit::links
