#pragma once
// Reading config files from disk and splicing `include "file"` statements into
// the token stream, as 1.5 did: the included tokens are parsed as if they had
// been written in place of the statement, so an included file may hold
// defines, devices or just properties.

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "config/limits.hpp"
#include "config/token.hpp"

namespace playerkit::config {

// The tokens of `text` (the contents of `file`) with every include statement
// replaced by the tokens of the named file, recursively. A relative name is
// resolved against the directory of the file holding the statement; a name
// starting with '/' or '~' is used as is. The statement must be alone on its
// line: `include "name"`. Throws ConfigError, pointing at the file name, when
// the file cannot be read or is already being read (an include cycle), and
// past the limits of limits.hpp (total size, include depth and count).
std::vector<Token> tokenize_with_includes(std::string_view text, const std::string& file);

// Why a file cannot be read as configuration text; what() is the reason
// alone ("it is a directory, not a file"), for the caller to place.
class UnreadableConfigFile : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The whole contents of a regular file of at most max_bytes. Devices
// (/dev/zero), pipes and directories are refused without reading them, so
// that neither memory nor time depends on what the name points at. Throws
// UnreadableConfigFile.
std::string read_config_text(const std::filesystem::path& path, std::size_t max_bytes = kMaxConfigBytes);

// read_config_text, or nullopt if it cannot be read.
std::optional<std::string> read_text_file(const std::filesystem::path& path);

}  // namespace playerkit::config
