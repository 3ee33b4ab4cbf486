#include "output_file.hpp"

#include "exit_status.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace playerkit::tools {
namespace output_file_test {

std::filesystem::path scratch_path(const std::string& name) {
  const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
  return std::filesystem::temp_directory_path() /
         (std::string("output_file_test_") + test->name() + "_" + name);
}

std::string read_whole(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(OutputFile, DashWritesToTheStandardOutputGiven) {
  std::ostringstream standard_out;
  OutputFile output("-", standard_out);
  output.stream() << "a,b\n";
  output.flush();
  EXPECT_EQ(standard_out.str(), "a,b\n");
  EXPECT_EQ(output.name(), "stdout");
}

TEST(OutputFile, APathIsReplacedOnCommitOnly) {
  const auto path = scratch_path("out.csv");
  {
    std::ofstream old(path);
    old << "old content that is longer than the new one\n";
  }
  std::ostringstream standard_out;
  {
    OutputFile output(path.string(), standard_out);
    output.stream() << "new\n";
    output.flush();
  }
  EXPECT_EQ(read_whole(path), "old content that is longer than the new one\n");
  {
    OutputFile output(path.string(), standard_out);
    output.stream() << "new\n";
    output.commit();
  }
  EXPECT_EQ(read_whole(path), "new\n");
  EXPECT_TRUE(standard_out.str().empty());
  std::filesystem::remove(path);
}

TEST(OutputFile, WritingOverAnInputIsAUsageError) {
  const auto path = scratch_path("in.log");
  std::ofstream(path) << "the input\n";
  std::ostringstream standard_out;
  const auto dotted = (path.parent_path() / "." / path.filename()).string();
  EXPECT_THROW(OutputFile(dotted, standard_out, {path.string()}), UsageError);
  EXPECT_THROW(refuse_output_over_inputs(dotted, {"other.log", path.string()}), UsageError);
  EXPECT_NO_THROW(refuse_output_over_inputs(path.string() + ".new", {path.string()}));
  EXPECT_EQ(read_whole(path), "the input\n");
  std::filesystem::remove(path);
}

TEST(OutputFile, AnUnwritablePathIsNamedInTheError) {
  std::ostringstream standard_out;
  const std::string path = "/nonexistent-directory/out.csv";
  try {
    OutputFile output(path, standard_out);
    FAIL() << "opened " << path;
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot write /nonexistent-directory/out.csv: "), std::string::npos)
        << e.what();
  }
}

TEST(OutputFile, AFailedWriteIsReportedByFlush) {
  std::ostringstream standard_out;
  OutputFile output("-", standard_out);
  output.stream() << "partial";
  standard_out.setstate(std::ios::badbit);  // what a full disk or a closed pipe leaves behind
  EXPECT_THROW(output.flush(), std::runtime_error);
}

}  // namespace output_file_test
}  // namespace playerkit::tools
