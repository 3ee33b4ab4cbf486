// The lexical rules of server-behaviour.md §9.1, quirks included.

#include "config/lexer.hpp"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "config/errors.hpp"

namespace playerkit::config {
namespace lexer_test {

using Kinds = std::vector<TokenKind>;
using Texts = std::vector<std::string>;

std::vector<Token> lex(std::string_view text) { return tokenize(text, "t.cfg"); }

Kinds kinds_of(const std::vector<Token>& tokens) {
  Kinds kinds;
  for (const Token& token : tokens) kinds.push_back(token.kind);
  return kinds;
}

// The texts of all tokens except the final end of file.
Texts texts_of(const std::vector<Token>& tokens) {
  Texts texts;
  for (const Token& token : tokens) {
    if (token.kind != TokenKind::EndOfFile) texts.push_back(token.text);
  }
  return texts;
}

std::string error_of(std::string_view text) {
  try {
    (void)lex(text);
  } catch (const ConfigError& error) {
    return error.what();
  }
  return "no error";
}

TEST(Lexer, EmptyTextIsJustEndOfFile) {
  const auto tokens = lex("");
  ASSERT_EQ(tokens.size(), 1u);
  EXPECT_EQ(tokens[0].kind, TokenKind::EndOfFile);
  EXPECT_EQ(tokens[0].where, (SourceLocation{"t.cfg", 1, 1}));
}

TEST(Lexer, SectionWithStringProperty) {
  const auto tokens = lex("position:0 ( driver \"p2os_position\" )\n");
  EXPECT_EQ(kinds_of(tokens),
            (Kinds{TokenKind::Word, TokenKind::OpenParen, TokenKind::Word, TokenKind::String,
                   TokenKind::CloseParen, TokenKind::Newline, TokenKind::EndOfFile}));
  EXPECT_EQ(texts_of(tokens), (Texts{"position:0", "(", "driver", "p2os_position", ")", "\n"}));
}

TEST(Lexer, LocationsAreLineAndColumnOfTheFirstCharacter) {
  const auto tokens = lex("a 1\n  bb \"s\"\n");
  EXPECT_EQ(tokens[0].where, (SourceLocation{"t.cfg", 1, 1}));
  EXPECT_EQ(tokens[1].where, (SourceLocation{"t.cfg", 1, 3}));
  EXPECT_EQ(tokens[2].where, (SourceLocation{"t.cfg", 1, 4}));  // the newline
  EXPECT_EQ(tokens[3].where, (SourceLocation{"t.cfg", 2, 3}));
  EXPECT_EQ(tokens[4].where, (SourceLocation{"t.cfg", 2, 6}));  // the opening quote
  EXPECT_EQ(tokens[6].where, (SourceLocation{"t.cfg", 3, 1}));  // end of file
}

TEST(Lexer, WordsKeepDotsColonsDashesUnderscoresAndBrackets) {
  EXPECT_EQ(texts_of(lex("a.b robot:6666:bob laser:0 map_file x-y pose[0] Z9")),
            (Texts{"a.b", "robot:6666:bob", "laser:0", "map_file", "x-y", "pose[0]", "Z9"}));
  for (const Token& token : lex("a.b robot:6666:bob pose[0]")) {
    if (token.kind != TokenKind::EndOfFile) {
      EXPECT_EQ(token.kind, TokenKind::Word) << token.text;
    }
  }
}

TEST(Lexer, BracketGluedToAWordIsPartOfTheWord) {
  // 1.5 quirk: "pose[0 0 0]" is the word "pose[0", two numbers and a ']'.
  const auto tokens = lex("pose[0 0 0]");
  EXPECT_EQ(kinds_of(tokens), (Kinds{TokenKind::Word, TokenKind::Number, TokenKind::Number,
                                     TokenKind::CloseBracket, TokenKind::EndOfFile}));
  EXPECT_EQ(texts_of(tokens), (Texts{"pose[0", "0", "0", "]"}));
}

TEST(Lexer, SpacedBracketsAreTupleBrackets) {
  const auto tokens = lex("pose [0 -1.5 +2]");
  EXPECT_EQ(kinds_of(tokens),
            (Kinds{TokenKind::Word, TokenKind::OpenBracket, TokenKind::Number, TokenKind::Number,
                   TokenKind::Number, TokenKind::CloseBracket, TokenKind::EndOfFile}));
  EXPECT_EQ(texts_of(tokens), (Texts{"pose", "[", "0", "-1.5", "+2", "]"}));
}

TEST(Lexer, NumbersAreRunsOfSignsDotsAndDigits) {
  EXPECT_EQ(texts_of(lex("6665 -1 .5 +3. 1.2.3 --")),
            (Texts{"6665", "-1", ".5", "+3.", "1.2.3", "--"}));
  for (const Token& token : lex("6665 -1 .5 1.2.3")) {
    if (token.kind != TokenKind::EndOfFile) {
      EXPECT_EQ(token.kind, TokenKind::Number) << token.text;
    }
  }
}

TEST(Lexer, ExponentIsNotPartOfANumber) {
  const auto tokens = lex("1e-3");
  EXPECT_EQ(kinds_of(tokens), (Kinds{TokenKind::Number, TokenKind::Word, TokenKind::EndOfFile}));
  EXPECT_EQ(texts_of(tokens), (Texts{"1", "e-3"}));
}

TEST(Lexer, HexIsNotANumber) { EXPECT_EQ(texts_of(lex("0x1F")), (Texts{"0", "x1F"})); }

TEST(Lexer, StringKeepsContentsWithoutQuotesOrEscapes) {
  const auto tokens = lex(R"("a \n b # not a comment" "")");
  ASSERT_EQ(tokens.size(), 3u);
  EXPECT_EQ(tokens[0].kind, TokenKind::String);
  EXPECT_EQ(tokens[0].text, R"(a \n b # not a comment)");
  EXPECT_EQ(tokens[1].kind, TokenKind::String);
  EXPECT_EQ(tokens[1].text, "");
}

TEST(Lexer, CommentsRunToTheEndOfTheLineAnywhere) {
  const auto tokens = lex("# heading\nlaser:0 ( # after paren\n port 1 # trailing ( ) \" [\n)#x");
  EXPECT_EQ(texts_of(tokens), (Texts{"\n", "laser:0", "(", "\n", "port", "1", "\n", ")"}));
}

TEST(Lexer, CommentEndsAWord) { EXPECT_EQ(texts_of(lex("laser:0#comment")), (Texts{"laser:0"})); }

TEST(Lexer, CrLfIsOneLineBreak) {
  const auto tokens = lex("a 1\r\nb 2\r\n");
  EXPECT_EQ(texts_of(tokens), (Texts{"a", "1", "\n", "b", "2", "\n"}));
  EXPECT_EQ(tokens[3].where, (SourceLocation{"t.cfg", 2, 1}));
  EXPECT_EQ(tokens.back().where, (SourceLocation{"t.cfg", 3, 1}));
}

TEST(Lexer, LoneCarriageReturnIsALineBreak) {
  const auto tokens = lex("a 1\rb 2");
  EXPECT_EQ(texts_of(tokens), (Texts{"a", "1", "\n", "b", "2"}));
  EXPECT_EQ(tokens[3].where, (SourceLocation{"t.cfg", 2, 1}));
}

TEST(Lexer, TabsAndSpacesSeparateTokens) {
  EXPECT_EQ(texts_of(lex("\ta\t \t1 ")), (Texts{"a", "1"}));
}

TEST(Lexer, UnexpectedCharacterIsASyntaxError) {
  EXPECT_EQ(error_of("laser:0 {\n"), "t.cfg:1:9: syntax error: unexpected character '{'");
  EXPECT_EQ(error_of("a 1\n  port = 5\n"), "t.cfg:2:8: syntax error: unexpected character '='");
  EXPECT_EQ(error_of("'x'"), "t.cfg:1:1: syntax error: unexpected character '''");
  EXPECT_EQ(error_of("_x 1"), "t.cfg:1:1: syntax error: unexpected character '_'");
}

TEST(Lexer, NonAsciiByteIsNamedInHex) {
  EXPECT_EQ(error_of("a \xC3\xA9"), "t.cfg:1:3: syntax error: unexpected byte 0xC3");
}

TEST(Lexer, StringMustCloseOnItsLine) {
  EXPECT_EQ(error_of("port \"/dev/ttyS0\nx"),
            "t.cfg:1:6: unterminated string: missing closing '\"' on this line");
  EXPECT_EQ(error_of("a 1\n  port \"/dev/tty"),
            "t.cfg:2:8: unterminated string: missing closing '\"' on this line");
}

TEST(Lexer, DescribeNamesTokensForMessages) {
  EXPECT_EQ(describe(Token{TokenKind::Word, "foo", {}}), "word 'foo'");
  EXPECT_EQ(describe(Token{TokenKind::Number, "1.5", {}}), "number '1.5'");
  EXPECT_EQ(describe(Token{TokenKind::String, "x", {}}), "string \"x\"");
  EXPECT_EQ(describe(Token{TokenKind::OpenParen, "(", {}}), "'('");
  EXPECT_EQ(describe(Token{TokenKind::CloseBracket, "]", {}}), "']'");
  EXPECT_EQ(describe(Token{TokenKind::Newline, "\n", {}}), "newline");
  EXPECT_EQ(describe(Token{TokenKind::EndOfFile, "", {}}), "end of file");
}

}  // namespace lexer_test
}  // namespace playerkit::config
