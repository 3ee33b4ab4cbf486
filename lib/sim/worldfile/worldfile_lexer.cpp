#include "sim/worldfile/worldfile_lexer.hpp"


#include "sim/worldfile/worldfile_error.hpp"
#include "text/printable.hpp"

namespace playerkit::sim::worldfile {
namespace {

// Spelled out rather than taken from <cctype>: the locale must not change
// what a word is.
bool is_world_letter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
bool is_world_digit(char c) { return c >= '0' && c <= '9'; }
bool is_world_word_char(char c) {
  return is_world_letter(c) || is_world_digit(c) || c == '.' || c == '-' || c == '_' || c == '[' || c == ']';
}
bool is_world_number_char(char c) { return is_world_digit(c) || c == '+' || c == '-' || c == '.'; }
bool is_world_line_break(char c) { return c == '\n' || c == '\r'; }
bool is_world_blank(char c) { return c == ' ' || c == '\t'; }

class WorldLexer {
 public:
  WorldLexer(std::string_view text, const std::string& file, std::vector<Token>& out,
             const IncludeHandler& on_include)
      : text_(text), file_(file), out_(out), on_include_(on_include) {}

  SourceLocation run() {
    while (!at_end()) {
      const char c = peek();
      if (is_world_blank(c)) {
        advance();
      } else if (c == '#') {
        const SourceLocation start = here();
        while (!at_end() && !is_world_line_break(peek())) advance();
        out_.push_back(Token{TokenKind::Comment, "#", start});
      } else if (is_world_line_break(c)) {
        line_break();
      } else if (c == '"') {
        out_.push_back(string());
      } else if (is_world_letter(c)) {
        Token word = run_of(TokenKind::Word, is_world_word_char);
        if (word.text == "include") {
          include();
        } else {
          out_.push_back(std::move(word));
        }
      } else if (is_world_number_char(c)) {
        out_.push_back(run_of(TokenKind::Number, is_world_number_char));
      } else if (c == '(' || c == ')' || c == '[' || c == ']') {
        const TokenKind kind = c == '(' ? TokenKind::OpenEntity
                               : c == ')' ? TokenKind::CloseEntity
                               : c == '[' ? TokenKind::OpenTuple
                                          : TokenKind::CloseTuple;
        out_.push_back(Token{kind, std::string(1, c), here()});
        advance();
      } else {
        std::string message = "syntax error: unexpected " + text::describe_character(c);
        if (c == ',') message += " (the values of a tuple are separated by spaces, not commas)";
        if (c == '{' || c == '}') message += " (entities are written with '(' and ')')";
        throw WorldFileError(here(), message);
      }
    }
    return here();
  }

 private:
  bool at_end() const { return pos_ >= text_.size(); }
  char peek() const { return text_[pos_]; }
  void advance() {
    ++pos_;
    ++column_;
  }
  SourceLocation here() const { return SourceLocation{file_, line_, column_}; }

  // CR, LF, CRLF and LFCR are each one line break, as in Stage.
  void line_break() {
    out_.push_back(Token{TokenKind::Newline, "\n", here()});
    const char first = peek();
    ++pos_;
    if (!at_end() && is_world_line_break(peek()) && peek() != first) ++pos_;
    ++line_;
    column_ = 1;
  }

  Token run_of(TokenKind kind, bool (*continues)(char)) {
    Token token{kind, "", here()};
    const std::size_t start = pos_;
    while (!at_end() && continues(peek())) advance();
    token.text = std::string(text_.substr(start, pos_ - start));
    return token;
  }

  Token string() {
    Token token{TokenKind::String, "", here()};
    advance();  // the opening quote
    const std::size_t start = pos_;
    while (!at_end() && peek() != '"') {
      if (is_world_line_break(peek())) break;
      advance();
    }
    if (at_end() || peek() != '"') {
      throw WorldFileError(token.where, "unterminated string: a string must close on the line it starts");
    }
    token.text = std::string(text_.substr(start, pos_ - start));
    advance();  // the closing quote
    return token;
  }

  // `include "file"`: the rest of the line is ignored, as in Stage.
  void include() {
    const bool blank = !at_end() && is_world_blank(peek());
    while (!at_end() && is_world_blank(peek())) advance();
    if (!blank || at_end() || peek() != '"') {
      throw WorldFileError(here(),
                           "incomplete include statement: 'include' must be followed by a space and a file "
                           "name in quotes on the same line");
    }
    const Token name = string();
    while (!at_end() && !is_world_line_break(peek())) advance();
    on_include_(name, out_);
  }

  std::string_view text_;
  const std::string& file_;
  std::vector<Token>& out_;
  const IncludeHandler& on_include_;
  std::size_t pos_ = 0;
  int line_ = 1;
  int column_ = 1;
};

}  // namespace

std::string describe(const Token& token) {
  switch (token.kind) {
    case TokenKind::Word: return "the word \"" + text::excerpt(token.text) + "\"";
    case TokenKind::Number: return "the number " + text::excerpt(token.text);
    case TokenKind::String: return "the string \"" + text::excerpt(token.text) + "\"";
    case TokenKind::OpenEntity: return "'('";
    case TokenKind::CloseEntity: return "')'";
    case TokenKind::OpenTuple: return "'['";
    case TokenKind::CloseTuple: return "']'";
    case TokenKind::Comment: return "a comment";
    case TokenKind::Newline: return "the end of the line";
    case TokenKind::EndOfFile: return "the end of the file";
  }
  return "a token";
}

SourceLocation tokenize(std::string_view text, const std::string& file, std::vector<Token>& out,
                        const IncludeHandler& on_include) {
  WorldLexer lexer(text, file, out, on_include);
  return lexer.run();
}

}  // namespace playerkit::sim::worldfile
