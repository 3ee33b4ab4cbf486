#pragma once
// Internal: a strict reader for the flat subset of YAML that map files use
// (ROS map_server's map.yaml): one `key: value` per line, where a value is a
// plain or quoted scalar or a flow list of them ([a, b, c]); `#` comments and
// a leading `---`. Anything else (nesting, block lists, multi-line values)
// is an error with its line and column rather than a silent misreading.

#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace playerkit::map {

struct YamlScalar {
  std::string text;   // quotes removed, escapes resolved
  bool quoted = false;
  int line = 0;       // 1-based position of the scalar's first character
  int column = 0;
};

struct YamlValue {
  bool is_list = false;
  YamlScalar scalar;               // when !is_list (text empty for `key:` alone)
  std::vector<YamlScalar> items;   // when is_list
  int line = 0;                    // position of the value (or of the key when empty)
  int column = 0;
};

using FlatYaml = std::map<std::string, YamlValue, std::less<>>;

// Throws MapFileError ("file:line:col: ...") on anything outside the subset
// and on a repeated key. `file` only names the source in messages.
FlatYaml parse_flat_yaml(std::string_view text, const std::filesystem::path& file);

}  // namespace playerkit::map
