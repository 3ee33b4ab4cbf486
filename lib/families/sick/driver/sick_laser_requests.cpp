// The laser interface's requests (sicklms200.md §3.2): GET_GEOM, GET_CONFIG
// and SET_CONFIG, which really reconfigures the laser; everything else NACK.
#include <cmath>
#include <numbers>

#include "core/device.hpp"
#include "families/sick/driver/sick_laser_driver.hpp"
#include "links/link_error.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/messages/laser.hpp"

namespace playerkit::drivers::sick_laser {

namespace {

std::int16_t rounded(double value) { return static_cast<std::int16_t>(std::lround(value)); }

}  // namespace

core::RequestResult SickLaserDriver::handle_request(const core::Request& request) {
  // The subtype is what a GET asks; 1.5 also NACKed any byte after it.
  switch (request.subtype()) {
    case protocol::kLaserGetGeom:
      return geometry();
    case protocol::kLaserGetConfig:
      return core::RequestResult::ack(
          protocol::encode(to_laser_config(scan_, settings_.model, protocol::kLaserGetConfig)));
    case protocol::kLaserSetConfig:
      return set_config(request);
    default:
      return core::RequestResult::nack();
  }
}

core::RequestResult SickLaserDriver::geometry() const {
  protocol::LaserGeom geom;
  geom.subtype = protocol::kLaserGetGeom;
  geom.pose = {rounded(settings_.pose_x * 1000.0), rounded(settings_.pose_y * 1000.0),
               rounded(settings_.pose_yaw * 180.0 / std::numbers::pi)};
  geom.size = {rounded(settings_.size_x * 1000.0), rounded(settings_.size_y * 1000.0)};
  return core::RequestResult::ack(protocol::encode(geom));
}

core::RequestResult SickLaserDriver::set_config(const core::Request& request) {
  auto& log = device().logger();
  if (request.payload.size() != protocol::LaserConfig::kWireSize) {
    log.warning(where() + ": SET_CONFIG refused: " + std::to_string(request.payload.size()) +
                " bytes, player_laser_config_t is " + std::to_string(protocol::LaserConfig::kWireSize));
    return core::RequestResult::nack();
  }
  if (lost() || lost_in_request_) {
    log.warning(where() + ": SET_CONFIG refused: the laser is not answering");
    return core::RequestResult::nack();
  }
  const auto asked = protocol::decode<protocol::LaserConfig>(request.payload);
  const ScanConfig wanted = from_laser_config(asked, settings_.model, settings_.preferred_fov);
  if (const auto problem = problem_with(wanted, settings_.model)) {
    log.warning(where() + ": SET_CONFIG refused: " + *problem);
    return core::RequestResult::nack();
  }
  const auto reply = [&] {
    return core::RequestResult::ack(
        protocol::encode(to_laser_config(scan_, settings_.model, protocol::kLaserSetConfig)));
  };
  if (wanted == scan_) return reply();

  try {
    SickLaserControl laser = control();
    try {
      laser.stop_streaming();
      const hardware::sick::Unit unit = laser.configure(wanted);
      laser.stream(wanted);
      scan_ = wanted;
      state_.unit = unit;
      last_scan_ = std::chrono::steady_clock::now();
      log.info(where() + ": now scanning " + describe(scan_, settings_.model));
      return reply();
    } catch (const SickSetupError& e) {
      log.warning(where() + ": SET_CONFIG refused: " + e.what() + "; back to " +
                  describe(scan_, settings_.model));
    }
    try {
      laser.stop_streaming();
      state_.unit = laser.configure(scan_);
      laser.stream(scan_);
      last_scan_ = std::chrono::steady_clock::now();
    } catch (const SickSetupError& e) {
      lost_in_request_ = std::string("the previous configuration could not be restored: ") + e.what();
    }
  } catch (const SickExchangeError&) {
    // Only `stopped` gets here: the driver is going away.
  } catch (const links::LinkError& e) {
    lost_in_request_ = e.what();
    port_gone_in_request_ = true;
  }
  return core::RequestResult::nack();
}

}  // namespace playerkit::drivers::sick_laser
