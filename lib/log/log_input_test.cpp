#include "log/log_input.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>
#include <zlib.h>

#include "files/output_file.hpp"

namespace playerkit::log {
namespace log_input_test {

class LogInputTest : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ = std::filesystem::temp_directory_path() /
                 ("log_input_test_" + std::to_string(::getpid()) + "_" +
                  ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(directory_);
  }
  void TearDown() override { std::filesystem::remove_all(directory_); }

  std::filesystem::path write_plain(const std::string& name, const std::string& text) {
    const auto path = directory_ / name;
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }
  std::filesystem::path write_gzip(const std::string& name, const std::string& text) {
    const auto path = directory_ / name;
    gzFile file = gzopen(path.c_str(), "wb");
    gzwrite(file, text.data(), static_cast<unsigned>(text.size()));
    gzclose(file);
    return path;
  }
  static std::string read_all(LogInput& in) {
    std::string all;
    for (std::string line; std::getline(in, line);) all += line + "\n";
    return all;
  }

  std::filesystem::path directory_;
};

// Many lines, longer together than one 64 KiB block.
std::string many_lines() {
  std::string text;
  for (int i = 0; i < 20000; ++i) text += "line " + std::to_string(i) + "\n";
  return text;
}

TEST_F(LogInputTest, ReadsAPlainFile) {
  const auto text = many_lines();
  auto in = open_log_input(write_plain("plain.log", text));
  EXPECT_EQ(read_all(*in), text);
  EXPECT_FALSE(in->error());
}

TEST_F(LogInputTest, ReadsAGzipFileWhateverItsName) {
  const auto text = many_lines();
  auto in = open_log_input(write_gzip("compressed.log", text));
  EXPECT_EQ(read_all(*in), text);
  EXPECT_FALSE(in->error());
}

TEST_F(LogInputTest, ATruncatedGzipFileReadsUpToTheDamageAndSaysSo) {
  const auto text = many_lines();
  const auto whole = write_gzip("whole.log.gz", text);
  std::ifstream source(whole, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(source)), std::istreambuf_iterator<char>());
  const auto cut = write_plain("cut.log.gz", bytes.substr(0, bytes.size() / 2));
  auto in = open_log_input(cut);
  const std::string read = read_all(*in);
  EXPECT_LT(read.size(), text.size());
  EXPECT_EQ(text.compare(0, read.size() - 1, read, 0, read.size() - 1), 0);  // a true prefix
  ASSERT_TRUE(in->error());
}

std::string bytes_of(const std::filesystem::path& path) {
  std::ifstream source(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(source), std::istreambuf_iterator<char>()};
}

TEST_F(LogInputTest, ATruncatedGzipFileNamesTheByteAndLineAndKeepsWholeLines) {
  const auto text = many_lines();
  const std::string bytes = bytes_of(write_gzip("whole.log.gz", text));
  const std::size_t cut_at = bytes.size() / 2;
  auto in = open_log_input(write_plain("cut.log.gz", bytes.substr(0, cut_at)));
  const std::string read = read_all(*in);
  ASSERT_FALSE(read.empty());
  EXPECT_EQ(text.compare(0, read.size(), read), 0);  // whole lines of the original, nothing torn
  const auto lines_read = static_cast<std::size_t>(std::count(read.begin(), read.end(), '\n'));
  ASSERT_TRUE(in->error());
  EXPECT_EQ(*in->error(), "gzip data cut short: the file ends at byte " + std::to_string(cut_at) + ", in line " +
                              std::to_string(lines_read + 1));
}

TEST_F(LogInputTest, CorruptGzipDataNamesTheByteAndLineWhereDecodingFailed) {
  const auto text = many_lines();
  // Level 0: stored blocks, whose headers sit at known places. The gzip
  // header is 10 bytes; a stored block is 1 byte of type, LEN and NLEN (2
  // bytes each, NLEN = ~LEN), then LEN bytes of text.
  const auto path = directory_ / "stored.log.gz";
  gzFile file = gzopen(path.c_str(), "wb0");
  gzwrite(file, text.data(), static_cast<unsigned>(text.size()));
  gzclose(file);
  std::string bytes = bytes_of(path);
  const auto first_length = static_cast<std::size_t>(static_cast<unsigned char>(bytes[11]) |
                                                     static_cast<unsigned char>(bytes[12]) << 8);
  ASSERT_LT(first_length, text.size());  // there is a second block
  const std::size_t second_header = 10 + 5 + first_length;
  bytes[second_header + 3] = static_cast<char>(bytes[second_header + 3] ^ 0x01);  // its NLEN no longer matches LEN
  auto in = open_log_input(write_plain("damaged.log.gz", bytes));
  const std::string read = read_all(*in);
  const std::string first_block = text.substr(0, first_length);
  EXPECT_EQ(read, first_block.substr(0, first_block.rfind('\n') + 1));  // its whole lines
  ASSERT_TRUE(in->error());
  EXPECT_EQ(*in->error(), "corrupt gzip data at byte " + std::to_string(second_header + 5) + ", in line " +
                              std::to_string(std::count(read.begin(), read.end(), '\n') + 1) +
                              ": invalid stored block lengths");
}

TEST_F(LogInputTest, ConcatenatedGzipMembersAreReadInTurnAndTrailingBytesIgnored) {
  const std::string first = bytes_of(write_gzip("a.gz", "first line\n"));
  const std::string second = bytes_of(write_gzip("b.gz", "second line\nno newline"));
  auto in = open_log_input(write_plain("both.gz", first + second + "\n\n(trailing junk)"));
  EXPECT_EQ(read_all(*in), "first line\nsecond line\nno newline\n");
  EXPECT_FALSE(in->error());
}

TEST_F(LogInputTest, AGzipFileWrittenByTheOutputFileReadsBack) {
  const auto text = many_lines();
  const auto path = directory_ / "written.log.gz";
  {
    files::OutputFile output(path);
    ASSERT_TRUE(output.compressed());
    output.stream() << text;
    output.commit();
  }
  EXPECT_TRUE(bytes_of(path).starts_with("\x1f\x8b"));
  auto in = open_log_input(path);
  EXPECT_EQ(read_all(*in), text);
  EXPECT_FALSE(in->error());
}

TEST_F(LogInputTest, AMissingFileIsAClearError) {
  try {
    open_log_input(directory_ / "absent.log");
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot open"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("absent.log"), std::string::npos) << e.what();
  }
  EXPECT_THROW(open_log_input(directory_), std::runtime_error);
}

}  // namespace log_input_test
}  // namespace playerkit::log
