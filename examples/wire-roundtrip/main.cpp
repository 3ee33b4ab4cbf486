// JSON lines -> Player wire bytes -> JSON lines, checking the round trip.
// See README.md beside this file.

#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "protocol/device_address.hpp"
#include "protocol/errors.hpp"
#include "protocol/message.hpp"
#include "protocol/message_json.hpp"

namespace {

using namespace playerkit::protocol;

void print_hex(std::ostream& out, std::string_view label, std::span<const std::uint8_t> bytes) {
  out << "  " << label << " (" << bytes.size() << " bytes):";
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    if (i % 16 == 0) out << "\n   ";
    char buf[4];
    std::snprintf(buf, sizeof buf, " %02x", bytes[i]);
    out << buf;
  }
  out << "\n";
}

// 0 when the message survived the round trip, 1 when it did not.
int round_trip(const nlohmann::json& in, bool show_hex) {
  const Message message = message_from_json(in);
  const std::vector<std::uint8_t> wire = encode_message(message);
  const auto parsed = parse_message(wire);
  if (!parsed || parsed->consumed != wire.size()) {
    std::cerr << "wire-roundtrip: encoded bytes do not parse back as one message\n";
    return 1;
  }
  const nlohmann::json out = message_to_json(parsed->message);
  std::cout << out.dump() << "\n";
  std::cerr << to_string(message.device()) << " " << to_string(message.type()) << ": "
            << wire.size() << " bytes on the wire (32 header + " << message.payload.size()
            << " payload)\n";
  if (show_hex) {
    print_hex(std::cerr, "header", std::span(wire).first(kHeaderSize));
    print_hex(std::cerr, "payload", std::span(wire).subspan(kHeaderSize));
  }
  if (parsed->message != message || message_from_json(out) != message) {
    std::cerr << "wire-roundtrip: MISMATCH after the round trip\n";
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Encode Player messages given as JSON lines to wire bytes and decode them back."};
  std::string input = "-";
  bool show_hex = false;
  app.add_option("FILE", input, "JSON lines to read, - for stdin")->capture_default_str();
  app.add_flag("--hex", show_hex, "dump the header and payload bytes on stderr");
  app.footer("Example:\n  wire-roundtrip --hex data/messages/intel-lab-first-scan.json");
  CLI11_PARSE(app, argc, argv);

  std::ifstream file;
  if (input != "-") {
    file.open(input);
    if (!file) {
      std::cerr << "wire-roundtrip: cannot open " << input << "\n";
      return 2;
    }
  }
  std::istream& in = input == "-" ? std::cin : file;

  int status = 0;
  std::string line;
  for (int line_number = 1; std::getline(in, line); ++line_number) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    try {
      status |= round_trip(nlohmann::json::parse(line), show_hex);
    } catch (const std::exception& e) {
      std::cerr << input << ":" << line_number << ": " << e.what() << "\n";
      return 2;
    }
  }
  return status;
}
