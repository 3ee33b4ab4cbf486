#pragma once
// Stage world files as a tree of entities (stage-worlds.md §1): the lexer,
// includes, the grammar and macro expansion, with every entity, property
// and value keeping its file:line:col. What the entities mean is the
// loader's business (world_loader.hpp).
//
//   const auto tree = worldfile::read_world_tree("worlds/simple.world");
//   for (const auto& robot : tree.world.children) ...   // robot.type == "position"

#include <filesystem>
#include <string>
#include <string_view>

#include "sim/worldfile/worldfile_error.hpp"
#include "sim/worldfile/worldfile_tree.hpp"

namespace playerkit::sim::worldfile {

// Reads `file` and its includes (relative names from the directory of
// `file`, §1.4). Throws WorldFileError.
WorldTree read_world_tree(const std::filesystem::path& file);

// The same for text in memory named `name` (the file name messages show);
// includes are resolved against `directory`.
WorldTree parse_world_text(std::string_view text, const std::string& name,
                           const std::filesystem::path& directory = ".");

}  // namespace playerkit::sim::worldfile
