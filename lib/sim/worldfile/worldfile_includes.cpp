#include "sim/worldfile/worldfile_includes.hpp"

#include <system_error>

#include "config/includes.hpp"
#include "sim/worldfile/worldfile_error.hpp"
#include "sim/worldfile/worldfile_limits.hpp"
#include "text/printable.hpp"

namespace playerkit::sim::worldfile {
namespace {

namespace fs = std::filesystem;

// Two spellings of one file must be recognised as one to find cycles.
fs::path world_file_identity(const fs::path& path) {
  std::error_code error;
  fs::path canonical = fs::weakly_canonical(path, error);
  if (!error) return canonical;
  return path.lexically_normal();
}

std::string too_large_message() {
  return "too large: a world file with its includes may have " + std::to_string(kMaxWorldFileBytes) +
         " bytes at most";
}

// The contents of a regular file within the bytes left; what() of the
// exception is the reason alone.
std::string read_world_text(const fs::path& path, std::size_t bytes_left) {
  try {
    return config::read_config_text(path, bytes_left);
  } catch (const config::UnreadableConfigFile& error) {
    std::error_code ignored;
    const auto size = fs::file_size(path, ignored);
    if (!ignored && size > bytes_left) throw config::UnreadableConfigFile(too_large_message());
    throw;
  }
}

class WorldIncludeReader {
 public:
  explicit WorldIncludeReader(fs::path directory) : directory_(std::move(directory)) {}

  TokenizedWorld read(std::string_view text, const std::string& name) {
    if (text.size() > kMaxWorldFileBytes) throw WorldFileError(SourceLocation{name}, too_large_message());
    bytes_read_ = text.size();
    TokenizedWorld world;
    files_ = &world.files;
    world.files.push_back(name);
    open_.push_back(world_file_identity(name));
    const SourceLocation end = tokenize(text, name, world.tokens, handler_);
    world.tokens.push_back(Token{TokenKind::EndOfFile, "", end});
    return world;
  }

 private:
  void include(const Token& name, std::vector<Token>& out) {
    const std::string shown = "include file \"" + text::excerpt(name.text) + "\"";
    if (name.text.empty()) throw WorldFileError(name.where, "include names no file");
    const fs::path path = name.text.front() == '/' ? fs::path(name.text) : directory_ / name.text;
    const fs::path identity = world_file_identity(path);
    for (const fs::path& open : open_) {
      if (open == identity) {
        std::string chain;
        for (const fs::path& link : open_) chain += link.filename().string() + " -> ";
        throw WorldFileError(name.where, "include cycle: " + chain + identity.filename().string());
      }
    }
    if (open_.size() > static_cast<std::size_t>(kMaxWorldIncludeDepth)) {
      throw WorldFileError(name.where, shown + ": includes nested more than " +
                                           std::to_string(kMaxWorldIncludeDepth) + " deep");
    }
    if (++included_ > kMaxWorldIncludedFiles) {
      throw WorldFileError(name.where, shown + ": more than " + std::to_string(kMaxWorldIncludedFiles) +
                                           " includes in one world");
    }
    std::string text;
    try {
      text = read_world_text(path, kMaxWorldFileBytes - bytes_read_);
    } catch (const config::UnreadableConfigFile& error) {
      throw WorldFileError(name.where, "cannot read " + shown + ": " + error.what() + " (looked for " +
                                           text::excerpt(path.string(), 200) + ")");
    }
    bytes_read_ += text.size();
    files_->push_back(path.string());
    open_.push_back(identity);
    tokenize(text, path.string(), out, handler_);
    open_.pop_back();
  }

  fs::path directory_;
  std::vector<fs::path> open_;  // the include chain being read, outermost first
  std::vector<std::string>* files_ = nullptr;
  std::size_t bytes_read_ = 0;
  int included_ = 0;
  IncludeHandler handler_ = [this](const Token& name, std::vector<Token>& out) { include(name, out); };
};

}  // namespace

TokenizedWorld tokenize_world_text(std::string_view text, const std::string& name,
                                   const std::filesystem::path& directory) {
  return WorldIncludeReader(directory).read(text, name);
}

TokenizedWorld tokenize_world_file(const std::filesystem::path& file) {
  std::string text;
  try {
    text = read_world_text(file, kMaxWorldFileBytes);
  } catch (const config::UnreadableConfigFile& error) {
    throw WorldFileError(SourceLocation{file.string()}, std::string("cannot read the world file: ") + error.what());
  }
  const fs::path directory = file.has_parent_path() ? file.parent_path() : fs::path(".");
  return tokenize_world_text(text, file.string(), directory);
}

}  // namespace playerkit::sim::worldfile
