#include "families/rflex/rflex_family.hpp"

#include <cstdio>
#include <memory>

#include "emulators/emulator_option_reader.hpp"
#include "emulators/mobile_base/robot_options.hpp"
#include "families/rflex/emulator/rflex_emulator.hpp"
#include "families/rflex/protocol/rflex_messages.hpp"
#include "families/rflex/protocol/rflex_packet.hpp"
#include "links/framed_reader.hpp"

namespace playerkit::families {

namespace hw = hardware::rflex;

namespace {

Identification found(std::string model) {
  return {.driver = "rflex",
          .model = std::move(model),
          .interface_name = "position",
          .config_driver = "rflex_position",
          .note = "give the robot's units (odo_distance_conversion, odo_angle_conversion: see data/config/rflex-*.cfg) "
                  "and add the other rflex_* devices, or run them all: player-drivers run rflex port=..."};
}

std::unique_ptr<emulators::DeviceEmulator> make_robot(const emulators::EmulatorOptionReader& options,
                                                      const emulators::EmulatorWorld& world) {
  emulators::rflex::RflexEmulatorOptions settings;
  const std::string model = options.text("model", "b21r");
  const auto* row = emulators::rflex::find_rflex_model(model);
  if (row == nullptr) options.fail("model", "the robots are b21r, atrvjr and magellan");
  settings.model = *row;
  const auto body = emulators::mobile_base::read_robot_options(options);
  settings.initial_pose = body.initial_pose;
  settings.odometry_error = body.odometry_error;
  settings.brake_at_start = options.flag("brake", false);
  settings.model.battery_centivolts =
      static_cast<unsigned>(options.number("battery", row->battery_centivolts / 100.0, 0.0, 100.0) * 100.0 + 0.5);
  settings.sonar_max_range = options.number("sonar_range", settings.sonar_max_range, 0.1, 50.0);
  settings.failsafe = options.number("failsafe", settings.failsafe, 0.0, 3600.0);
  settings.map = world.map;
  return std::make_unique<emulators::rflex::RflexEmulator>(settings);
}

}  // namespace

std::optional<Identification> probe_rflex(const ProbeContext& line) {
  const hw::RflexFrameFormat format;
  links::FramedReader reader(line.link, format, hw::kLongestPacket);
  reader.flush();
  line.link.write_all(hw::encode_packet(hw::system_status_request()), line.first_reply);
  bool other_packets = false;
  links::Deadline deadline = line.first_reply;
  while (auto telegram = reader.next(deadline)) {
    const auto packet = hw::decode_packet(*telegram);
    if (!packet) continue;
    if (const auto status = hw::read_system_status(*packet)) {
      char volts[32];
      std::snprintf(volts, sizeof volts, "%.1f V", status->voltage / 100.0);
      return found(std::string("an RFLEX controller (battery ") + volts + (status->brake != 0 ? ", braked)" : ")"));
    }
    // A controller still reporting from an earlier session answers too; an
    // echo of the request (a loopback plug, a modem) is no report.
    if (hw::read_motion_report(*packet) || hw::read_sonar_report(*packet) || hw::read_dio_report(*packet) ||
        hw::read_ir_report(*packet)) {
      other_packets = true;
      deadline = line.finish;
    }
  }
  if (other_packets) return found("an RFLEX controller (reports, no status reply)");
  return std::nullopt;
}

emulators::EmulatorKind rflex_emulator_kind() {
  std::vector<emulators::EmulatorOptionDoc> options{
      {"model", "b21r", "the robot: b21r, atrvjr or magellan (its units, body and sensors)"},
      {"brake", "0", "1: the brake is set at power-up (MOTOR_POWER 1 releases it)"},
      {"battery", "", "battery voltage, V (the model's by default)"},
      {"sonar_range", "5", "longest sonar reading, m"},
      {"failsafe", "1", "stop when no velocity came for this long, s; 0: never"},
  };
  for (auto& doc : emulators::mobile_base::robot_option_docs()) options.push_back(std::move(doc));
  return {
      .name = "rflex",
      .summary = "an iRobot/RWI RFLEX controller on its robot: odometry reports, sonar, IR, bump panels, battery",
      .interface_name = "position",
      .driver = "rflex_position",
      .mount = emulators::EmulatorMount::robot,
      .options = std::move(options),
      .make = make_robot,
  };
}

FamilySpec rflex_family() {
  return {
      .name = "rflex",
      .summary = "iRobot/RWI RFLEX robots (B21r, ATRV, Magellan): seven devices on one serial link",
      // The controller's line runs at 115200 only (rflex.md §1).
      .probes = {{.label = "RFLEX", .bauds = {115200}, .line = {}, .ask = probe_rflex}},
      .framing = {std::make_shared<hw::RflexFrameFormat>(), std::make_shared<hw::RflexFrameFormat>()},
      .emulators = {rflex_emulator_kind()},
      .drivers = {},  // built in through CMake (playerkit_driver_family)
      .examples =
          {
              "player-drivers info rflex_position",
              "player-drivers run rflex port=/dev/ttyR0 -n 5",
              "player-drivers emulate rflex --link /tmp/robot model=b21r",
              "player-serve data/config/rflex-b21r.cfg",
          },
  };
}

}  // namespace playerkit::families
