#include "text/line_reader.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

namespace playerkit::text {
namespace line_reader_test {

std::vector<std::string> all_lines(std::istream& in, std::size_t max_bytes = kMaxLineBytes) {
  std::vector<std::string> lines;
  std::string line;
  for (long long number = 1; read_line(in, line, "input", number, max_bytes); ++number) lines.push_back(line);
  return lines;
}

TEST(ReadLine, ReadsLikeGetline) {
  for (const std::string text : {"", "a", "a\n", "a\nb", "a\n\nb\n", "\n", "a\r\nb"}) {
    std::istringstream ours(text);
    std::istringstream theirs(text);
    std::vector<std::string> expected;
    std::string line;
    while (std::getline(theirs, line)) expected.push_back(line);
    EXPECT_EQ(all_lines(ours), expected) << '"' << text << '"';
    EXPECT_EQ(ours.rdstate(), theirs.rdstate()) << '"' << text << '"';
  }
}

TEST(ReadLine, LinesLongerThanOneChunkReadLikeGetline) {
  // The reader takes 4 KB at a time: lines on either side of that size.
  for (const std::size_t length : {4094u, 4095u, 4096u, 4097u, 8190u, 8191u, 8192u, 12289u}) {
    const std::string a(length, 'a'), b(length + 1, 'b');
    for (const std::string& text : {a, a + "\n", a + "\n" + b, a + "\n\n" + b + "\n"}) {
      std::istringstream ours(text);
      std::istringstream theirs(text);
      std::vector<std::string> expected;
      std::string line;
      while (std::getline(theirs, line)) expected.push_back(line);
      EXPECT_EQ(all_lines(ours), expected) << length;
      EXPECT_EQ(ours.rdstate(), theirs.rdstate()) << length;
    }
  }
}

TEST(ReadLine, EofTellsWhetherTheLastLineEndedWithANewline) {
  std::string line;
  std::istringstream ended("a\n");
  ASSERT_TRUE(read_line(ended, line, "x", 1));
  EXPECT_FALSE(ended.eof());
  std::istringstream unended("a");
  ASSERT_TRUE(read_line(unended, line, "x", 1));
  EXPECT_TRUE(unended.eof());
}

TEST(ReadLine, ALineAtTheCapIsRead) {
  std::istringstream in(std::string(16, 'x') + "\nnext");
  EXPECT_EQ(all_lines(in, 16), (std::vector<std::string>{std::string(16, 'x'), "next"}));
}

TEST(ReadLine, ALongerLineIsAnErrorNamingFileAndLine) {
  std::istringstream in("short\n" + std::string(17, '\x1b') + "\nafter");
  std::string line;
  ASSERT_TRUE(read_line(in, line, "run.log", 1, 16));
  try {
    read_line(in, line, "run.log", 2, 16);
    FAIL() << "no error";
  } catch (const LineTooLongError& error) {
    EXPECT_STREQ(error.what(), "run.log:2: line longer than 16 bytes");
    EXPECT_EQ(error.line_number(), 2);
  }
  EXPECT_LE(line.size(), 16u);
  // The long line is dropped: reading goes on with the next one.
  ASSERT_TRUE(read_line(in, line, "run.log", 3, 16));
  EXPECT_EQ(line, "after");
  EXPECT_FALSE(read_line(in, line, "run.log", 4, 16));
}

TEST(ReadLine, ACapBeyondOneChunkIsKeptToTheByte) {
  std::istringstream in(std::string(5000, 'x') + "\n" + std::string(5001, 'y') + "\nlast");
  std::string line;
  ASSERT_TRUE(read_line(in, line, "run.log", 1, 5000));
  EXPECT_EQ(line.size(), 5000u);
  EXPECT_THROW(read_line(in, line, "run.log", 2, 5000), LineTooLongError);
  EXPECT_EQ(line, std::string(5000, 'y'));
  ASSERT_TRUE(read_line(in, line, "run.log", 3, 5000));
  EXPECT_EQ(line, "last");
}

TEST(ReadLine, AHugeLineCostsOnlyTheCap) {
  // 64 MiB of one line: what is kept stops at the cap.
  std::istringstream in(std::string(std::size_t{64} << 20, 'x'));
  std::string line;
  EXPECT_THROW(read_line(in, line, "big", 1), LineTooLongError);
  EXPECT_LE(line.capacity(), 2 * kMaxLineBytes);
  EXPECT_FALSE(read_line(in, line, "big", 2));
}

TEST(ReadLine, TheNameIsEscapedInTheMessage) {
  std::istringstream in(std::string(5, 'x'));
  std::string line;
  try {
    read_line(in, line, "evil\x1b[2J.log", 7, 4);
    FAIL() << "no error";
  } catch (const LineTooLongError& error) {
    EXPECT_STREQ(error.what(), "evil\\x1b[2J.log:7: line longer than 4 bytes");
  }
}

}  // namespace line_reader_test
}  // namespace playerkit::text
