#include "line_streams.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <sstream>
#include <thread>
#include <vector>

#include "input_lines.hpp"

namespace playerkit::player_drivers {
namespace line_streams_test {

TEST(SharedLines, WholeLinesFromSeveralThreadsNeverInterleave) {
  std::ostringstream target;
  SharedLines lines(target);
  std::vector<std::thread> writers;
  for (int writer = 0; writer < 4; ++writer) {
    writers.emplace_back([&lines, writer] {
      const auto stream = lines.open();
      for (int i = 0; i < 200; ++i) *stream << "writer " << writer << " line " << i << " end\n";
    });
  }
  for (auto& writer : writers) writer.join();
  std::istringstream written(target.str());
  std::string line;
  int count = 0;
  while (std::getline(written, line)) {
    ++count;
    EXPECT_EQ(line.rfind("writer ", 0), 0u) << line;
    EXPECT_EQ(line.substr(line.size() - 4), " end") << line;
  }
  EXPECT_EQ(count, 800);
}

TEST(SharedLines, APartialLineWaitsForItsEndOrAFlush) {
  std::ostringstream target;
  SharedLines lines(target);
  const auto stream = lines.open();
  *stream << "half";
  EXPECT_EQ(target.str(), "");
  *stream << " and the rest\nnext";
  EXPECT_EQ(target.str(), "half and the rest\n");
  *stream << std::flush;
  EXPECT_EQ(target.str(), "half and the rest\nnext");
  EXPECT_TRUE(lines.write_line("direct"));
  EXPECT_EQ(target.str(), "half and the rest\nnextdirect\n");
}

TEST(SharedLines, AFilterRewritesOrDropsEachLine) {
  std::ostringstream target;
  SharedLines lines(target);
  const auto stream = lines.open([](std::string_view line) -> std::optional<std::string> {
    if (line.starts_with("drop")) return std::nullopt;
    return "<" + std::string(line) + ">";
  });
  *stream << "one\ndrop this\ntwo\n" << std::flush;
  EXPECT_EQ(target.str(), "<one>\n<two>\n");
}

TEST(SharedLines, AFailedTargetMakesTheStreamBad) {
  std::ostringstream target;
  target.setstate(std::ios::badbit);
  SharedLines lines(target);
  const auto stream = lines.open();
  *stream << "lost\n";
  EXPECT_FALSE(*stream);
  EXPECT_FALSE(lines.write_line("lost too"));
}

TEST(InterruptibleInput, ReadsLinesThenEndsAtEndOfInput) {
  int pipe_ends[2];
  ASSERT_EQ(::pipe(pipe_ends), 0);
  const std::string text = "one\ntwo\n";
  ASSERT_EQ(::write(pipe_ends[1], text.data(), text.size()), static_cast<ssize_t>(text.size()));
  ::close(pipe_ends[1]);
  InterruptibleInput input(pipe_ends[0]);
  std::string line;
  ASSERT_TRUE(std::getline(input.stream(), line));
  EXPECT_EQ(line, "one");
  ASSERT_TRUE(std::getline(input.stream(), line));
  EXPECT_EQ(line, "two");
  EXPECT_FALSE(std::getline(input.stream(), line));
  ::close(pipe_ends[0]);
}

TEST(InterruptibleInput, StopEndsAReadNobodyAnswers) {
  int pipe_ends[2];
  ASSERT_EQ(::pipe(pipe_ends), 0);
  InterruptibleInput input(pipe_ends[0]);
  std::thread stopper([&input] {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    input.stop();
  });
  std::string line;
  EXPECT_FALSE(std::getline(input.stream(), line));  // returns although the pipe stays open
  stopper.join();
  ::close(pipe_ends[0]);
  ::close(pipe_ends[1]);
}

}  // namespace line_streams_test
}  // namespace playerkit::player_drivers
