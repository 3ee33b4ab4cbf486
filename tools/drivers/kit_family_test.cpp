// A family registered at run time (echo_family_test_support.hpp) is known to
// every subcommand of player-drivers: no file outside the family names it.

#include <gtest/gtest.h>
#include <unistd.h>

#include <sstream>

#include "driver_listing.hpp"
#include "echo_family_test_support.hpp"
#include "emulate_options.hpp"
#include "emulate_session.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "families/builtin_families.hpp"
#include "families/port_probe.hpp"
#include "help_text.hpp"
#include "known_drivers.hpp"
#include "run_options.hpp"
#include "run_session.hpp"

namespace playerkit::player_drivers {
namespace kit_family_test {

// The built-in families and the echo family after them.
families::FamilyRegistry with_echo() {
  families::FamilyRegistry registry;
  families::register_builtin_families(registry);
  registry.add(echo_family_test_support::echo_family());
  return registry;
}

core::DriverRegistry drivers_of(const families::FamilyRegistry& registry) {
  core::Logger logger("test");
  logger.set_level(core::LogLevel::kError);
  return known_drivers({}, registry, logger);
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(KitFamily, ListAndInfoKnowItsDriver) {
  const auto registry = with_echo();
  std::ostringstream list;
  write_driver_list(drivers_of(registry), {}, list);
  EXPECT_TRUE(contains(list.str(), "echoline")) << list.str();
  std::ostringstream info;
  write_driver_info(drivers_of(registry), "echoline", false, info);
  EXPECT_TRUE(contains(info.str(), "an echo box on a serial line")) << info.str();
  // Without the family its driver is unknown.
  std::ostringstream builtin;
  write_driver_list(drivers_of(families::builtin_families()), {}, builtin);
  EXPECT_FALSE(contains(builtin.str(), "echoline"));
}

TEST(KitFamily, HelpNamesItsProbeEmulatorAndExamples) {
  const auto registry = with_echo();
  EXPECT_TRUE(contains(probe_footer(registry), "ECHO (echo): 9600 baud")) << probe_footer(registry);
  EXPECT_TRUE(contains(emulate_footer(registry), "  echobox ")) << emulate_footer(registry);
  EXPECT_TRUE(contains(emulate_footer(registry), " an echo box that greets and repeats lines\n"));
  EXPECT_TRUE(contains(main_footer(registry), "player-drivers emulate echobox greeting=hi")) << main_footer(registry);
  EXPECT_FALSE(contains(emulate_footer(families::builtin_families()), "echobox"));
}

TEST(KitFamily, ProbeFindsItsEmulatorAmongTheBuiltInFamilies) {
  const auto registry = with_echo();
  emulators::EmulatorRunner box(registry.emulator_catalog().make("echobox", {{"greeting", "hi"}}),
                                emulators::PtyEndpoint{});
  const auto result = families::probe_port(box.device_path(), registry, {}, [] { return false; });
  ASSERT_TRUE(result.found) << result.problem;
  EXPECT_EQ(result.found->driver, "echoline");
  EXPECT_EQ(result.found->model, "echo-box hi");
  EXPECT_EQ(result.baud, 9600);
  EXPECT_EQ(result.config_line, "comms:0 ( driver \"echoline\" port \"" + box.device_path() + "\" )");
}

TEST(KitFamily, EmulateRunsItWithItsOptions) {
  const auto registry = with_echo();
  const auto catalog = registry.emulator_catalog();
  EmulateCommandLine line;
  line.words = {"echobox", "greeting=hi"};
  line.duration = 0.2;
  const auto options = make_emulate_options(line, catalog);
  std::ostringstream out, err;
  EXPECT_EQ(run_emulators(options, catalog, out, err, [] { return false; }), kExitOk) << err.str();
  EXPECT_TRUE(contains(out.str(), "echobox on /dev/pts/")) << out.str();
  EXPECT_TRUE(contains(out.str(), "comms:0 ( driver \"echoline\" port \"/dev/pts/")) << out.str();
  line.words = {"echobox", "greting=hi"};
  std::ostringstream refused;
  EXPECT_EQ(run_emulators(make_emulate_options(line, catalog), catalog, out, refused, [] { return false; }),
            kExitUsage);
  EXPECT_TRUE(contains(refused.str(), "echobox: no option 'greting'")) << refused.str();
}

TEST(KitFamily, RunTracesItsLinesWithItsFraming) {
  const auto registry = with_echo();
  emulators::EmulatorRunner box(registry.emulator_catalog().make("echobox", {}), emulators::PtyEndpoint{});
  int input[2];
  ASSERT_EQ(::pipe(input), 0);
  const std::string command = "{\"device\":\"comms:0\",\"type\":\"cmd\",\"data\":{\"msg\":[104,105]}}\n";
  ASSERT_EQ(::write(input[1], command.data(), command.size()), static_cast<ssize_t>(command.size()));
  ::close(input[1]);
  RunCommandLine line;
  line.words = {"echoline", "port=" + box.device_path()};
  line.from_stdin = true;
  line.trace = true;
  line.count = 1;
  line.timeout = 10;
  std::ostringstream out, err;
  const int status = run_driver(make_run_options(line), registry, {out, err, input[0]}, [] { return false; });
  ::close(input[0]);
  EXPECT_EQ(status, kExitOk) << err.str();
  // "SAY hi\n" out and "hi\n" back, each a whole telegram of the echo framing.
  EXPECT_TRUE(contains(err.str(), "> 53 41 59 20 68 69 0A\n")) << err.str();
  EXPECT_TRUE(contains(err.str(), "< 68 69 0A\n")) << err.str();
}

}  // namespace kit_family_test
}  // namespace playerkit::player_drivers
