// include "file" splices the file's tokens in place of the statement.

#include "config/includes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "config/lexer.hpp"
#include "config/test_support.hpp"

namespace playerkit::config {
namespace includes_test {

using testing::data_path;
using testing::error_of;

std::vector<Token> tokens_of_file(const std::string& path) {
  const auto text = read_text_file(path);
  EXPECT_TRUE(text.has_value()) << path;
  return tokenize_with_includes(text.value_or(""), path);
}

std::vector<std::string> words_of(const std::vector<Token>& tokens) {
  std::vector<std::string> words;
  for (const Token& token : tokens) {
    if (token.kind == TokenKind::Word || token.kind == TokenKind::String)
      words.push_back(token.text);
  }
  return words;
}

TEST(ReadTextFile, ReadsWholeFileAndRejectsMissingOnesAndDirectories) {
  const auto text = read_text_file(data_path("includes/sub/laser-options.cfg"));
  EXPECT_EQ(text, "port \"/dev/ttyS2\"\npose [ 10 0 90 ]\n");
  EXPECT_EQ(read_text_file(data_path("includes/nothere.cfg")), std::nullopt);
  EXPECT_EQ(read_text_file(data_path("includes")), std::nullopt);
}

TEST(Includes, TextWithoutIncludesIsJustTokenized) {
  EXPECT_EQ(tokenize_with_includes("a 1\n", "x.cfg"), tokenize("a 1\n", "x.cfg"));
}

TEST(Includes, NestedIncludesResolveAgainstTheIncludingFile) {
  const std::string main = data_path("includes/nested-main.cfg");
  const auto tokens = tokens_of_file(main);
  EXPECT_EQ(words_of(tokens),
            (std::vector<std::string>{"define", "pioneer2", "position", "driver", "p2os_position",
                                      "port", "/dev/ttyS0", "robot_radius", "sonar:0", "driver",
                                      "p2os_sonar", "range_max", "map", "maps/cave.pgm",
                                      "unit_length", "cm", "pioneer2", "port", "/dev/ttyS1"}));
  // Tokens keep the file they come from.
  const auto location_of = [&](const std::string& text) {
    const auto found =
        std::find_if(tokens.begin(), tokens.end(), [&](const Token& t) { return t.text == text; });
    return found == tokens.end() ? SourceLocation{} : found->where;
  };
  EXPECT_EQ(location_of("define"), (SourceLocation{data_path("includes/sub/defines.cfg"), 1, 1}));
  EXPECT_EQ(location_of("sonar:0"), (SourceLocation{data_path("includes/sub/robot.cfg"), 3, 1}));
  EXPECT_EQ(location_of("unit_length"), (SourceLocation{main, 5, 1}));
  // The end of file is the main file's.
  EXPECT_EQ(tokens.back().kind, TokenKind::EndOfFile);
  EXPECT_EQ(tokens.back().where, (SourceLocation{main, 8, 1}));
}

TEST(Includes, IncludeInsideASectionSplicesProperties) {
  const auto tokens = tokens_of_file(data_path("includes/inside-section.cfg"));
  EXPECT_EQ(words_of(tokens), (std::vector<std::string>{"laser:0", "driver", "sicklms200", "port",
                                                        "/dev/ttyS2", "pose"}));
}

TEST(Includes, AbsolutePathIsUsedAsIs) {
  const std::string text = "include \"" + data_path("includes/sub/laser-options.cfg") + "\"\n";
  const auto tokens = tokenize_with_includes(text, "/nowhere/else/x.cfg");
  EXPECT_EQ(words_of(tokens), (std::vector<std::string>{"port", "/dev/ttyS2", "pose"}));
}

TEST(Includes, RelativeToTheDirectoryOfTheGivenName) {
  const std::string text = "include \"sub/laser-options.cfg\"";
  const auto tokens = tokenize_with_includes(text, data_path("includes/virtual.cfg"));
  EXPECT_EQ(words_of(tokens), (std::vector<std::string>{"port", "/dev/ttyS2", "pose"}));
}

TEST(Includes, MissingFileIsReportedAtTheFileName) {
  const std::string file = data_path("includes/missing.cfg");
  EXPECT_EQ(error_of([&] { (void)tokens_of_file(file); }),
            file + ":2:11: cannot read include file 'nothere.cfg': no such file (looked for " +
                data_path("includes/nothere.cfg") + ")");
}

TEST(Includes, CycleIsReportedWithTheChain) {
  const std::string b = data_path("includes/cycle-b.cfg");
  EXPECT_EQ(error_of([&] { (void)tokens_of_file(data_path("includes/cycle-a.cfg")); }),
            b + ":2:9: include cycle: cycle-a.cfg -> cycle-b.cfg -> cycle-a.cfg");
}

TEST(Includes, FileIncludingItselfUnderAnotherSpellingIsACycle) {
  const std::string self = data_path("includes/self.cfg");
  EXPECT_EQ(error_of([&] { (void)tokens_of_file(self); }),
            self + ":1:9: include cycle: self.cfg -> self.cfg");
}

TEST(Includes, SameFileTwiceInARowIsNotACycle) {
  const std::string options = data_path("includes/sub/laser-options.cfg");
  const std::string text = "include \"" + options + "\"\ninclude \"" + options + "\"\n";
  EXPECT_EQ(words_of(tokenize_with_includes(text, "x.cfg")),
            (std::vector<std::string>{"port", "/dev/ttyS2", "pose", "port", "/dev/ttyS2", "pose"}));
}

TEST(Includes, FileNameMustBeAQuotedStringOnTheSameLine) {
  EXPECT_EQ(error_of([] { (void)tokenize_with_includes("include foo.cfg\n", "x.cfg"); }),
            "x.cfg:1:9: syntax error: expected a file name in quotes after 'include', found "
            "word 'foo.cfg'");
  EXPECT_EQ(error_of([] { (void)tokenize_with_includes("include\n\"a.cfg\"\n", "x.cfg"); }),
            "x.cfg:1:8: syntax error: expected a file name in quotes after 'include', found "
            "newline");
  EXPECT_EQ(error_of([] { (void)tokenize_with_includes("include", "x.cfg"); }),
            "x.cfg:1:8: syntax error: expected a file name in quotes after 'include', found "
            "end of file");
}

TEST(Includes, StatementMustBeAloneOnItsLine) {
  EXPECT_EQ(
      error_of([] { (void)tokenize_with_includes("include \"a.cfg\" laser:0 ()\n", "x.cfg"); }),
      "x.cfg:1:17: syntax error: expected end of line after include \"a.cfg\", found word "
      "'laser:0'");
}

TEST(Includes, ErrorsInsideAnIncludedFileNameThatFile) {
  const std::string text = "include \"" + data_path("broken-bad-character.cfg") + "\"\n";
  EXPECT_EQ(error_of([&] { (void)tokenize_with_includes(text, "x.cfg"); }),
            data_path("broken-bad-character.cfg") + ":3:8: syntax error: unexpected character '='");
}

}  // namespace includes_test
}  // namespace playerkit::config
