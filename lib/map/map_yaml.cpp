#include "map/map_yaml.hpp"

#include "map/flat_yaml.hpp"
#include "map/map_file_error.hpp"
#include "text/printable.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <system_error>

namespace playerkit::map {
namespace {

class FieldReader {
 public:
  FieldReader(const FlatYaml& entries, const std::filesystem::path& file)
      : entries_(entries), file_(file) {}

  [[noreturn]] void fail(int line, int column, const std::string& message) const {
    throw MapFileError(file_, line, column, message);
  }

  const YamlValue* find(std::string_view key) const {
    const auto found = entries_.find(key);
    return found == entries_.end() ? nullptr : &found->second;
  }

  // A missing key has no place in the file; the document start stands in.
  const YamlValue& require(std::string_view key) const {
    const YamlValue* value = find(key);
    if (value == nullptr) fail(1, 1, std::string("missing required key '") + std::string(key) + "'");
    return *value;
  }

  const YamlScalar& scalar(std::string_view key, const YamlValue& value) const {
    if (value.is_list) fail(value.line, value.column, std::string(key) + " must be a single value, not a list");
    if (value.scalar.text.empty()) fail(value.line, value.column, std::string(key) + " has no value");
    return value.scalar;
  }

  double number(std::string_view key, const YamlScalar& scalar) const {
    std::string_view text = scalar.text;
    if (!text.empty() && text.front() == '+') text.remove_prefix(1);
    double result = 0.0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), result);
    if (error != std::errc{} || end != text.data() + text.size() || !std::isfinite(result)) {
      fail(scalar.line, scalar.column,
           std::string(key) + " must be a number, got '" + text::excerpt(scalar.text) + "'");
    }
    return result;
  }

  double number(std::string_view key) const { return number(key, scalar(key, require(key))); }

 private:
  const FlatYaml& entries_;
  const std::filesystem::path& file_;
};

std::string format_number(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  std::string text(buffer, result.ptr);
  // Keep numbers looking like reals, as map_saver writes them.
  if (text.find_first_of(".eE") == std::string::npos && text.find_first_of("ni") == std::string::npos) {
    text += ".0";
  }
  return text;
}

bool needs_quotes(const std::string& text) {
  if (text.empty()) return true;
  for (const char c : text) {
    const bool safe = std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' ||
                      c == '.' || c == '/' || c == '+';
    if (!safe) return true;
  }
  return text.front() == '-';
}

std::string quote(const std::string& text) {
  std::string quoted = "\"";
  for (const char c : text) {
    // A raw line break would end the line, and the quoted value with it, for
    // the reader (parse_flat_yaml reads one key per line).
    if (c == '\n') {
      quoted += "\\n";
      continue;
    }
    if (c == '"' || c == '\\') quoted += '\\';
    quoted += c;
  }
  return quoted + "\"";
}

}  // namespace

MapYaml parse_map_yaml(std::string_view text, const std::filesystem::path& yaml_file) {
  const FlatYaml entries = parse_flat_yaml(text, yaml_file);
  const FieldReader fields(entries, yaml_file);
  MapYaml description;

  const YamlScalar& image = fields.scalar("image", fields.require("image"));
  const std::filesystem::path image_path(image.text);
  description.image = image_path.is_absolute() ? image_path : yaml_file.parent_path() / image_path;
  description.image_line = image.line;
  description.image_column = image.column;

  const YamlValue& resolution = fields.require("resolution");
  description.resolution = fields.number("resolution");
  if (!(description.resolution > 0.0)) {
    fields.fail(resolution.line, resolution.column, "resolution must be positive");
  }

  const YamlValue& origin = fields.require("origin");
  if (!origin.is_list || origin.items.size() != 3) {
    fields.fail(origin.line, origin.column, "origin must be a list of three numbers [x, y, yaw]");
  }
  description.origin = {fields.number("origin x", origin.items[0]),
                        fields.number("origin y", origin.items[1])};
  const double yaw = fields.number("origin yaw", origin.items[2]);
  if (yaw != 0.0) {
    fields.fail(origin.items[2].line, origin.items[2].column,
                "origin yaw " + origin.items[2].text +
                    " is not supported: rotated maps cannot be represented (rotate the image instead)");
  }

  const YamlScalar& negate = fields.scalar("negate", fields.require("negate"));
  if (negate.text == "0" || negate.text == "false") {
    description.negate = false;
  } else if (negate.text == "1" || negate.text == "true") {
    description.negate = true;
  } else {
    fields.fail(negate.line, negate.column, "negate must be 0 or 1, got '" + text::excerpt(negate.text) + "'");
  }

  description.occupied_threshold = fields.number("occupied_thresh");
  description.free_threshold = fields.number("free_thresh");
  for (const char* key : {"occupied_thresh", "free_thresh"}) {
    const double value = fields.number(key);
    if (value < 0.0 || value > 1.0) {
      const YamlValue& where = fields.require(key);
      fields.fail(where.line, where.column, std::string(key) + " must lie in [0, 1]");
    }
  }
  if (description.free_threshold > description.occupied_threshold) {
    const YamlValue& where = fields.require("free_thresh");
    fields.fail(where.line, where.column, "free_thresh is above occupied_thresh");
  }

  if (const YamlValue* mode = fields.find("mode")) {
    const YamlScalar& name = fields.scalar("mode", *mode);
    if (name.text == "scale" || name.text == "raw") {
      fields.fail(name.line, name.column,
                  "mode '" + text::excerpt(name.text) + "' is not supported: only trinary maps can be loaded");
    }
    if (name.text != "trinary") {
      fields.fail(name.line, name.column, "unknown mode '" + text::excerpt(name.text) + "'");
    }
  }
  return description;
}

std::string format_map_yaml(const MapYaml& description) {
  const std::string image = description.image.string();
  // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "literal" + temporary string.
  std::string text = "image: ";
  text += needs_quotes(image) ? quote(image) : image;
  text += "\nresolution: ";
  text += format_number(description.resolution);
  text += "\norigin: [";
  text += format_number(description.origin.x());
  text += ", ";
  text += format_number(description.origin.y());
  text += ", 0.0]\nnegate: ";
  text += description.negate ? "1" : "0";
  text += "\noccupied_thresh: ";
  text += format_number(description.occupied_threshold);
  text += "\nfree_thresh: ";
  text += format_number(description.free_threshold);
  text += "\n";
  return text;
}

}  // namespace playerkit::map
