#include "families/port_probe.hpp"

#include <algorithm>

#include "links/link_address.hpp"
#include "links/link_error.hpp"
#include "links/open_link.hpp"
#include "links/port_diagnosis.hpp"

namespace playerkit::families {

namespace {

using Clock = links::LinkClock;

std::string attempt_label(const ProbeAttempt& attempt) {
  std::string text = attempt.method->label;
  if (attempt.baud == 0) return text;
  return text + " at " + std::to_string(attempt.baud) + " " + links::framing_name(attempt.method->line);
}

std::string config_line_for(const Identification& found, const std::string& port) {
  return found.interface_name + ":0 ( driver \"" + found.config_driver + "\" port \"" + port + "\" )";
}

// "P2OS at 9600, 38400; SICK (LMS password) at 9600" for the nothing-answered message.
std::string tried_text(const std::vector<ProbeAttempt>& attempts) {
  std::vector<std::pair<std::string, std::string>> tried;  // label, rates
  for (const auto& attempt : attempts) {
    auto entry = std::find_if(tried.begin(), tried.end(),
                              [&](const auto& item) { return item.first == attempt.method->label; });
    if (entry == tried.end()) entry = tried.insert(tried.end(), {attempt.method->label, ""});
    const std::string baud = attempt.baud == 0 ? std::string("once") : std::to_string(attempt.baud);
    entry->second += (entry->second.empty() ? "" : ", ") + baud;
  }
  const bool serial = !attempts.empty() && attempts.front().baud != 0;
  std::string text;
  for (const auto& [label, rates] : tried) {
    text += (text.empty() ? "" : "; ") + label + " at " + rates + (serial ? " baud" : "");
  }
  return text.empty() ? "no probes: no family that can be probed is built" : text;
}

}  // namespace

std::vector<ProbeAttempt> probe_attempts(const FamilyRegistry& families, bool serial) {
  std::vector<ProbeAttempt> attempts;
  if (!serial) {
    for (const auto& family : families.all()) {
      for (const auto& method : family.probes) attempts.push_back({&method, family.name, 0});
    }
    return attempts;
  }
  std::size_t ranks = 0;
  for (const auto& family : families.all()) {
    for (const auto& method : family.probes) ranks = std::max(ranks, method.bauds.size());
  }
  for (std::size_t rank = 0; rank < ranks; ++rank) {
    for (const auto& family : families.all()) {
      for (const auto& method : family.probes) {
        if (rank < method.bauds.size()) attempts.push_back({&method, family.name, method.bauds[rank]});
      }
    }
  }
  return attempts;
}

ProbeResult probe_port(const std::string& port, const FamilyRegistry& families, const ProbeSettings& settings,
                       const std::function<bool()>& stop) {
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
  const auto attempts = probe_attempts(families, !address.is_tcp());
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
      links::SerialSettings wanted = attempt.method->line;
      wanted.baud = attempt.baud == 0 ? 9600 : attempt.baud;
      const bool same_framing = link && wanted.data_bits == line.data_bits && wanted.parity == line.parity &&
                                wanted.stop_bits == line.stop_bits && wanted.flow_control == line.flow_control;
      if (!link || (!address.is_tcp() && !same_framing)) {
        link.reset();  // release the port before opening it again with another framing
        link = links::open_link(address, wanted, std::chrono::seconds(2));
        line = wanted;
      } else if (!address.is_tcp() && wanted.baud != line.baud) {
        link->set_baud(wanted.baud);
        line.baud = wanted.baud;
      }
      const auto now = Clock::now();
      const ProbeContext context{.link = *link,
                                 .baud = attempt.baud,
                                 .first_reply = std::min(budget_end, now + settings.first_reply),
                                 .finish = std::min(budget_end, now + settings.first_reply + settings.follow_up)};
      const std::optional<Identification> found = attempt.method->ask(context);
      if (settings.progress) {
        settings.progress(port + ": " + attempt_label(attempt) + ": " + (found ? found->driver : "no answer"));
      }
      if (found) {
        result.found = found;
        result.baud = attempt.baud;
        result.config_line = config_line_for(*found, port);
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

}  // namespace playerkit::families
