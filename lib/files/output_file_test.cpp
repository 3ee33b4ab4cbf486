#include "files/output_file.hpp"

#include <gtest/gtest.h>

#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <zlib.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/scratch_directory.hpp"

namespace playerkit::files {
namespace output_file_test {

using testing::ScratchDirectory;

std::string read_whole(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Every entry of the directory, by name: what a writer left behind.
std::vector<std::string> entries(const std::filesystem::path& directory) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(directory)) {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

// zlib's own decoder, not ours: what any gzip reader makes of the bytes.
std::string gunzip(const std::string& compressed, int flush = Z_NO_FLUSH) {
  z_stream z{};
  EXPECT_EQ(inflateInit2(&z, 15 + 16), Z_OK);
  std::string text;
  std::vector<char> block(1 << 16);
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(compressed.data()));
  z.avail_in = static_cast<uInt>(compressed.size());
  int result = Z_OK;
  do {
    z.next_out = reinterpret_cast<Bytef*>(block.data());
    z.avail_out = static_cast<uInt>(block.size());
    result = inflate(&z, flush);
    text.append(block.data(), block.size() - z.avail_out);
  } while (result == Z_OK && (z.avail_in > 0 || z.avail_out == 0));
  inflateEnd(&z);
  return text;
}

TEST(OutputFile, CommitRenamesTheTemporaryIntoPlace) {
  ScratchDirectory scratch("output_file_test");
  const auto path = scratch.write("out.log", "previous content, longer than the new one\n");
  OutputFile output(path);
  ASSERT_FALSE(output.temporary().empty());
  EXPECT_EQ(output.temporary().parent_path(), path.parent_path());
  EXPECT_TRUE(output.temporary().filename().string().starts_with("out.log.tmp-"));
  output.stream() << "new\n";
  output.flush();
  // Until commit the previous file is what readers see.
  EXPECT_EQ(read_whole(path), "previous content, longer than the new one\n");
  EXPECT_EQ(read_whole(output.temporary()), "new\n");
  output.commit();
  EXPECT_TRUE(output.committed());
  EXPECT_EQ(read_whole(path), "new\n");
  EXPECT_EQ(entries(scratch.path()), std::vector<std::string>{"out.log"});
}

TEST(OutputFile, WithoutCommitTheTemporaryGoesAndThePreviousFileStays) {
  ScratchDirectory scratch("output_file_test");
  const auto path = scratch.write("out.log", "previous\n");
  try {
    OutputFile output(path);
    output.stream() << "half of the new";
    output.flush();
    throw std::runtime_error("the work failed half-way");
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(read_whole(path), "previous\n");
  EXPECT_EQ(entries(scratch.path()), std::vector<std::string>{"out.log"});
}

TEST(OutputFile, ANewFileAppearsOnlyOnCommit) {
  ScratchDirectory scratch("output_file_test");
  const auto path = scratch.file("new.log");
  {
    OutputFile output(path);
    output.stream() << "data\n";
    EXPECT_FALSE(std::filesystem::exists(path));
  }
  EXPECT_TRUE(entries(scratch.path()).empty());
}

TEST(OutputFile, RefusesItsInputBeforeWritingAnything) {
  ScratchDirectory scratch("output_file_test");
  const auto log = scratch.write("a.log", "the only copy\n");
  std::filesystem::create_symlink(log, scratch.file("link.log"));
  std::filesystem::create_hard_link(log, scratch.file("hard.log"));
  const std::vector<std::filesystem::path> spellings{scratch.path() / "." / "a.log", scratch.file("link.log"),
                                                     scratch.file("hard.log")};
  for (const auto& output : spellings) {
    EXPECT_THROW(OutputFile(output, {.inputs = {log}}), OutputIsInputError) << output;
  }
  EXPECT_EQ(read_whole(log), "the only copy\n");
  EXPECT_EQ(entries(scratch.path()), (std::vector<std::string>{"a.log", "hard.log", "link.log"}));
}

TEST(OutputFile, DashWritesToTheStandardOutputGiven) {
  std::ostringstream standard_out;
  OutputFile output("-", {.inputs = {"-"}, .standard_out = &standard_out});
  output.stream() << "a,b\n";
  output.commit();
  EXPECT_EQ(standard_out.str(), "a,b\n");
  EXPECT_EQ(output.name(), "stdout");
  EXPECT_TRUE(output.temporary().empty());
  EXPECT_FALSE(output.compressed());
}

TEST(OutputFile, AFailedWriteToStdoutIsReported) {
  std::ostringstream standard_out;
  OutputFile output("-", {.standard_out = &standard_out});
  standard_out.setstate(std::ios::badbit);  // what a closed pipe leaves behind
  EXPECT_THROW(output.flush(), OutputError);
}

TEST(OutputFile, ADotGzNameIsWrittenGzipCompressed) {
  ScratchDirectory scratch("output_file_test");
  const auto path = scratch.file("run.log.gz");
  std::string text;
  for (int i = 0; i < 5000; ++i) text += "0000001000." + std::to_string(i) + " 16 laser 00 ...\n";
  {
    OutputFile output(path);
    EXPECT_TRUE(output.compressed());
    output.stream() << text;
    output.commit();
  }
  const auto bytes = read_whole(path);
  ASSERT_GE(bytes.size(), 2U);
  EXPECT_EQ(static_cast<unsigned char>(bytes[0]), 0x1f);
  EXPECT_EQ(static_cast<unsigned char>(bytes[1]), 0x8b);
  EXPECT_LT(bytes.size(), text.size() / 4);
  EXPECT_EQ(gunzip(bytes), text);
}

TEST(OutputFile, CompressionCanBeChosenAgainstTheName) {
  ScratchDirectory scratch("output_file_test");
  const auto plain = scratch.file("keep.gz");
  {
    OutputFile output(plain, {.compression = Compression::kNone});
    output.stream() << "plain\n";
    output.commit();
  }
  EXPECT_EQ(read_whole(plain), "plain\n");
}

TEST(OutputFile, AStreamingFileShowsItsDataAsItGoesAndKeepsItWithoutCommit) {
  ScratchDirectory scratch("output_file_test");
  const auto path = scratch.write("rec.log", "an older recording\n");
  {
    OutputFile output(path, {.mode = WriteMode::kStreaming});
    EXPECT_TRUE(output.temporary().empty());
    output.stream() << "line 1\n";
    output.flush();
    EXPECT_EQ(read_whole(path), "line 1\n");
    output.stream() << "line 2\n";
  }
  EXPECT_EQ(read_whole(path), "line 1\nline 2\n");
  EXPECT_EQ(entries(scratch.path()), std::vector<std::string>{"rec.log"});
}

TEST(OutputFile, AStreamingGzipFileIsReadableAtEachFlushAndWholeAtTheEnd) {
  ScratchDirectory scratch("output_file_test");
  const auto path = scratch.file("rec.log.gz");
  {
    OutputFile output(path, {.mode = WriteMode::kStreaming});
    output.stream() << "line 1\n";
    output.flush();
    // A reader tolerant of the missing end (zcat prints it, then complains).
    EXPECT_EQ(gunzip(read_whole(path), Z_SYNC_FLUSH), "line 1\n");
    output.stream() << "line 2\n";
  }
  EXPECT_EQ(gunzip(read_whole(path)), "line 1\nline 2\n");
}

TEST(OutputFile, ASymlinkedOutputStaysALink) {
  ScratchDirectory scratch("output_file_test");
  const auto target = scratch.write("target.log", "old\n");
  const auto link = scratch.file("link.log");
  std::filesystem::create_symlink(target, link);
  {
    OutputFile output(link);
    EXPECT_EQ(output.temporary().parent_path(), target.parent_path());
    output.stream() << "new\n";
    output.commit();
  }
  EXPECT_TRUE(std::filesystem::is_symlink(link));
  EXPECT_EQ(read_whole(target), "new\n");
}

TEST(OutputFile, TheReplacedFileKeepsItsModeAndANewOneFollowsTheUmask) {
  ScratchDirectory scratch("output_file_test");
  const auto existing = scratch.write("script.sh", "old\n");
  std::filesystem::permissions(existing, std::filesystem::perms(0750));
  {
    OutputFile output(existing);
    output.stream() << "new\n";
    output.commit();
  }
  EXPECT_EQ(std::filesystem::status(existing).permissions(), std::filesystem::perms(0750));

  const mode_t mask = ::umask(027);
  const auto created = scratch.file("new.log");
  {
    OutputFile output(created);
    output.commit();
  }
  ::umask(mask);
  EXPECT_EQ(std::filesystem::status(created).permissions(), std::filesystem::perms(0640));
}

TEST(OutputFile, AReadOnlyFileIsNotReplaced) {
  if (::geteuid() == 0) GTEST_SKIP() << "root may write any file";
  ScratchDirectory scratch("output_file_test");
  const auto path = scratch.write("ro.log", "keep\n");
  std::filesystem::permissions(path, std::filesystem::perms(0444));
  EXPECT_THROW(OutputFile{path}, OutputError);
  EXPECT_EQ(read_whole(path), "keep\n");
}

TEST(OutputFile, ADeviceIsWrittenDirectly) {
  OutputFile output("/dev/null");
  EXPECT_TRUE(output.temporary().empty());
  output.stream() << "nothing\n";
  EXPECT_NO_THROW(output.commit());
}

TEST(OutputFile, UnwritablePlacesAreNamedInTheError) {
  ScratchDirectory scratch("output_file_test");
  try {
    OutputFile output("/nonexistent-directory/out.csv");
    FAIL() << "opened";
  } catch (const OutputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "cannot write /nonexistent-directory/out.csv: cannot create a temporary file beside it: "
              "No such file or directory");
  }
  try {
    OutputFile output(scratch.path());
    FAIL() << "opened";
  } catch (const OutputError& e) {
    EXPECT_EQ(std::string(e.what()), "cannot write " + scratch.path().string() + ": it is a directory");
  }
}

TEST(OutputFile, AFatalSignalRemovesTheTemporary) {
  ScratchDirectory scratch("output_file_test");
  const auto path = scratch.write("out.log", "previous\n");
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    OutputFile output(path);
    output.stream() << "half";
    output.flush();
    ::raise(SIGTERM);
    ::_exit(0);  // not reached
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status));
  EXPECT_EQ(WTERMSIG(status), SIGTERM);
  EXPECT_EQ(read_whole(path), "previous\n");
  EXPECT_EQ(entries(scratch.path()), std::vector<std::string>{"out.log"});
}

}  // namespace output_file_test
}  // namespace playerkit::files
