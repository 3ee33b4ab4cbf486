#pragma once
// How a tool reports a command line CLI11 could not parse. Header-only: it
// needs CLI11, which only the tools' main programs link.
//
//   try { app.parse(argc, argv); }
//   catch (const CLI::ParseError& e) { return tools::report_parse_error(app, e, std::cerr); }
//
// Two things differ from CLI11's own app.exit(e):
//  * an unknown argument is named even when a required one is missing too:
//    CLI11 checks requirements before extras, so `player-serve --bogus` said
//    only "CONFIG is required";
//  * arguments quoted back are escaped (text::printable), so a pasted control
//    sequence reaches the terminal as text.

#include <ostream>
#include <string>

#include <CLI/CLI.hpp>

#include "exit_status.hpp"
#include "text/printable.hpp"

namespace playerkit::tools {

// The message lines for a parse error that is not --help or --version.
inline std::string parse_error_message(const CLI::App& app, const CLI::ParseError& error) {
  std::string message;
  const std::vector<std::string> unknown = app.remaining(true);
  const bool extras_reported = dynamic_cast<const CLI::ExtrasError*>(&error) != nullptr;
  if (!unknown.empty() && !extras_reported) {
    message += text::printable(CLI::ExtrasError(unknown).what()) + "\n";
  }
  message += text::printable(error.what()) + "\n";
  message += "Run with --help for more information.\n";
  return message;
}

// Prints the error (CLI11's help and version go to stdout as usual) and
// returns the exit status: kExitOk for --help/--version, kExitUsage otherwise.
inline int report_parse_error(const CLI::App& app, const CLI::ParseError& error, std::ostream& err) {
  if (error.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) {
    return app.exit(error) == 0 ? kExitOk : kExitUsage;
  }
  err << parse_error_message(app, error);
  return kExitUsage;
}

}  // namespace playerkit::tools
