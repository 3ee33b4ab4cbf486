#include "sim/worldfile/world_loader.hpp"

#include <algorithm>

#include "config/closest_name.hpp"
#include "sim/worldfile/world_loader_context.hpp"
#include "sim/worldfile/world_loader_devices.hpp"
#include "sim/worldfile/world_loader_dialect.hpp"
#include "sim/worldfile/worldfile_colors.hpp"
#include "sim/worldfile/worldfile_syntax.hpp"
#include "text/printable.hpp"

namespace playerkit::sim::worldfile {
namespace {

WorldDescription describe_tree(const WorldTree& tree, const std::filesystem::path& directory,
                               const WorldLoadOptions& options) {
  WorldDescription description;
  description.warnings = tree.warnings;
  LoadContext context{.tree = tree,
                      .units = read_units(tree, description.warnings),
                      .directory = directory,
                      .options = options,
                      .warnings = description.warnings,
                      .dialect = detect_dialect(tree),
                      .settings = {},
                      .models = {},
                      .devices = {},
                      .map = {},
                      .names = {},
                      .siblings = {}};
  context.settings.seed = options.seed;
  context.map.where = tree.world.where;
  if (context.dialect == Dialect::stage13) {
    read_stage13_world(context);
  } else {
    read_stage4_world(context);
  }
  description.dialect = context.dialect;
  description.settings = context.settings;
  description.map = build_map(context.map, description.warnings);
  description.devices = assign_device_indices(context);
  description.models = std::move(context.models);
  return description;
}

// splitmix64: a colour for `color "random"` that depends on the seed only.
std::uint64_t mix_bits(std::uint64_t value) {
  value += 0x9E3779B97F4A7C15ULL;
  value = (value ^ (value >> 30)) * 0xBF58476D1CE4E5B9ULL;
  value = (value ^ (value >> 27)) * 0x94D049BB133111EBULL;
  return value ^ (value >> 31);
}

}  // namespace

std::string_view dialect_name(Dialect dialect) {
  switch (dialect) {
    case Dialect::stage13: return "Stage 1.3";
    case Dialect::stage3: return "Stage 3";
    case Dialect::stage4: return "Stage 4";
  }
  return "Stage";
}

std::string LoadContext::model_name(const std::string& given, const std::string& type, int parent,
                                    const SourceLocation& where) {
  const std::string prefix = parent < 0 ? "" : models.at(static_cast<std::size_t>(parent)).name + ".";
  const int sibling = siblings[{parent, type}]++;
  std::string wanted;
  if (given.empty()) {
    wanted = prefix + type + ":" + std::to_string(sibling);
  } else if (given.front() == '/') {
    wanted = given.substr(1);
  } else {
    wanted = prefix + given;
  }
  if (names.insert(wanted).second) return wanted;
  for (int copy = 2;; ++copy) {
    std::string renamed = wanted + "#" + std::to_string(copy);
    if (names.insert(renamed).second) {
      warnings.push_back(located(where, "the name \"" + text::excerpt(wanted) + "\" is taken; this model is named \"" +
                                            text::excerpt(renamed) + "\""));
      return renamed;
    }
  }
}

void LoadContext::unknown_type(const Entity& entity, std::span<const std::string_view> known_types) const {
  for (const MacroDefinition& macro : tree.macros) {
    if (macro.name == entity.type) {
      throw WorldFileError(entity.where, "macro \"" + text::excerpt(entity.type) +
                                             "\" is used before its definition at " + to_string(macro.where) +
                                             " (a macro must be defined before it is used)");
    }
  }
  std::vector<std::string_view> candidates(known_types.begin(), known_types.end());
  for (const MacroDefinition& macro : tree.macros) candidates.push_back(macro.name);
  std::string message = "unknown macro or model type \"" + text::excerpt(entity.type) + "\"";
  if (const auto suggestion = config::closest_name(entity.type, candidates)) {
    message += " (did you mean \"" + *suggestion + "\"?)";
  }
  if (entity.type != entity.written_type()) {
    message += " (the base of macro \"" + text::excerpt(entity.written_type()) + "\")";
  }
  throw WorldFileError(entity.where, message + " in a " + std::string(dialect_name(dialect)) + " world");
}

Rgb color_named(const Value& name, LoadContext& context) {
  if (const auto rgb = x11_color(name.text)) return *rgb;
  if (name.text == "random" && context.dialect != Dialect::stage13) {
    const std::uint64_t bits = mix_bits(context.options.seed ^ mix_bits(context.models.size()));
    return Rgb{static_cast<std::uint8_t>(bits), static_cast<std::uint8_t>(bits >> 8),
               static_cast<std::uint8_t>(bits >> 16)};
  }
  context.warnings.push_back(
      located(name.where, "unknown colour \"" + text::excerpt(name.text) + "\": red is used, as in Stage"));
  return Rgb{255, 0, 0};
}

WorldDescription describe_world(const std::filesystem::path& file, const WorldLoadOptions& options) {
  const WorldTree tree = read_world_tree(file);
  return describe_tree(tree, file.has_parent_path() ? file.parent_path() : std::filesystem::path("."), options);
}

WorldDescription describe_world_text(std::string_view text, const std::string& name,
                                     const std::filesystem::path& directory, const WorldLoadOptions& options) {
  const WorldTree tree = parse_world_text(text, name, directory);
  return describe_tree(tree, directory, options);
}

}  // namespace playerkit::sim::worldfile
