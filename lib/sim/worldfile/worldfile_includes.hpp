#pragma once
// Reading a world file from disk with its includes spliced in (§1.4).

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "sim/worldfile/worldfile_lexer.hpp"

namespace playerkit::sim::worldfile {

struct TokenizedWorld {
  std::vector<Token> tokens;       // ends with EndOfFile at the end of the main file
  std::vector<std::string> files;  // the main file, then each include as read
};

// The tokens of the world file `file` and of every file it includes. An
// include's relative name is resolved against the directory of the
// top-level world file, even from a nested include, as Stage does; a name
// starting with '/' is used as is ('~' is not expanded, and $STAGEPATH is
// not searched). Throws WorldFileError: an unreadable file (regular files
// only), an include cycle, the limits of worldfile_limits.hpp.
TokenizedWorld tokenize_world_file(const std::filesystem::path& file);

// The same for text in memory named `name`; includes are resolved against
// `directory`.
TokenizedWorld tokenize_world_text(std::string_view text, const std::string& name,
                                   const std::filesystem::path& directory);

}  // namespace playerkit::sim::worldfile
