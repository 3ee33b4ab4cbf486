#include "config/lexer.hpp"


#include "config/errors.hpp"
#include "config/limits.hpp"
#include "text/printable.hpp"

namespace playerkit::config {
namespace {

// The character classes of 1.5's tokenizer. They are spelled out rather than
// taken from <cctype> so that the locale cannot change what a word is.
bool is_letter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_word_char(char c) {
  return is_letter(c) || is_digit(c) || c == '.' || c == '-' || c == '_' || c == '[' || c == ']' ||
         c == ':';
}
bool is_number_char(char c) { return is_digit(c) || c == '+' || c == '-' || c == '.'; }
bool is_line_break(char c) { return c == '\n' || c == '\r'; }

class Lexer {
 public:
  Lexer(std::string_view text, const std::string& file) : text_(text), file_(file) {}

  std::vector<Token> run() {
    refuse_long_lines();
    std::vector<Token> tokens;
    while (!at_end()) {
      const char c = peek();
      if (c == ' ' || c == '\t') {
        advance();
      } else if (c == '#') {
        while (!at_end() && !is_line_break(peek())) advance();
      } else if (is_line_break(c)) {
        tokens.push_back(single(TokenKind::Newline, "\n"));
        if (c == '\r' && !at_end() && peek() == '\n') ++pos_;  // CRLF is one break
        ++line_;
        column_ = 1;
      } else if (c == '"') {
        tokens.push_back(string());
      } else if (is_letter(c)) {
        tokens.push_back(run_of(TokenKind::Word, is_word_char));
      } else if (is_number_char(c)) {
        tokens.push_back(run_of(TokenKind::Number, is_number_char));
      } else if (c == '(') {
        tokens.push_back(single(TokenKind::OpenParen, "("));
      } else if (c == ')') {
        tokens.push_back(single(TokenKind::CloseParen, ")"));
      } else if (c == '[') {
        tokens.push_back(single(TokenKind::OpenBracket, "["));
      } else if (c == ']') {
        tokens.push_back(single(TokenKind::CloseBracket, "]"));
      } else {
        throw ConfigError(here(), "syntax error: unexpected " + text::describe_character(c));
      }
    }
    tokens.push_back(Token{TokenKind::EndOfFile, "", here()});
    return tokens;
  }

 private:
  // Before any token: a line over the limit is reported first, wherever it is.
  void refuse_long_lines() const {
    int line = 1;
    std::size_t start = 0;
    for (std::size_t i = 0; i <= text_.size(); ++i) {
      if (i < text_.size() && !is_line_break(text_[i])) continue;
      if (i - start > kMaxConfigLineBytes) {
        throw ConfigError(SourceLocation{file_, line, static_cast<int>(kMaxConfigLineBytes) + 1},
                          "line longer than " + std::to_string(kMaxConfigLineBytes) + " bytes");
      }
      if (i + 1 < text_.size() && text_[i] == '\r' && text_[i + 1] == '\n') ++i;
      ++line;
      start = i + 1;
    }
  }

  bool at_end() const { return pos_ >= text_.size(); }
  char peek() const { return text_[pos_]; }
  void advance() {
    ++pos_;
    ++column_;
  }
  SourceLocation here() const { return SourceLocation{file_, line_, column_}; }

  Token single(TokenKind kind, std::string text) {
    Token token{kind, std::move(text), here()};
    advance();
    return token;
  }

  template <typename CharClass>
  Token run_of(TokenKind kind, CharClass belongs) {
    Token token{kind, "", here()};
    const std::size_t start = pos_;
    while (!at_end() && belongs(peek())) advance();
    token.text = std::string(text_.substr(start, pos_ - start));
    return token;
  }

  Token string() {
    Token token{TokenKind::String, "", here()};
    advance();  // opening quote
    const std::size_t start = pos_;
    while (!at_end() && peek() != '"' && !is_line_break(peek())) advance();
    if (at_end() || peek() != '"') {
      throw ConfigError(token.where, "unterminated string: missing closing '\"' on this line");
    }
    token.text = std::string(text_.substr(start, pos_ - start));
    advance();  // closing quote
    return token;
  }

  std::string_view text_;
  const std::string& file_;
  std::size_t pos_ = 0;
  int line_ = 1;
  int column_ = 1;
};

}  // namespace

std::vector<Token> tokenize(std::string_view text, const std::string& file) {
  return Lexer(text, file).run();
}

}  // namespace playerkit::config
