#include "probe_output.hpp"

#include <nlohmann/json.hpp>

namespace playerkit::player_drivers {

void write_probe_result(const families::ProbeResult& result, bool json, std::ostream& out) {
  const std::string note = result.found ? result.found->note : std::string();
  if (json) {
    nlohmann::json line = {{"port", result.port}, {"found", result.found.has_value()}};
    if (result.found) {
      line["driver"] = result.found->driver;
      line["model"] = result.found->model;
      line["baud"] = result.baud;
      line["config"] = result.config_line;
      if (!note.empty()) line["note"] = note;
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
  if (!note.empty()) out << "    (" << note << ")\n";
  out << std::flush;
}

}  // namespace playerkit::player_drivers
