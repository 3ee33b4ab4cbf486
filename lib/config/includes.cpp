#include "config/includes.hpp"

#include <fstream>
#include <iterator>
#include <system_error>

#include "config/errors.hpp"
#include "config/lexer.hpp"

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
                                             name.text + "\", found " + describe(after));
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
    OpenFile opened{identity_of(path), path.filename().string()};
    for (const OpenFile& open : open_files_) {
      if (open.identity == opened.identity) {
        std::string chain;
        for (const OpenFile& link : open_files_) chain += link.short_name + " -> ";
        throw ConfigError(name.where, "include cycle: " + chain + opened.short_name);
      }
    }
    const auto text = read_text_file(path);
    if (!text) {
      throw ConfigError(name.where, "cannot open include file '" + name.text + "' (looked for " +
                                        path.string() + ")");
    }
    open_files_.push_back(std::move(opened));
    append_tokens(*text, path.string());
    open_files_.pop_back();
  }

  std::vector<Token> tokens_;
  std::vector<OpenFile> open_files_;  // the include chain being read, outermost first
  SourceLocation end_of_main_file_;
};

}  // namespace

std::vector<Token> tokenize_with_includes(std::string_view text, const std::string& file) {
  return IncludeExpander().expand(text, file);
}

std::optional<std::string> read_text_file(const std::filesystem::path& path) {
  std::error_code error;
  if (fs::is_directory(path, error)) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) return std::nullopt;
  return text;
}

}  // namespace playerkit::config
