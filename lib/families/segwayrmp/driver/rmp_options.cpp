#include "families/segwayrmp/driver/rmp_options.hpp"

#include <array>
#include <cmath>

#include "core/option_reader.hpp"
#include "core/robot_option.hpp"
#include "links/port_option.hpp"

namespace playerkit::drivers::segwayrmp {

namespace {

constexpr std::array<std::string_view, 3> kFamilyDrivers{"segwayrmp", "rmpposition", "rmppower"};

core::OptionSchema make_schema() {
  using core::OptionSpec;
  return {
      OptionSpec::word("canio", "socketcan", {"socketcan", "slcan", "kvaser"})
          .doc("how the CAN bus is reached: socketcan (a Linux CAN interface, `device`) or slcan (a USB-CAN "
               "adapter speaking Lawicel ASCII on `port`; the default when a port is written); 1.5's kvaser "
               "(Kvaser's CANLIB) is refused"),
      OptionSpec::text("device", "can0").doc("socketcan: the CAN network interface (can0, vcan0) (playerkit)"),
      links::port_option("/dev/ttyUSB0").doc("slcan: the adapter's serial port, or tcp:HOST:PORT (playerkit)"),
      OptionSpec::choice("baudrate", 115200, {9600, 19200, 38400, 57600, 115200, 230400, 460800, 500000, 921600,
                                              1000000, 3000000})
          .unit("baud")
          .doc("slcan: the adapter's serial line (USB adapters ignore it) (playerkit)"),
      OptionSpec::choice("bitrate", 500000, {10000, 20000, 50000, 100000, 125000, 250000, 500000, 800000, 1000000})
          .unit("bit/s")
          .doc("slcan: the CAN bus's bit rate, set on the adapter (the RMP's is 500000); socketcan: set with "
               "`ip link` (playerkit)"),
      OptionSpec::integer("max_xspeed", 500, -3576, 3576).unit("mm/s").doc("fastest translation (absolute value)"),
      OptionSpec::integer("max_yawspeed", 40, -131, 131).unit("deg/s").doc("fastest turn (absolute value)"),
      OptionSpec::number("max_xaccel", 0, 0, 10000)
          .unit("mm/s^2")
          .doc("largest change of the commanded translation a second; 0: none (playerkit)"),
      OptionSpec::number("max_yawaccel", 0, 0, 3600)
          .unit("deg/s^2")
          .doc("largest change of the commanded turn rate a second; 0: none (playerkit)"),
      OptionSpec::number("command_timeout", 0.4, 0.05, 10)
          .unit("s")
          .doc("no new command from a client for this long: the robot is stopped (the manual's 400 ms) (playerkit)"),
      OptionSpec::number("status_timeout", 1.0, 0.1, 60)
          .unit("s")
          .doc("no status from the robot for this long: it counts as lost, stopped and looked for again (playerkit)"),
  };
}

template <class Read>
auto robot_value(const core::DriverContext& context, std::string_view name, Read read) {
  return core::robot_value(context, kFamilyDrivers, name,
                           [&](const config::Section& section, const std::string& driver) {
                             return read(core::OptionReader(section, driver, rmp_option_schema()), name);
                           });
}

double number_option(const core::DriverContext& context, std::string_view name) {
  const auto value = robot_value(
      context, name, [](const core::OptionReader& options, std::string_view n) { return options.number(n); });
  return value.value_or(rmp_option_schema().find(name)->number_fallback());
}

int integer_option(const core::DriverContext& context, std::string_view name) {
  const auto value = robot_value(
      context, name, [](const core::OptionReader& options, std::string_view n) { return options.integer(n); });
  return value.value_or(static_cast<int>(rmp_option_schema().find(name)->number_fallback()));
}

std::string text_option(const core::DriverContext& context, std::string_view name) {
  const auto value = robot_value(
      context, name, [](const core::OptionReader& options, std::string_view n) { return options.text(n); });
  return value.value_or(rmp_option_schema().find(name)->text_fallback());
}

std::chrono::milliseconds seconds_option(const core::DriverContext& context, std::string_view name) {
  return std::chrono::milliseconds(std::lround(number_option(context, name) * 1000.0));
}

}  // namespace

std::string RmpSettings::bus_name() const {
  return canio == CanIo::slcan ? "slcan:" + port : "socketcan:" + device;
}

const core::OptionSchema& rmp_option_schema() {
  static const core::OptionSchema schema = make_schema();
  return schema;
}

RmpSettings read_rmp_settings(const core::DriverContext& context) {
  RmpSettings settings;
  const auto canio = robot_value(context, "canio", [](const core::OptionReader& options, std::string_view name) {
    const std::string value = options.text(name);
    if (value == "kvaser") {
      options.fail({std::string(name)},
                   "kvaser (Kvaser's proprietary CANLIB) is not supported: Kvaser's PCI and USB adapters have "
                   "Linux SocketCAN drivers, so write canio \"socketcan\" and device \"can0\" (the adapter's "
                   "interface, at 500000 bit/s: ip link set can0 type can bitrate 500000 && ip link set can0 up), "
                   "or canio \"slcan\" and port \"/dev/ttyUSB0\" for a USB-CAN adapter speaking slcan");
    }
    return value;
  });
  // Without canio, a port names an slcan adapter (what `player-drivers probe` finds and prints).
  const bool port_given = robot_value(context, "port", [](const core::OptionReader& options, std::string_view name) {
                            return options.text(name);
                          }).has_value();
  settings.canio = canio.value_or(port_given ? "slcan" : "socketcan") == "slcan" ? CanIo::slcan : CanIo::socketcan;
  settings.device = text_option(context, "device");
  settings.port = text_option(context, "port");
  settings.baudrate = integer_option(context, "baudrate");
  settings.bitrate = integer_option(context, "bitrate");
  settings.max_xspeed = std::abs(integer_option(context, "max_xspeed"));
  settings.max_yawspeed = std::abs(integer_option(context, "max_yawspeed"));
  settings.max_xaccel = number_option(context, "max_xaccel");
  settings.max_yawaccel = number_option(context, "max_yawaccel");
  settings.command_timeout = seconds_option(context, "command_timeout");
  settings.status_timeout = seconds_option(context, "status_timeout");
  return settings;
}

}  // namespace playerkit::drivers::segwayrmp
