#include "map/flat_yaml.hpp"

#include "map/map_file_error.hpp"
#include "text/printable.hpp"

#include <cctype>

namespace playerkit::map {
namespace {

bool is_blank(char c) { return c == ' ' || c == '\t'; }

// One line of the file, read left to right; columns are 1-based.
class LineReader {
 public:
  LineReader(std::string_view text, int line, const std::filesystem::path& file)
      : text_(text), line_(line), file_(file) {}

  [[noreturn]] void fail(std::size_t position, const std::string& message) const {
    throw MapFileError(file_, line_, static_cast<int>(position) + 1, message);
  }

  std::size_t position() const { return position_; }
  bool at_end() const { return position_ >= text_.size(); }
  char peek() const { return at_end() ? '\0' : text_[position_]; }
  void skip_blanks() {
    while (!at_end() && is_blank(text_[position_])) ++position_;
  }

  std::string read_key() {
    const std::size_t start = position_;
    while (!at_end() && text_[position_] != ':' && !is_blank(text_[position_])) {
      const char c = text_[position_];
      if (c == '"' || c == '\'' || c == '[' || c == '{' || (c == '-' && position_ == start)) {
        fail(position_, "expected a plain key (quoted keys, lists and mappings are not supported)");
      }
      ++position_;
    }
    if (position_ == start) fail(start, "expected a key");
    std::string key(text_.substr(start, position_ - start));
    skip_blanks();
    if (peek() != ':') fail(position_, "expected ':' after key '" + text::excerpt(key) + "'");
    ++position_;
    if (!at_end() && !is_blank(peek())) fail(position_, "expected a space after ':'");
    return key;
  }

  YamlValue read_value(int key_column) {
    skip_blanks();
    YamlValue value;
    value.line = line_;
    value.column = at_end() ? key_column : static_cast<int>(position_) + 1;
    if (at_end()) {
      value.scalar = {"", false, line_, key_column};
      return value;
    }
    if (peek() == '{') fail(position_, "flow mappings ({...}) are not supported");
    if (peek() == '[') {
      value.is_list = true;
      read_list(value.items);
    } else {
      value.scalar = read_scalar(/*in_list=*/false);
    }
    skip_blanks();
    if (!at_end()) fail(position_, "unexpected text after the value");
    return value;
  }

 private:
  void read_list(std::vector<YamlScalar>& items) {
    const std::size_t open = position_++;
    skip_blanks();
    if (peek() == ']') {
      ++position_;
      return;
    }
    while (true) {
      skip_blanks();
      if (at_end()) fail(open, "unterminated '['");
      if (peek() == '[' || peek() == '{') fail(position_, "nested lists and mappings are not supported");
      if (peek() == ',' || peek() == ']') fail(position_, "empty list item");
      items.push_back(read_scalar(/*in_list=*/true));
      skip_blanks();
      if (at_end()) fail(open, "unterminated '['");
      if (peek() == ']') {
        ++position_;
        return;
      }
      if (peek() != ',') fail(position_, "expected ',' or ']' in list");
      ++position_;
    }
  }

  YamlScalar read_scalar(bool in_list) {
    YamlScalar scalar{"", false, line_, static_cast<int>(position_) + 1};
    const char quote = peek();
    if (quote == '"' || quote == '\'') {
      scalar.quoted = true;
      const std::size_t open = position_++;
      while (true) {
        if (at_end()) fail(open, "unterminated quoted string");
        const char c = text_[position_++];
        if (c == quote) {
          // In single quotes a doubled quote stands for one.
          if (quote == '\'' && peek() == '\'') {
            scalar.text += '\'';
            ++position_;
            continue;
          }
          return scalar;
        }
        if (c == '\\' && quote == '"') {
          if (at_end()) fail(open, "unterminated quoted string");
          const char escaped = text_[position_++];
          switch (escaped) {
            case '"': case '\\': case '/': scalar.text += escaped; break;
            case 'n': scalar.text += '\n'; break;
            case 't': scalar.text += '\t'; break;
            default: fail(position_ - 2, std::string("unsupported escape '\\") + escaped + "'");
          }
          continue;
        }
        scalar.text += c;
      }
    }
    const std::size_t start = position_;
    while (!at_end() && !(in_list && (peek() == ',' || peek() == ']'))) {
      if (in_list && (peek() == '[' || peek() == '{')) fail(position_, "nested lists and mappings are not supported");
      ++position_;
    }
    std::string_view text = text_.substr(start, position_ - start);
    while (!text.empty() && is_blank(text.back())) text.remove_suffix(1);
    scalar.text = std::string(text);
    return scalar;
  }

  std::string_view text_;
  std::size_t position_ = 0;
  int line_;
  const std::filesystem::path& file_;
};

// The line without its comment. YAML starts a comment at '#' at the start of
// the line or after a blank, and never inside quotes.
std::string_view strip_comment(std::string_view line) {
  char quote = '\0';
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quote != '\0') {
      if (c == '\\' && quote == '"') ++i;
      else if (c == quote) quote = '\0';
    } else if (c == '"' || c == '\'') {
      quote = c;
    } else if (c == '#' && (i == 0 || is_blank(line[i - 1]))) {
      return line.substr(0, i);
    }
  }
  return line;
}

}  // namespace

FlatYaml parse_flat_yaml(std::string_view text, const std::filesystem::path& file) {
  FlatYaml entries;
  int line_number = 0;
  bool seen_content = false;
  while (!text.empty() || line_number == 0) {
    ++line_number;
    const std::size_t newline = text.find('\n');
    std::string_view line = text.substr(0, newline);
    text = newline == std::string_view::npos ? std::string_view{} : text.substr(newline + 1);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);

    line = strip_comment(line);
    while (!line.empty() && is_blank(line.back())) line.remove_suffix(1);
    if (line.empty()) continue;
    if (line == "---" && !seen_content) continue;
    seen_content = true;

    LineReader reader(line, line_number, file);
    if (is_blank(line.front())) {
      reader.skip_blanks();
      reader.fail(reader.position(), "indented line: nested values are not supported in a map file");
    }
    const int key_column = static_cast<int>(reader.position()) + 1;
    std::string key = reader.read_key();
    YamlValue value = reader.read_value(key_column);
    if (entries.contains(key)) reader.fail(0, "duplicate key '" + text::excerpt(key) + "'");
    entries.emplace(std::move(key), std::move(value));
  }
  return entries;
}

}  // namespace playerkit::map
