// The catalog on its own, with toy kinds made here: names, order, refusals
// and how options and the world reach a factory. What the real kinds accept
// is tested with their family (lib/families/<name>/<name>_family_test.cpp).

#include "emulators/catalog/emulator_catalog.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "emulators/emulator_option_reader.hpp"

namespace playerkit::emulators {
namespace emulator_catalog_test {

// A device that says nothing and keeps what its factory gave it.
class ToyDevice final : public DeviceEmulator {
 public:
  ToyDevice(std::string kind, int level, std::string label, bool loud, const EmulatorWorld& world)
      : kind_(std::move(kind)), level_(level), label_(std::move(label)), loud_(loud), world_(world) {}

  void receive(std::span<const std::uint8_t>, Duration, int) override {}
  void advance(Duration) override {}
  [[nodiscard]] Duration next_deadline() const override { return Duration::max(); }
  std::vector<Telegram> take_output() override { return {}; }
  [[nodiscard]] std::string describe() const override { return kind_ + " " + label_; }

  [[nodiscard]] const std::string& kind() const { return kind_; }
  [[nodiscard]] int level() const { return level_; }
  [[nodiscard]] const std::string& label() const { return label_; }
  [[nodiscard]] bool loud() const { return loud_; }
  [[nodiscard]] const EmulatorWorld& world() const { return world_; }

