#include "port_probe.hpp"

#include <nlohmann/json.hpp>

#include "links/link_address.hpp"
#include "links/link_error.hpp"
#include "links/open_link.hpp"
#include "links/port_diagnosis.hpp"

namespace playerkit::player_drivers {

namespace {

using Clock = links::LinkClock;

std::string protocol_label(ProbeProtocol protocol) {
  switch (protocol) {
    case ProbeProtocol::p2os: return "P2OS";
    case ProbeProtocol::sick_lms: return "SICK (LMS password)";
    case ProbeProtocol::sick_pls: return "SICK (PLS password)";
  }
  return "?";
}

std::string attempt_label(const ProbeAttempt& attempt) {
  std::string text = protocol_label(attempt.protocol);
  if (attempt.baud == 0) return text;
  return text + " at " + std::to_string(attempt.baud) + " " + (attempt.parity == links::Parity::even ? "8E1" : "8N1");
}

std::string config_line_for(const Identification& found, const std::string& port) {
  if (found.driver == "p2os") return "position:0 ( driver \"p2os_position\" port \"" + port + "\" )";
  return "laser:0 ( driver \"" + found.driver + "\" port \"" + port + "\" )";
}

std::string note_for(const Identification& found, int baud) {
  if (found.driver == "p2os") {
    return "add the other p2os_* devices with the same port, or run them all: player-drivers run p2os port=...";
  }
  if (baud == 19200 || baud == 500000) {
    return "the laser runs at " + std::to_string(baud) +
           " baud; drivers look for it at 38400 and 9600 first: power-cycle it (it starts at 9600)";
  }
  return "";
}

// "P2OS at 9600, 38400, ...; SICK at 9600, ..." for the nothing-answered message.
std::string tried_text(const std::vector<ProbeAttempt>& attempts) {
  std::string p2os, sick;
  for (const auto& attempt : attempts) {
    std::string& list = attempt.protocol == ProbeProtocol::p2os ? p2os : sick;
    const std::string baud = attempt.baud == 0 ? std::string("once") : std::to_string(attempt.baud);
    if (list.find(baud) == std::string::npos) list += (list.empty() ? "" : ", ") + baud;
  }
  const bool serial = !attempts.empty() && attempts.front().baud != 0;
  const std::string unit = serial ? " baud" : "";
  return "SICK LMS 200 / PLS at " + sick + unit + " and P2OS at " + p2os + unit;
}

}  // namespace

std::vector<ProbeAttempt> probe_attempts(bool serial) {
  using links::Parity;
  if (!serial) return {{ProbeProtocol::sick_lms, 0, Parity::none}, {ProbeProtocol::p2os, 0, Parity::none}};
  std::vector<ProbeAttempt> attempts;
  // Both lasers power up at 9600; 38400 is where the drivers leave them; a
  // Pioneer's controller is set to one of five rates.
  for (const int baud : {9600, 38400, 19200}) {
    attempts.push_back({ProbeProtocol::sick_lms, baud, Parity::none});
    attempts.push_back({ProbeProtocol::p2os, baud, Parity::none});
    attempts.push_back({ProbeProtocol::sick_pls, baud, Parity::even});
  }
  attempts.push_back({ProbeProtocol::p2os, 115200, Parity::none});
  attempts.push_back({ProbeProtocol::p2os, 57600, Parity::none});
  attempts.push_back({ProbeProtocol::sick_lms, 500000, Parity::none});
  attempts.push_back({ProbeProtocol::sick_pls, 500000, Parity::even});
  return attempts;
}

ProbeResult probe_port(const std::string& port, const ProbeSettings& settings, const std::function<bool()>& stop) {
  ProbeResult result;
  result.port = port;
  links::LinkAddress address;
  try {
    address = links::parse_link_address(port);
  } catch (const links::LinkError& e) {
    result.problem = e.what();
    result.port_unusable = true;
    return result;
  }
  if (!address.is_tcp()) {
    const links::PortDiagnosis diagnosis = links::describe_open_problem(port);
    if (diagnosis.problem) {
      result.problem = diagnosis.summary;
      result.port_unusable = true;
      return result;
    }
  }

  const auto budget_end = Clock::now() + settings.budget;
  const auto attempts = probe_attempts(!address.is_tcp());
  std::unique_ptr<links::ByteLink> link;
  links::SerialSettings line;
  try {
    for (const ProbeAttempt& attempt : attempts) {
      if (stop()) {
        result.interrupted = true;
        result.problem = "interrupted";
        return result;
      }
      if (Clock::now() >= budget_end) break;
      links::SerialSettings wanted{.baud = attempt.baud == 0 ? 9600 : attempt.baud, .parity = attempt.parity};
      if (!link || (!address.is_tcp() && (wanted.parity != line.parity))) {
        link.reset();  // release the port before opening it again with another framing
        link = links::open_link(address, wanted, std::chrono::seconds(2));
        line = wanted;
      } else if (!address.is_tcp() && wanted.baud != line.baud) {
        link->set_baud(wanted.baud);
        line.baud = wanted.baud;
      }
      const auto now = Clock::now();
      const ProbeDeadlines deadlines{std::min(budget_end, now + settings.first_reply),
                                     std::min(budget_end, now + settings.first_reply + settings.follow_up)};
      std::optional<Identification> found;
      switch (attempt.protocol) {
        case ProbeProtocol::p2os:
          found = probe_p2os(*link, deadlines);
          break;
        case ProbeProtocol::sick_lms:
          found = probe_sick(*link, hardware::sick::Model::lms200, deadlines);
          break;
        case ProbeProtocol::sick_pls:
          found = probe_sick(*link, hardware::sick::Model::pls, deadlines);
          break;
      }
      if (settings.progress) {
        settings.progress(port + ": " + attempt_label(attempt) + ": " + (found ? found->driver : "no answer"));
      }
      if (found) {
        result.found = found;
        result.baud = attempt.baud;
        result.config_line = config_line_for(*found, port);
        result.note = note_for(*found, attempt.baud);
        return result;
      }
    }
  } catch (const links::LinkError& e) {
    result.problem = e.what();
    result.port_unusable = e.kind() != links::LinkErrorKind::timed_out && e.kind() != links::LinkErrorKind::disconnected;
    return result;
  }
  result.problem = "no supported device answered on " + port + " (tried " + tried_text(attempts) +
                   "); is it powered, cabled to this port, and not in use by a program that ignores locks?";
  return result;
}

void write_probe_result(const ProbeResult& result, bool json, std::ostream& out) {
  if (json) {
    nlohmann::json line = {{"port", result.port}, {"found", result.found.has_value()}};
    if (result.found) {
      line["driver"] = result.found->driver;
      line["model"] = result.found->model;
      line["baud"] = result.baud;
      line["config"] = result.config_line;
      if (!result.note.empty()) line["note"] = result.note;
    } else {
      line["problem"] = result.problem;
      line["port_unusable"] = result.port_unusable;
    }
    out << line.dump() << "\n" << std::flush;
    return;
  }
  if (!result.found) {
    out << result.port << ": " << result.problem << "\n" << std::flush;
    return;
  }
  out << result.port << ": " << result.found->driver;
  if (result.baud != 0) out << " at " << result.baud << " baud";
  out << ", " << result.found->model << "\n    " << result.config_line << "\n";
  if (!result.note.empty()) out << "    (" << result.note << ")\n";
  out << std::flush;
}

}  // namespace playerkit::player_drivers
