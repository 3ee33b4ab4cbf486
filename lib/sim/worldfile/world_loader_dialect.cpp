#include "sim/worldfile/world_loader_dialect.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <string_view>

#include "sim/worldfile/worldfile_error.hpp"

namespace playerkit::sim::worldfile {
namespace {

constexpr std::array<std::string_view, 17> kStage13OnlyTypes = {
    "bitmap", "gui",  "ptz",   "fiducialfinder", "lbd",  "vision", "truth", "sonar", "box",
    "puck",   "omniposition", "power", "broadcast",      "mcom", "idar",   "idarturret", "host"};
constexpr std::array<std::string_view, 10> kStage4OnlyTypes = {
    "block", "window", "sensor", "model", "ranger", "fiducial", "camera", "actuator", "blinkenlight",
    "lightindicator"};

struct Clue {
  std::string what;
  SourceLocation where;
};

class DialectClues {
 public:
  void world(const Entity& world) {
    for (const Property& property : world.properties) {
      if (property.name == "sim_timestep" || property.name == "real_timestep") note(stage13_, property);
      if (property.name == "interval_sim") note(stage4_, property);
    }
    for (const Entity& child : world.children) entity(child);
  }

  [[nodiscard]] Dialect decide() const {
    if (stage13_ && stage4_) {
      throw WorldFileError(stage4_->where, "this world mixes Stage 1.3 (" + stage13_->what + " at " +
                                               to_string(stage13_->where) + ") and Stage 3/4 (" + stage4_->what +
                                               " here) syntax");
    }
    if (stage13_) return Dialect::stage13;
    if (stage4_) return stage3_ && !sensor_ ? Dialect::stage3 : Dialect::stage4;
    return Dialect::stage13;
  }

 private:
  static void note(std::optional<Clue>& clue, const Property& property) {
    if (!clue) clue = Clue{"a " + property.name + " property", property.where};
  }
  static void note(std::optional<Clue>& clue, const Entity& entity, const std::string& what) {
    if (!clue) clue = Clue{what, entity.where};
  }

  void entity(const Entity& entity) {
    const auto is = [&](const auto& types) {
      return std::find(types.begin(), types.end(), entity.type) != types.end();
    };
    if (entity.type == "gui") {
      note(stage13_, entity, "a gui entity");
      return;  // its size and origin are not a model's
    }
    if (is(kStage13OnlyTypes)) note(stage13_, entity, "a " + entity.type + " entity");
    if (is(kStage4OnlyTypes)) note(stage4_, entity, "a " + entity.type + " entity");
    if (std::find(entity.macros.begin(), entity.macros.end(), "floorplan") != entity.macros.end()) {
      note(stage4_, entity, "a floorplan");
    }
    if (entity.type == "sensor") sensor_ = true;
    if (entity.type == "laser" || (entity.type == "ranger" && entity.find("scount") != nullptr)) stage3_ = true;
    for (const Property& property : entity.properties) {
      if (property.name == "port") note(stage13_, property);
      if (property.name == "bitmap") note(stage4_, property);
      if (property.name == "pose" && property.values.size() == 4 && !stage4_) {
        stage4_ = Clue{"a 4-element pose", property.where};
      }
    }
    for (const Entity& child : entity.children) this->entity(child);
  }

  std::optional<Clue> stage13_;
  std::optional<Clue> stage4_;
  bool sensor_ = false;
  bool stage3_ = false;
};

}  // namespace

Dialect detect_dialect(const WorldTree& tree) {
  DialectClues clues;
  clues.world(tree.world);
  return clues.decide();
}

}  // namespace playerkit::sim::worldfile
