#include "eval_options.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "support/scratch_directory.hpp"

namespace playerkit::amcl_offline {
namespace eval_options_test {

EvalCommand command_of(std::vector<std::string> estimates, std::vector<std::string> truths) {
  EvalCommand command;
  command.estimates = std::move(estimates);
  command.truths = std::move(truths);
  return command;
}

std::string usage_error(const EvalCommand& command) {
  try {
    (void)make_eval_options(command);
  } catch (const tools::UsageError& e) {
    return e.what();
  }
  return "no error";
}

TEST(EvalOptions, OneEstimateIsOneRunInText) {
  const EvalOptions options = make_eval_options(command_of({"est.csv"}, {"intel.log.gz"}));
  ASSERT_EQ(options.runs.size(), 1u);
  EXPECT_EQ(options.runs[0].estimate, "est.csv");
  EXPECT_EQ(options.runs[0].truth, "intel.log.gz");
  EXPECT_EQ(options.format, EvalFormat::text);
}

TEST(EvalOptions, FormatsAndTheJsonFlag) {
  EvalCommand command = command_of({"est.csv"}, {"t.csv"});
  command.format = "markdown";
  EXPECT_EQ(make_eval_options(command).format, EvalFormat::markdown);
  command.format = "md";
  EXPECT_EQ(make_eval_options(command).format, EvalFormat::markdown);
  command.format = "xml";
  EXPECT_EQ(usage_error(command), "--format: 'xml' is not text, markdown or json");
  command.format = "";
  command.json = true;
  EXPECT_EQ(make_eval_options(command).format, EvalFormat::json);
  command.format = "markdown";
  EXPECT_EQ(usage_error(command), "--json and --format markdown exclude each other");
}

TEST(EvalOptions, OneTruthServesEveryEstimateOrOneEachPairsInOrder) {
  const EvalOptions shared = make_eval_options(command_of({"a.csv", "b.csv"}, {"t.log"}));
  ASSERT_EQ(shared.runs.size(), 2u);
  EXPECT_EQ(shared.runs[1].estimate, "b.csv");
  EXPECT_EQ(shared.runs[1].truth, "t.log");
  const EvalOptions paired = make_eval_options(command_of({"a.csv", "b.csv"}, {"ta.log", "tb.log"}));
  EXPECT_EQ(paired.runs[0].truth, "ta.log");
  EXPECT_EQ(paired.runs[1].truth, "tb.log");
  EXPECT_EQ(usage_error(command_of({"a.csv", "b.csv", "c.csv"}, {"ta.log", "tb.log"})),
            "--truth: give one for every estimate, or one for all (3 estimates, 2 truths)");
}

TEST(EvalOptions, ADirectoryStandsForItsCsvFilesInNameOrder) {
  playerkit::testing::ScratchDirectory scratch("eval_options_test");
  std::filesystem::create_directory(scratch.file("runs"));
  for (const char* name : {"seed-2.csv", "seed-10.csv", "seed-1.csv", "notes.txt"}) {
    scratch.write(std::string("runs/") + name, "time,x,y,yaw\n");
  }
  const EvalOptions options = make_eval_options(command_of({scratch.file("runs").string()}, {"t.log"}));
  ASSERT_EQ(options.runs.size(), 3u);
  EXPECT_EQ(options.runs[0].estimate, scratch.file("runs/seed-1.csv").string());
  EXPECT_EQ(options.runs[1].estimate, scratch.file("runs/seed-10.csv").string());
  EXPECT_EQ(options.runs[2].estimate, scratch.file("runs/seed-2.csv").string());

  std::filesystem::create_directory(scratch.file("empty"));
  EXPECT_EQ(usage_error(command_of({scratch.file("empty").string()}, {"t.log"})),
            scratch.file("empty").string() + ": a directory without .csv estimates");
}

}  // namespace eval_options_test
}  // namespace playerkit::amcl_offline
