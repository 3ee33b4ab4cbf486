#include "files/temporary_cleanup.hpp"

#include <limits.h>
#include <signal.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cstring>
#include <mutex>

namespace playerkit::files {
namespace {

// Fixed storage: the handler must not touch memory another thread may free.
struct Slot {
  std::atomic<bool> used{false};
  char path[PATH_MAX]{};
};

std::array<Slot, 32> slots;
std::mutex slots_mutex;  // between threads taking slots; the handler only reads
constexpr std::array kFatalSignals{SIGINT, SIGTERM, SIGHUP};

extern "C" void remove_temporaries_and_die(int signal_number) {
  for (auto& slot : slots) {
    if (slot.used.load()) ::unlink(slot.path);
  }
  // Die of the signal, as without this handler (the shell sees 128 + n).
  ::signal(signal_number, SIG_DFL);
  ::raise(signal_number);
}

void install_handlers_once() {
  static std::once_flag installed;
  std::call_once(installed, [] {
    for (const int signal_number : kFatalSignals) {
      struct sigaction current {};
      if (::sigaction(signal_number, nullptr, &current) != 0) continue;
      if (current.sa_handler != SIG_DFL || (current.sa_flags & SA_SIGINFO) != 0) continue;  // the program's own
      struct sigaction action {};
      action.sa_handler = remove_temporaries_and_die;
      sigemptyset(&action.sa_mask);
      ::sigaction(signal_number, &action, nullptr);
    }
  });
}

}  // namespace

int remember_temporary(const std::string& path) {
  if (path.size() >= PATH_MAX) return -1;
  install_handlers_once();
  std::lock_guard lock(slots_mutex);
  for (std::size_t i = 0; i < slots.size(); ++i) {
    if (slots[i].used.load()) continue;
    std::memcpy(slots[i].path, path.c_str(), path.size() + 1);
    slots[i].used.store(true);
    return static_cast<int>(i);
  }
  return -1;
}

void forget_temporary(int slot) {
  if (slot < 0 || slot >= static_cast<int>(slots.size())) return;
  std::lock_guard lock(slots_mutex);
  slots[static_cast<std::size_t>(slot)].used.store(false);
}

}  // namespace playerkit::files
