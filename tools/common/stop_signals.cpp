#include "stop_signals.hpp"

#include <csignal>

namespace playerkit::tools {

namespace {

volatile std::sig_atomic_t received_signal = 0;

extern "C" void remember_signal(int signal_number) { received_signal = signal_number; }

}  // namespace

void ignore_broken_pipes() { std::signal(SIGPIPE, SIG_IGN); }

void install_stop_signals() {
  struct sigaction action {};
  action.sa_handler = remember_signal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
  ignore_broken_pipes();
}

bool stop_requested() { return received_signal != 0; }

int stop_signal_number() { return received_signal; }

}  // namespace playerkit::tools
