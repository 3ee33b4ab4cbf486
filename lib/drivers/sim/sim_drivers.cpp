#include "drivers/sim/sim_drivers.hpp"

#include <string>
#include <utility>

#include "config/errors.hpp"
#include "core/option_reader.hpp"
#include "drivers/sim/simulated_drivers.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/laser.hpp"
#include "protocol/messages/sonar.hpp"
#include "text/printable.hpp"

namespace playerkit::drivers {

namespace {

using sim::HeadingRange;
using sim::ModelKind;

enum class SimFamily { stage, gazebo, control };

struct SimDriverDescription {
  std::string name;
  std::vector<std::uint16_t> interfaces;
  SimFamily family;
  std::string manual_section;
  std::string summary;
};

const std::vector<SimDriverDescription>& sim_driver_descriptions() {
  using namespace protocol;
  static const std::vector<SimDriverDescription> descriptions{
      {"position", {kPositionCode}, SimFamily::stage, "", "a simulated robot base (-s worlds)"},
      {"omniposition", {kPositionCode}, SimFamily::stage, "", "a simulated omnidirectional base (-s worlds)"},
      {"laser", {kLaserCode}, SimFamily::stage, "", "a simulated scanning laser (-s worlds)"},
      {"ranger", {kLaserCode, kSonarCode}, SimFamily::stage, "",
       "a simulated Stage 3/4 ranger: a laser when it has one many-sample sensor, else sonar (-s worlds)"},
      {"sonar", {kSonarCode}, SimFamily::stage, "", "a simulated sonar ring (-s worlds)"},
      {"fiducialfinder", {kFiducialCode}, SimFamily::stage, "", "a simulated fiducial finder (-s worlds)"},
      {"lbd", {kFiducialCode}, SimFamily::stage, "", "a simulated fiducial finder, Stage 1.3's other name (-s worlds)"},
      {"fiducial", {kFiducialCode}, SimFamily::stage, "", "a simulated Stage 3/4 fiducial finder (-s worlds)"},
      {"blobfinder", {kBlobfinderCode}, SimFamily::stage, "", "a simulated colour blob finder (-s worlds)"},
      {"vision", {kBlobfinderCode}, SimFamily::stage, "", "a simulated blob finder, Stage 1.3's other name (-s worlds)"},
      {"ptz", {kPtzCode}, SimFamily::stage, "", "a simulated pan-tilt-zoom head (-s worlds)"},
      {"gripper", {kGripperCode}, SimFamily::stage, "", "a simulated Pioneer-style gripper (-s worlds)"},
      {"power", {kPowerCode}, SimFamily::stage, "", "a simulated battery (-s worlds)"},
      {"truth", {kTruthCode}, SimFamily::stage, "", "a simulated robot's true pose; teleports it (-s worlds)"},
      {"simulation", {kSimulationCode}, SimFamily::control, "",
       "run control of the simulated world: pause, run, one step (-s worlds)"},
      {"gz_position", {kPositionCode}, SimFamily::gazebo, "7.15", "Gazebo-era robot base on the -s world"},
      {"gz_laser", {kLaserCode}, SimFamily::gazebo, "7.14", "Gazebo-era laser on the -s world"},
      {"gz_sonar", {kSonarCode}, SimFamily::gazebo, "7.19", "Gazebo-era sonar on the -s world"},
      {"gz_sonars", {kSonarCode}, SimFamily::gazebo, "7.19",
       "Gazebo-era sonar on the -s world (gz_sonar's name in 1.5's code)"},
      {"gz_fiducial", {kFiducialCode}, SimFamily::gazebo, "", "Gazebo-era fiducial finder on the -s world"},
      {"gz_truth", {kTruthCode}, SimFamily::gazebo, "7.20", "Gazebo-era true pose on the -s world"},
      {"gz_gripper", {kGripperCode}, SimFamily::gazebo, "7.13", "Gazebo-era gripper on the -s world"},
      {"gz_ptz", {kPtzCode}, SimFamily::gazebo, "7.18", "Gazebo-era pan-tilt-zoom head on the -s world"},
      {"gz_power", {kPowerCode}, SimFamily::gazebo, "7.17", "Gazebo-era battery on the -s world"},
  };
  return descriptions;
}

const SimDriverDescription& sim_description(std::string_view name) {
  for (const SimDriverDescription& description : sim_driver_descriptions()) {
    if (description.name == name) return description;
  }
  throw std::logic_error("no simulated driver " + std::string(name));
}

std::vector<std::string> requests_of(std::uint16_t interface) {
  using namespace protocol;
  switch (interface) {
    case kPositionCode:
      return {"GET_GEOM: the body's offset and size (mm, degrees)", "MOTOR_POWER, VELOCITY_MODE, POSITION_MODE: ACK",
              "RESET_ODOM: odometry to (0, 0, 0)", "SET_ODOM: odometry to the pose given"};
    case kLaserCode:
      return {"GET_GEOM: the scan origin on the robot and the laser's size",
              "GET_CONFIG: angles and resolution (0.01°), range_res, intensity",
              "SET_CONFIG: resolution 25, 50 or 100 with angles within ±50°, ±90°, ±180°; else NACK",
              "POWER: ACK"};
    case kSonarCode:
      return {"GET_GEOM: every transducer's pose on the robot", "POWER: ACK"};
    case kFiducialCode:
      return {"GET_GEOM: the finder's pose on the robot", "GET_FOV: its ranges and field of view"};
    case kPtzCode:
      return {"CONTROL_MODE position: ACK"};
    case kPowerCode:
      return {"MAIN_POWER: the voltage"};
    case kTruthCode:
      return {"GET_POSE: the robot's true pose (mm, degrees)",
              "SET_POSE, SET_POSE_ON_ROOT: teleport the robot (odometry does not see the jump)",
              "GET_FIDUCIAL_ID: the robot's fiducial id"};
    default:
      return {};
  }
}

std::string example_for(const SimDriverDescription& description) {
  const std::string interface = protocol::interface_name(description.interfaces.front());
  switch (description.family) {
    case SimFamily::control:
      return "simulation:0 ( driver \"simulation\" )  # player-send simulation:0 cmd cmd=1 pauses";
    case SimFamily::gazebo:
      return interface + ":0 ( driver \"" + description.name + "\" gz_id \"robot1\" )";
    case SimFamily::stage:
      break;
  }
  return interface + ":0 ( driver \"" + description.name + "\" model \"robot1\" )";
}

std::unique_ptr<core::Driver> make_simulated_driver(const SimDriverDescription& description,
                                                    const std::shared_ptr<sim::SimulationSource>& source,
                                                    const core::DriverContext& context) {
  const core::OptionReader options(context.section, description.name);
  if (!source) {
    throw config::ConfigError(context.section.where(), description.name +
                                                           ": no simulated world to serve: start player-serve "
                                                           "with -s WORLD");
  }
  std::shared_ptr<sim::SimulationHost> host = source->host(context);
  context.clock.claim(host->clock(), core::to_string(context.key) + " (" + description.name + ")");
  const std::uint16_t interface = context.key.address.interface;
  if (description.family == SimFamily::control) return std::make_unique<sim::SimControlDriver>(host);

  const std::string option = description.family == SimFamily::gazebo ? "gz_id" : "model";
  if (!options.has({option})) {
    throw config::ConfigError(context.section.where(), description.name + ": needs " + option +
                                                           ", the name of a model in " +
                                                           text::excerpt(source->world_name()));
  }
  const std::string name = options.text({option}, "");
  const ModelKind kind = sim::model_kind_for(interface);
  std::string why;
  const auto model = host->with_world([&](sim::World& world) { return sim::find_model(world, name, kind, why); });
  if (!model) throw config::ConfigError(options.where({option}), description.name + ": " + why);

  const HeadingRange heading =
      description.family == SimFamily::gazebo ? HeadingRange::from_minus_180_to_180 : HeadingRange::from_0_to_360;
  const std::string device = core::to_string(context.key);
  switch (interface) {
    case protocol::kPositionCode: return std::make_unique<sim::SimPositionDriver>(host, *model, heading);
    case protocol::kLaserCode: {
      const int samples = host->with_world([&](sim::World& world) {
        return std::get<playerkit::sim::LaserSpec>(world.spec(*model).params).samples;
      });
      if (samples > static_cast<int>(protocol::kLaserMaxSamples)) {
        context.logger.info(device + ": the laser's " + std::to_string(samples) + " samples are served as " +
                            std::to_string(sim::default_laser_view(samples, 0.0).count) +
                            " (Player 1.5 carries 401 at most)");
      }
      return std::make_unique<sim::SimLaserDriver>(host, *model);
    }
    case protocol::kSonarCode: {
      const std::size_t transducers = host->with_world([&](sim::World& world) {
        return std::get<playerkit::sim::SonarSpec>(world.spec(*model).params).transducers.size();
      });
      if (transducers > protocol::kSonarMaxSamples) {
        context.logger.warning(device + ": the sonar's first 64 of " + std::to_string(transducers) +
                               " transducers are served (Player 1.5 carries 64 at most)");
      }
      return std::make_unique<sim::SimSonarDriver>(host, *model);
    }
    case protocol::kFiducialCode: return std::make_unique<sim::SimFiducialDriver>(host, *model);
    case protocol::kBlobfinderCode: return std::make_unique<sim::SimBlobfinderDriver>(host, *model);
    case protocol::kPtzCode: return std::make_unique<sim::SimPtzDriver>(host, *model);
    case protocol::kGripperCode: return std::make_unique<sim::SimGripperDriver>(host, *model);
    case protocol::kPowerCode: return std::make_unique<sim::SimPowerDriver>(host, *model);
    case protocol::kTruthCode: return std::make_unique<sim::SimTruthDriver>(host, *model, heading);
    default:
      throw config::ConfigError(context.section.where(),
                                description.name + ": cannot serve " + protocol::interface_name(interface));
  }
}

core::DriverSpec simulated_driver_spec(const SimDriverDescription& description,
                                       std::shared_ptr<sim::SimulationSource> source) {
  core::DriverSpec spec;
  spec.name = description.name;
  spec.interfaces = description.interfaces;
  spec.access = protocol::Access::kAll;
  spec.limits.request_queue = 10;  // as 1.5's gz drivers
  spec.summary = description.summary;
  spec.factory = [description, source = std::move(source)](const core::DriverContext& context) {
    return make_simulated_driver(description, source, context);
  };
  spec.doc.manual_section = description.manual_section;
  if (description.family == SimFamily::gazebo) {
    spec.doc.options = {{"gz_id", "string", "", "", "the model's name in the -s world (or a model carrying it)"}};
  } else if (description.family == SimFamily::stage) {
    spec.doc.options = {{"model", "string", "", "", "the model's name in the -s world (or a model carrying it)"}};
  }
  for (std::uint16_t interface : description.interfaces) {
    for (std::string& request : requests_of(interface)) spec.doc.requests.push_back(std::move(request));
  }
  if (description.family == SimFamily::control) {
    spec.doc.requests = {"0 run, 1 pause, 2 one step (then paused): ACK with the state byte (1 paused)",
                         "commands: the same bytes, acted on at the next server cycle"};
  }
  spec.doc.example = example_for(description);
  return spec;
}

core::DriverSpec builtin_sim_spec(std::string_view name) { return simulated_driver_spec(sim_description(name), nullptr); }

}  // namespace

std::vector<core::DriverSpec> simulation_driver_specs(std::shared_ptr<sim::SimulationSource> source) {
  std::vector<core::DriverSpec> specs;
  for (const SimDriverDescription& description : sim_driver_descriptions()) {
    specs.push_back(simulated_driver_spec(description, source));
  }
  return specs;
}

core::DriverSpec sim_position_driver_spec() { return builtin_sim_spec("position"); }
core::DriverSpec sim_omniposition_driver_spec() { return builtin_sim_spec("omniposition"); }
core::DriverSpec sim_laser_driver_spec() { return builtin_sim_spec("laser"); }
core::DriverSpec sim_ranger_driver_spec() { return builtin_sim_spec("ranger"); }
core::DriverSpec sim_sonar_driver_spec() { return builtin_sim_spec("sonar"); }
core::DriverSpec sim_fiducialfinder_driver_spec() { return builtin_sim_spec("fiducialfinder"); }
core::DriverSpec sim_lbd_driver_spec() { return builtin_sim_spec("lbd"); }
core::DriverSpec sim_fiducial_driver_spec() { return builtin_sim_spec("fiducial"); }
core::DriverSpec sim_blobfinder_driver_spec() { return builtin_sim_spec("blobfinder"); }
core::DriverSpec sim_vision_driver_spec() { return builtin_sim_spec("vision"); }
core::DriverSpec sim_ptz_driver_spec() { return builtin_sim_spec("ptz"); }
core::DriverSpec sim_gripper_driver_spec() { return builtin_sim_spec("gripper"); }
core::DriverSpec sim_power_driver_spec() { return builtin_sim_spec("power"); }
core::DriverSpec sim_truth_driver_spec() { return builtin_sim_spec("truth"); }
core::DriverSpec sim_simulation_driver_spec() { return builtin_sim_spec("simulation"); }
core::DriverSpec gz_position_driver_spec() { return builtin_sim_spec("gz_position"); }
core::DriverSpec gz_laser_driver_spec() { return builtin_sim_spec("gz_laser"); }
core::DriverSpec gz_sonar_driver_spec() { return builtin_sim_spec("gz_sonar"); }
core::DriverSpec gz_sonars_driver_spec() { return builtin_sim_spec("gz_sonars"); }
core::DriverSpec gz_fiducial_driver_spec() { return builtin_sim_spec("gz_fiducial"); }
core::DriverSpec gz_truth_driver_spec() { return builtin_sim_spec("gz_truth"); }
core::DriverSpec gz_gripper_driver_spec() { return builtin_sim_spec("gz_gripper"); }
core::DriverSpec gz_ptz_driver_spec() { return builtin_sim_spec("gz_ptz"); }
core::DriverSpec gz_power_driver_spec() { return builtin_sim_spec("gz_power"); }

}  // namespace playerkit::drivers
