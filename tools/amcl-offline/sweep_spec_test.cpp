#include "sweep_spec.hpp"

#include <gtest/gtest.h>

#include "exit_status.hpp"

namespace playerkit::amcl_offline {
namespace sweep_spec_test {

SweepSpec parse(const std::string& text) { return parse_sweep_spec(text, "spec.json", "/data/sweep"); }

// The message of the UsageError `text` gives.
std::string error_of(const std::string& text) {
  try {
    parse(text);
  } catch (const tools::UsageError& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted: " << text;
  return "";
}

TEST(SweepSpec, AFullSpecIsRead) {
  const SweepSpec spec = parse(R"({
    "logs": [{"name": "orebro", "log": "orebro.log.gz", "map": "maps/orebro.yaml", "perturb_seed": 1},
             {"log": "/logs/csail-corrected.log.gz", "map": "cave.pnm", "truth": "csail.csv",
              "scale": 0.03, "negate": true, "origin": "0,0", "start": "global"}],
    "start": "truth",
    "parameters": {"--sigma-hit": [0.1, 0.2], "particles": ["100,5000", "500,5000"], "every-reading": [true, false]},
    "seeds": [3, 1]
  })");
  ASSERT_EQ(spec.logs.size(), 2U);
  EXPECT_EQ(spec.logs[0].name, "orebro");
  EXPECT_EQ(spec.logs[0].log, "/data/sweep/orebro.log.gz");
  EXPECT_EQ(spec.logs[0].map, "/data/sweep/maps/orebro.yaml");
  EXPECT_EQ(spec.logs[0].truth, "/data/sweep/orebro.log.gz");  // the log itself by default
  EXPECT_EQ(spec.logs[0].perturb_seed, 1U);
  EXPECT_EQ(spec.logs[0].start, SweepStart::truth);
  EXPECT_FALSE(spec.logs[0].scale);
  EXPECT_EQ(spec.logs[1].name, "csail-corrected");  // the file's name up to its first '.'
  EXPECT_EQ(spec.logs[1].log, "/logs/csail-corrected.log.gz");
  EXPECT_EQ(spec.logs[1].truth, "/data/sweep/csail.csv");
  EXPECT_EQ(spec.logs[1].scale, 0.03);
  EXPECT_TRUE(spec.logs[1].negate);
  EXPECT_EQ(spec.logs[1].origin, "0,0");
  EXPECT_FALSE(spec.logs[1].perturb_seed);
  EXPECT_EQ(spec.logs[1].start, SweepStart::global);
  // The spec's order, not alphabetical; dashes dropped; numbers as JSON writes them.
  ASSERT_EQ(spec.parameters.size(), 3U);
  EXPECT_EQ(spec.parameters[0].name, "sigma-hit");
  EXPECT_EQ(spec.parameters[0].values, (std::vector<std::string>{"0.1", "0.2"}));
  EXPECT_EQ(spec.parameters[1].name, "particles");
  EXPECT_EQ(spec.parameters[1].values, (std::vector<std::string>{"100,5000", "500,5000"}));
  EXPECT_EQ(spec.parameters[2].values, (std::vector<std::string>{"true", "false"}));
  EXPECT_EQ(spec.seeds, (std::vector<std::uint64_t>{3, 1}));
}

TEST(SweepSpec, ParametersAndSeedsMayBeLeftOut) {
  const SweepSpec spec = parse(R"({"logs": [{"log": "a.log", "map": "a.yaml"}], "start": "global"})");
  EXPECT_TRUE(spec.parameters.empty());
  EXPECT_EQ(spec.seeds, (std::vector<std::uint64_t>{0}));  // localize's default
  EXPECT_EQ(spec.logs[0].start, SweepStart::global);
  EXPECT_EQ(spec.logs[0].name, "a");
}

TEST(SweepSpec, SyntaxErrorsGiveLineAndColumn) {
  const std::string message = error_of("{\n  \"logs\": [\n    {\"log\": \"a\",, }\n  ]\n}");
  EXPECT_EQ(message.rfind("spec.json:3:17: ", 0), 0U) << message;
  EXPECT_NE(error_of("").find("spec.json:1:1: "), std::string::npos);
}

TEST(SweepSpec, FieldErrorsNameTheField) {
  const std::string good_log = R"({"log": "a.log", "map": "a.yaml"})";
  const auto with = [&](const std::string& rest) { return R"({"logs": [)" + good_log + "]" + rest + "}"; };
  EXPECT_EQ(error_of("[]"), "spec.json: (top): must be an object with logs, parameters and seeds");
  EXPECT_EQ(error_of(R"({"logs": []})"), "spec.json: logs: must be a non-empty list");
  EXPECT_EQ(error_of(R"({"logs": [{"map": "a.yaml"}]})"), "spec.json: logs[0].log: missing");
  EXPECT_EQ(error_of(R"({"logs": [{"log": "a.log"}]})"), "spec.json: logs[0].map: missing");
  EXPECT_EQ(error_of(R"({"logs": [{"log": "a.log", "map": "a.yaml", "maps": 1}]})"), "spec.json: logs[0].maps: unknown field");
  EXPECT_EQ(error_of(R"({"logs": [{"log": "", "map": "a.yaml"}]})"), "spec.json: logs[0].log: must be a non-empty string");
  EXPECT_EQ(error_of(R"({"logs": [{"log": "a.log", "map": "a.yaml", "scale": "0.05"}]})"),
            "spec.json: logs[0].scale: must be a number (metres per pixel)");
  EXPECT_EQ(error_of(R"({"logs": [{"log": "a.log", "map": "a.yaml", "perturb_seed": -1}]})"),
            "spec.json: logs[0].perturb_seed: must be a non-negative integer");
  EXPECT_EQ(error_of(R"({"logs": [{"log": "a.log", "map": "a.yaml", "name": "a_b"}]})"),
            "spec.json: logs[0].name: \"a_b\": only letters, digits, '-' and '.' (it names files)");
  EXPECT_EQ(error_of(R"({"logs": [{"log": "a.log", "map": "a.yaml"}, {"log": "b/a.log.gz", "map": "b.yaml"}]})"),
            "spec.json: logs[1].name: \"a\" is also logs[0]'s name");
  EXPECT_EQ(error_of(with(R"(, "start": "anywhere")")), "spec.json: start: must be \"truth\" or \"global\", not \"anywhere\"");
  EXPECT_EQ(error_of(with(R"(, "seed": [1])")), "spec.json: (top).seed: unknown field");
  EXPECT_EQ(error_of(with(R"(, "seeds": [])")), "spec.json: seeds: must be a non-empty list of integers");
  EXPECT_EQ(error_of(with(R"(, "seeds": [1, 1.5])")), "spec.json: seeds[1]: must be a non-negative integer");
  EXPECT_EQ(error_of(with(R"(, "seeds": [2, 2])")), "spec.json: seeds[1]: repeats 2");
  EXPECT_EQ(error_of(with(R"(, "parameters": [])")), "spec.json: parameters: must be an object: flag name -> list of values");
  EXPECT_EQ(error_of(with(R"(, "parameters": {"particles": []})")), "spec.json: parameters.particles: must be a non-empty list of values");
  EXPECT_EQ(error_of(with(R"(, "parameters": {"particles": "100,5000"})")), "spec.json: parameters.particles: must be a non-empty list of values");
  EXPECT_EQ(error_of(with(R"(, "parameters": {"sigma-hit": [0.1, null]})")), "spec.json: parameters.sigma-hit[1]: must be a number or a string");
  EXPECT_EQ(error_of(with(R"(, "parameters": {"sigma-hit": [0.1, 0.1]})")), "spec.json: parameters.sigma-hit[1]: repeats 0.1");
  EXPECT_EQ(error_of(with(R"(, "parameters": {"every-reading": [1]})")),
            "spec.json: parameters.every-reading[0]: must be true or false (--every-reading is a flag)");
  EXPECT_EQ(error_of(with(R"(, "parameters": {"sigma-hit": [0.1], "--sigma-hit": [0.2]})")), "spec.json: parameters.--sigma-hit: given twice");
  // The sweep sets these itself.
  for (const char* owned : {"seed", "map", "global", "init-pose", "output", "plot"}) {
    const std::string message = error_of(with(R"(, "parameters": {")" + std::string(owned) + R"(": [1]})"));
    EXPECT_EQ(message.rfind("spec.json: parameters." + std::string(owned) + ": not a localize flag a sweep may vary (particles, ", 0), 0U)
        << message;
  }
}

}  // namespace sweep_spec_test
}  // namespace playerkit::amcl_offline