 private:
  std::string kind_;
  int level_;
  std::string label_;
  bool loud_;
  EmulatorWorld world_;
};

// A kind of toy with the options level, label and loud. Its factory refuses
// level 7 in words of its own (not naming the kind), level 8 in words that
// name it already, and level 9 with an error that is no std::invalid_argument.
EmulatorKind toy_kind(const std::string& name) {
  return {
      .name = name,
      .summary = "a toy " + name,
      .interface_name = "comms",
      .driver = name + "_driver",
      .mount = EmulatorMount::standalone,
      .options =
          {
              {"level", "3", "how loud, 0 to 9"},
              {"label", "toy", "what it calls itself"},
              {"loud", "0", "1: it shouts"},
          },
      .make =
          [name](const EmulatorOptionReader& options, const EmulatorWorld& world) {
            const int level = options.integer("level", 3, 0, 9);
            if (level == 7) throw std::invalid_argument("level 7 is unlucky");
            if (level == 8) throw std::invalid_argument(name + ": level 8 is taken");
            if (level == 9) throw std::runtime_error("level 9 broke the toy");
            return std::unique_ptr<DeviceEmulator>(std::make_unique<ToyDevice>(
                name, level, options.text("label", "toy"), options.flag("loud", false), world));
          },
  };
}

EmulatorCatalog toys() { return EmulatorCatalog({toy_kind("whistle"), toy_kind("drum"), toy_kind("bell")}); }

// The message of the std::invalid_argument `make` throws ("" when it does not).
template <class Make>
std::string refusal(Make make) {
  try {
    make();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(EmulatorCatalog, KeepsTheKindsInTheOrderGiven) {
  const auto catalog = toys();
  ASSERT_EQ(catalog.kinds().size(), 3u);
  EXPECT_EQ(catalog.kinds()[0].name, "whistle");
  EXPECT_EQ(catalog.kinds()[1].name, "drum");
  EXPECT_EQ(catalog.kinds()[2].name, "bell");
  EXPECT_EQ(catalog.names(), "whistle, drum, bell");
}

TEST(EmulatorCatalog, FindsAKindByItsWholeName) {
  const auto catalog = toys();
  ASSERT_NE(catalog.find("drum"), nullptr);
  EXPECT_EQ(catalog.find("drum"), &catalog.kinds()[1]);
  EXPECT_EQ(catalog.find("drum")->driver, "drum_driver");
  EXPECT_EQ(catalog.find("dru"), nullptr);
  EXPECT_EQ(catalog.find("drums"), nullptr);
  EXPECT_EQ(catalog.find(""), nullptr);
}

TEST(EmulatorCatalog, AnEmptyCatalogHasNone) {
  const EmulatorCatalog empty;
  EXPECT_TRUE(empty.kinds().empty());
  EXPECT_EQ(empty.names(), "none");
  EXPECT_EQ(empty.find("whistle"), nullptr);
  EXPECT_EQ(refusal([&] { (void)empty.make("whistle", {}); }), "no emulator 'whistle'; there are none");
  EXPECT_EQ(EmulatorCatalog(std::vector<EmulatorKind>{}).names(), "none");
}

TEST(EmulatorCatalog, RefusesTwoKindsOfOneName) {
  EXPECT_EQ(refusal([] { EmulatorCatalog({toy_kind("drum"), toy_kind("bell"), toy_kind("drum")}); }),
            "two emulators are named 'drum'");
}

TEST(EmulatorCatalog, RefusesAKindWithoutAFactory) {
  EmulatorKind silent = toy_kind("mute");
  silent.make = nullptr;
  EXPECT_EQ(refusal([&] { EmulatorCatalog({toy_kind("drum"), silent}); }), "emulator 'mute' has no factory");
}

TEST(EmulatorCatalog, UnknownNameListsTheNames) {
  EXPECT_EQ(refusal([] { (void)toys().make("drums", {}); }), "no emulator 'drums'; there are whistle, drum, bell");
}

TEST(EmulatorCatalog, UnknownOptionListsTheOptions) {
  EXPECT_EQ(refusal([] { (void)toys().make("bell", {{"levle", "1"}}); }),
            "bell: no option 'levle'; its options are level, label, loud");
  EXPECT_EQ(refusal([] { (void)toys().make("bell", {{"level", "1"}, {"level", "2"}}); }),
            "bell: option 'level' is given twice");
}

TEST(EmulatorCatalog, BadValuesAreRefusedByNameOnce) {
  EXPECT_EQ(refusal([] { (void)toys().make("drum", {{"level", "10"}}); }),
            "drum: level=10: expected a whole number from 0 to 9");
  EXPECT_EQ(refusal([] { (void)toys().make("drum", {{"loud", "maybe"}}); }),
            "drum: loud=maybe: expected 1 or 0 (yes/no, on/off)");
}

TEST(EmulatorCatalog, AFactorysRefusalIsPrefixedWithTheKindsNameOnce) {
  EXPECT_EQ(refusal([] { (void)toys().make("whistle", {{"level", "7"}}); }), "whistle: level 7 is unlucky");
  EXPECT_EQ(refusal([] { (void)toys().make("whistle", {{"level", "8"}}); }), "whistle: level 8 is taken");
  // Other errors pass as they are.
  EXPECT_THROW((void)toys().make("whistle", {{"level", "9"}}), std::runtime_error);
  try {
    (void)toys().make("whistle", {{"level", "9"}});
  } catch (const std::invalid_argument&) {
    ADD_FAILURE() << "became an invalid_argument";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "level 9 broke the toy");
  }
}

TEST(EmulatorCatalog, OptionValuesReachTheFactory) {
  const auto catalog = toys();
  auto made = catalog.make("drum", {{"label", "snare"}, {"level", "5"}, {"loud", "yes"}});
  ASSERT_NE(made, nullptr);
  auto& drum = dynamic_cast<ToyDevice&>(*made);
  EXPECT_EQ(drum.kind(), "drum");
  EXPECT_EQ(drum.level(), 5);
  EXPECT_EQ(drum.label(), "snare");
  EXPECT_TRUE(drum.loud());
  EXPECT_EQ(drum.describe(), "drum snare");
}

TEST(EmulatorCatalog, OptionsNotGivenAreLeftToTheFactory) {
  auto made = toys().make("bell", {});
  auto& bell = dynamic_cast<ToyDevice&>(*made);
  EXPECT_EQ(bell.kind(), "bell");
  EXPECT_EQ(bell.level(), 3);
  EXPECT_EQ(bell.label(), "toy");
  EXPECT_FALSE(bell.loud());
}

TEST(EmulatorCatalog, TheWorldReachesTheFactory) {
  const auto map = grid::OccupancyGrid::centred(10, 10, 0.1, grid::CellState::free);
  auto made = toys().make("whistle", {}, {.map = &map, .carrier_pose = [] { return geometry::Pose2{1.0, 2.0, 0.5}; }});
  const auto& whistle = dynamic_cast<ToyDevice&>(*made);
  EXPECT_EQ(whistle.world().map, &map);
  ASSERT_TRUE(whistle.world().carrier_pose);
  EXPECT_DOUBLE_EQ(whistle.world().carrier_pose().y, 2.0);
  // Without a world: no map, no carrier.
  auto alone = toys().make("whistle", {});
  EXPECT_EQ(dynamic_cast<ToyDevice&>(*alone).world().map, nullptr);
  EXPECT_FALSE(dynamic_cast<ToyDevice&>(*alone).world().carrier_pose);
}

TEST(EmulatorCatalog, ConfigExampleNamesTheInterfaceDriverAndPort) {
  EXPECT_EQ(config_example(*toys().find("bell"), "/tmp/bell"), "comms:0 ( driver \"bell_driver\" port \"/tmp/bell\" )");
}

}  // namespace emulator_catalog_test
}  // namespace playerkit::emulators
