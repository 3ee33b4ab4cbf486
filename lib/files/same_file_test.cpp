#include "files/same_file.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>

#include "support/scratch_directory.hpp"

namespace playerkit::files {
namespace same_file_test {

using testing::ScratchDirectory;

TEST(SameFile, TheSameFileSpelledDifferentlyIsTheSameFile) {
  ScratchDirectory scratch("same_file_test");
  const auto log = scratch.write("a.log", "data\n");
  const auto dotted = scratch.path() / "." / "a.log";
  const auto linked = scratch.file("link.log");
  const auto hard = scratch.file("hard.log");
  std::filesystem::create_symlink(log, linked);
  std::filesystem::create_hard_link(log, hard);
  EXPECT_TRUE(same_file(log, dotted));
  EXPECT_TRUE(same_file(log, linked));
  EXPECT_TRUE(same_file(log, hard));
}

TEST(SameFile, EqualContentIsNotTheSameFile) {
  ScratchDirectory scratch("same_file_test");
  EXPECT_FALSE(same_file(scratch.write("a.log", "data\n"), scratch.write("b.log", "data\n")));
  EXPECT_FALSE(same_file(scratch.file("missing.log"), scratch.file("missing.log")));
}

TEST(RefuseOutputOverInputs, NamesBothFilesWhateverTheSpelling) {
  ScratchDirectory scratch("same_file_test");
  const auto log = scratch.write("a.log", "data\n");
  const auto linked = scratch.file("link.log");
  std::filesystem::create_symlink(log, linked);
  const auto other = scratch.write("b.log", "data\n");
  try {
    refuse_output_over_inputs(linked, {other, scratch.path() / "." / "a.log"});
    FAIL() << "not refused";
  } catch (const OutputIsInputError& e) {
    const std::string text = e.what();
    EXPECT_EQ(text, "cannot write " + linked.string() + ": it is the input " +
                        (scratch.path() / "." / "a.log").string() + " (the same file); write to another file");
  }
  std::filesystem::create_hard_link(log, scratch.file("hard.log"));
  EXPECT_THROW(refuse_output_over_inputs(scratch.file("hard.log"), {log}), OutputIsInputError);
}

TEST(RefuseOutputOverInputs, NewFilesStdoutAndDevicesAreNeverRefused) {
  ScratchDirectory scratch("same_file_test");
  const auto log = scratch.write("a.log", "data\n");
  EXPECT_NO_THROW(refuse_output_over_inputs(scratch.file("new.log"), {log}));
  EXPECT_NO_THROW(refuse_output_over_inputs("-", {"-", log}));
  EXPECT_NO_THROW(refuse_output_over_inputs("/dev/null", {"/dev/null"}));
  EXPECT_NO_THROW(refuse_output_over_inputs(log, {scratch.file("missing.log")}));
}

}  // namespace same_file_test
}  // namespace playerkit::files
