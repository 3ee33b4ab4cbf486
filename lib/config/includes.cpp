#include "config/includes.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <system_error>

#include "config/errors.hpp"
#include "config/lexer.hpp"
#include "text/printable.hpp"

namespace playerkit::config {
namespace {

namespace fs = std::filesystem;

// Two spellings of the same file must be recognised as one to detect cycles.
fs::path identity_of(const fs::path& path) {
  std::error_code error;
  fs::path canonical = fs::weakly_canonical(path, error);
  if (!error) return canonical;
  fs::path absolute = fs::absolute(path, error);
  return error ? path.lexically_normal() : absolute.lexically_normal();
}

fs::path resolve_include(const std::string& name, const std::string& including_file) {
  if (!name.empty() && (name.front() == '/' || name.front() == '~')) return fs::path(name);
  return fs::path(including_file).parent_path() / name;
}

struct OpenFile {
  fs::path identity;
  std::string short_name;  // for the cycle message
};

class IncludeExpander {
 public:
  std::vector<Token> expand(std::string_view text, const std::string& file) {
    if (text.size() > kMaxConfigBytes) {
      throw ConfigError(SourceLocation{file}, "the configuration is larger than " +
                                                  std::to_string(kMaxConfigBytes) + " bytes");
    }
    bytes_read_ = text.size();
    open_files_.push_back(OpenFile{identity_of(file), fs::path(file).filename().string()});
    append_tokens(text, file);
    tokens_.push_back(Token{TokenKind::EndOfFile, "", end_of_main_file_});
    return std::move(tokens_);
  }

 private:
  void append_tokens(std::string_view text, const std::string& file) {
    const std::vector<Token> tokens = tokenize(text, file);
    for (std::size_t i = 0; i < tokens.size(); ++i) {
      const Token& token = tokens[i];
      if (token.kind == TokenKind::EndOfFile) {
        if (open_files_.size() == 1) end_of_main_file_ = token.where;
        break;
      }
      if (token.kind == TokenKind::Word && token.text == "include") {
        const Token& name = tokens[i + 1];
        if (name.kind != TokenKind::String) {
          const std::string expected = "a file name in quotes after 'include'";
          throw ConfigError(name.where,
                            "syntax error: expected " + expected + ", found " + describe(name));
        }
        const Token& after = tokens[i + 2];
        if (after.kind != TokenKind::Newline && after.kind != TokenKind::EndOfFile) {
          throw ConfigError(after.where, "syntax error: expected end of line after include \"" +
                                             text::excerpt(name.text) + "\", found " + describe(after));
        }
        include(name, file);
        ++i;  // skip the name; the line break stays to end the line as usual
        continue;
      }
      tokens_.push_back(token);
    }
  }

  void include(const Token& name, const std::string& including_file) {
    const fs::path path = resolve_include(name.text, including_file);
    const std::string shown = "include file '" + text::excerpt(name.text) + "'";
    OpenFile opened{identity_of(path), path.filename().string()};
    for (const OpenFile& open : open_files_) {
      if (open.identity == opened.identity) {
        std::string chain;
        for (const OpenFile& link : open_files_) chain += link.short_name + " -> ";
        throw ConfigError(name.where, "include cycle: " + chain + opened.short_name);
      }
    }
    if (open_files_.size() > static_cast<std::size_t>(kMaxIncludeDepth)) {
      throw ConfigError(name.where, shown + ": includes nested more than " +
                                        std::to_string(kMaxIncludeDepth) + " deep");
    }
    if (++included_files_ > kMaxIncludedFiles) {
      throw ConfigError(name.where, shown + ": more than " + std::to_string(kMaxIncludedFiles) +
                                        " includes in one configuration");
    }
    std::string text;
    try {
      text = read_config_text(path, kMaxConfigBytes - bytes_read_);
    } catch (const UnreadableConfigFile& error) {
      throw ConfigError(name.where, "cannot read " + shown + ": " + error.what() + " (looked for " +
                                        path.string() + ")");
    }
    bytes_read_ += text.size();
    open_files_.push_back(std::move(opened));
    append_tokens(text, path.string());
    open_files_.pop_back();
  }

  std::vector<Token> tokens_;
  std::vector<OpenFile> open_files_;  // the include chain being read, outermost first
  std::size_t bytes_read_ = 0;         // of every file so far, for kMaxConfigBytes
  int included_files_ = 0;
  SourceLocation end_of_main_file_;
};

}  // namespace

std::vector<Token> tokenize_with_includes(std::string_view text, const std::string& file) {
  return IncludeExpander().expand(text, file);
}

std::string read_config_text(const fs::path& path, std::size_t max_bytes) {
  // Opened without waiting (a pipe would block until a writer came) and
  // checked on the descriptor, so what is read is what was checked.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) {
    if (errno == ENOENT) throw UnreadableConfigFile("no such file");
    throw UnreadableConfigFile(std::strerror(errno));
  }
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat status {};
  if (::fstat(fd, &status) != 0) throw UnreadableConfigFile(std::strerror(errno));
  if (S_ISDIR(status.st_mode)) throw UnreadableConfigFile("it is a directory, not a file");
  if (!S_ISREG(status.st_mode)) {
    throw UnreadableConfigFile("it is not a regular file (a device, a pipe or a socket)");
  }
  const auto too_large = [] {
    return UnreadableConfigFile("too large: a configuration with its includes may have " +
                                std::to_string(kMaxConfigBytes) + " bytes at most");
  };
  if (static_cast<std::uintmax_t>(status.st_size) > max_bytes) throw too_large();
  std::string text;
  char block[16384];
  for (;;) {
    const ssize_t count = ::read(fd, block, sizeof block);
    if (count < 0 && errno == EINTR) continue;
    if (count < 0) throw UnreadableConfigFile(std::strerror(errno));
    if (count == 0) break;
    // The file may have grown since fstat.
    if (text.size() + static_cast<std::size_t>(count) > max_bytes) throw too_large();
    text.append(block, static_cast<std::size_t>(count));
  }
  return text;
}

std::optional<std::string> read_text_file(const std::filesystem::path& path) {
  try {
    return read_config_text(path);
  } catch (const UnreadableConfigFile&) {
    return std::nullopt;
  }
}

}  // namespace playerkit::config
