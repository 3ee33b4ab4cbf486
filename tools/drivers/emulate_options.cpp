#include "emulate_options.hpp"

#include <charconv>
#include <cmath>
#include <stdexcept>

#include "emulators/catalog/emulator_catalog.hpp"

namespace playerkit::player_drivers {

namespace {

emulators::Endpoint endpoint_of(const EndpointArgument& argument) {
  if (argument.kind == EndpointArgument::Kind::link) {
    if (argument.text.empty()) throw UsageError("--link needs a path, e.g. /tmp/robot");
    return emulators::PtyEndpoint{std::filesystem::path(argument.text)};
  }
  int port = -1;
  const auto [end, error] = std::from_chars(argument.text.data(), argument.text.data() + argument.text.size(), port);
  if (error != std::errc{} || end != argument.text.data() + argument.text.size() || port < 0 || port > 65535) {
    throw UsageError("--tcp '" + argument.text + "': a port number is 0 (any free port) to 65535");
  }
  return emulators::TcpEndpoint{"127.0.0.1", static_cast<std::uint16_t>(port)};
}

}  // namespace

EmulateOptions make_emulate_options(const EmulateCommandLine& command_line, const emulators::EmulatorCatalog& catalog) {
  EmulateOptions options;
  for (const std::string& word : command_line.words) {
    const std::size_t equals = word.find('=');
    if (equals == std::string::npos) {
      if (!catalog.find(word)) {
        throw UsageError("no emulator '" + word + "'; there are " + catalog.names());
      }
      options.requests.push_back({word, {}, emulators::PtyEndpoint{}});
      continue;
    }
    if (options.requests.empty()) {
      throw UsageError("'" + word + "': name the emulator first, then its KEY=VALUE options (NAME KEY=VALUE ...)");
    }
    if (equals == 0) throw UsageError("'" + word + "': an option needs a name before '='");
    options.requests.back().options.emplace_back(word.substr(0, equals), word.substr(equals + 1));
  }
  if (options.requests.empty()) {
    throw UsageError("emulate: name an emulator: " + catalog.names());
  }
  if (command_line.endpoints.size() > options.requests.size()) {
    throw UsageError("emulate: " + std::to_string(command_line.endpoints.size()) + " --link/--tcp for " +
                     std::to_string(options.requests.size()) + " emulator(s): give one per emulator, in order");
  }
  for (std::size_t i = 0; i < command_line.endpoints.size(); ++i) {
    options.requests[i].endpoint = endpoint_of(command_line.endpoints[i]);
  }

  if (!command_line.map.empty()) options.map = command_line.map;
  if (command_line.map_scale) {
    if (!options.map) throw UsageError("--map-scale is the scale of --map's image: it needs --map");
    if (!std::isfinite(*command_line.map_scale) || *command_line.map_scale <= 0.0) {
      throw UsageError("--map-scale must be a positive number of metres per pixel");
    }
    options.map_scale = command_line.map_scale;
  }
  if (command_line.map_negate && !options.map) throw UsageError("--map-negate applies to --map's image: it needs --map");
  options.map_negate = command_line.map_negate;

  for (const std::string& fault : command_line.faults) {
    try {
      emulators::add_fault(options.faults, fault);
    } catch (const std::invalid_argument& e) {
      throw UsageError(e.what());
    }
  }
  if (command_line.duration && (!std::isfinite(*command_line.duration) || *command_line.duration <= 0.0)) {
    throw UsageError("--duration must be a positive number of seconds");
  }
  options.duration = command_line.duration;
  options.stats = command_line.stats;
  return options;
}

}  // namespace playerkit::player_drivers
