// A .cfg text through config::ConfigFile::parse, as player-serve reads one,
// then every property read back in every typed form a driver may ask for.
// The file is named inside the scratch directory and its '/' are made '_',
// so an include can only name a missing file of that directory.

#include <algorithm>
#include <string>

#include "config/config_file.hpp"
#include "config/errors.hpp"
#include "fuzz_support.hpp"
#include "fuzz_targets.hpp"

namespace playerkit::fuzz {
namespace config_parser_detail {

void read_every_form(const config::Section& section) {
  for (const std::string& name : section.property_names()) {
    (void)section.read_string(name, "");
    (void)section.read_int(name, 0);
    (void)section.read_float(name, 0.0);
    (void)section.read_length(name, 0.0);
    (void)section.read_angle(name, 0.0);
    (void)section.read_filename(name, "");
    // Tuples may hold thousands of values: the first few and one past the end.
    const std::size_t size = section.tuple_size(name);
    for (std::size_t i = 0; i < std::min<std::size_t>(size, 4) + 1; ++i) {
      (void)section.read_tuple_int(name, i, 0);
      (void)section.read_tuple_float(name, i, 0.0);
      (void)section.read_tuple_length(name, i, 0.0);
      (void)section.read_tuple_angle(name, i, 0.0);
    }
  }
}

}  // namespace config_parser_detail

int config_parser(const std::uint8_t* data, std::size_t size) {
  const std::string text = without_slashes(as_text({data, size}));
  const std::string file = (scratch_directory() / "fuzz.cfg").string();
  try {
    const config::ConfigFile parsed = config::ConfigFile::parse(text, file);
    for (const auto& section : parsed.sections()) config_parser_detail::read_every_form(section);
    for (const auto& device : parsed.devices()) {
      if (device.section >= parsed.sections().size()) {
        invariant_failed("config_parser", "a device declared by a section that does not exist");
      }
    }
    for (const auto& warning : parsed.warnings()) (void)warning.to_string();
    for (const auto& warning : parsed.unused_properties()) (void)warning.to_string();
  } catch (const config::ConfigError&) {
  }
  return 0;
}

}  // namespace playerkit::fuzz
