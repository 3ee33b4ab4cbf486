#pragma once
// How every playerkit tool ends on a signal: SIGINT and SIGTERM set a flag
// that the tool's loop polls (so output is flushed and files closed, exit
// 0), and SIGPIPE is ignored, so a reader of stdout that goes away (`| head`)
// shows up as a failed write the tool ends on quietly.
//
//   tools::install_stop_signals();
//   run(options, [] { return tools::stop_requested(); });

namespace playerkit::tools {

// Once, early in main().
void install_stop_signals();
// True once SIGINT or SIGTERM arrived.
[[nodiscard]] bool stop_requested();
// The signal that arrived, 0 before.
[[nodiscard]] int stop_signal_number();
// Only ignore SIGPIPE (tools that run to completion and have no loop to stop).
void ignore_broken_pipes();

}  // namespace playerkit::tools
