#include "log/log_input.hpp"

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>
#include <zlib.h>

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
