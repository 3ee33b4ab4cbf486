#include "session.hpp"

#include <algorithm>
#include <cmath>

#include "client/typed/fiducial.hpp"
#include "client/typed/laser.hpp"
#include "map/map_file.hpp"
#include "client/typed/message_as.hpp"
#include "client/typed/position.hpp"
#include "client/typed/ranging.hpp"
#include "protocol/errors.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::player_view {
namespace {

std::string device_lines(const std::vector<client::DeviceEntry>& entries) {
  if (entries.empty()) return "  (no devices)\n";
  std::string text;
  for (const auto& entry : entries) {
    text += "  " + protocol::to_string(entry.address) + " " +
            (entry.driver_name.empty() ? std::string("(driver unknown)") : entry.driver_name) + "\n";
  }
  return text;
}

bool readable(const client::AccessGrant& grant) {
  return grant.access == protocol::Access::kRead || grant.access == protocol::Access::kAll;
}

std::string refusal(protocol::DeviceAddress device, const client::AccessGrant& grant, const std::string& where) {
  const std::string name = protocol::to_string(device);
  if (grant.driver_name.empty()) return where + " has no device " + name;
  return name + " (driver " + grant.driver_name + ") on " + where +
         " could not be opened for reading: its driver failed to set up; the server's log says why";
}

// The reply to a one-byte request (the subtype), or nullopt when the device
// does not answer it with an ACK in time.
std::optional<protocol::Message> ask(client::Client& connection, protocol::DeviceAddress device,
                                     std::uint8_t subtype) {
  const std::vector<std::uint8_t> payload{subtype};
  try {
    auto reply = connection.request(device, payload);
    if (reply.type() != protocol::MessageType::kAck) return std::nullopt;
    return reply;
  } catch (const client::TimeoutError&) {
    return std::nullopt;
  }
}

}  // namespace

std::optional<grid::OccupancyGrid> load_view_map(const ViewOptions& options) {
  if (!options.map) return std::nullopt;
  return map::load_map(*options.map, options.map_loading);
}

std::chrono::milliseconds reply_timeout(const ViewOptions& options) {
  return std::chrono::milliseconds(static_cast<std::int64_t>(std::ceil(options.timeout * 1000.0)));
}

std::chrono::milliseconds geometry_timeout(const ViewOptions& options) {
  // Geometry replies come quickly or not at all; a device that ignores them
  // must not hold the view up for the whole --timeout each.
  return std::min(std::chrono::milliseconds(1000), reply_timeout(options));
}

Session open_session(const ViewOptions& options, std::ostream& err) {
  Session session{client::Client::connect(options.server.host, options.server.port, reply_timeout(options)), {}};
  auto& connection = session.connection;
  const std::string where = client::to_string(options.server);
  try {
    if (options.key) connection.authenticate(*options.key);
    if (!options.devices.empty()) {
      for (const auto device : options.devices) {
        const auto grant = connection.request_access(device, protocol::Access::kRead);
        if (!readable(grant)) {
          throw ViewFailure(refusal(device, grant, where) + "\nthe server has:\n" +
                            device_lines(connection.device_list()));
        }
        session.devices.push_back(device);
      }
      return session;
    }
    const auto entries = connection.device_list();
    for (const auto& entry : entries) {
      const auto grant = connection.request_access(entry.address, protocol::Access::kRead);
      if (readable(grant)) {
        session.devices.push_back(entry.address);
      } else {
        err << "player-view: skipping " << refusal(entry.address, grant, where) << "\n";
      }
    }
    if (session.devices.empty()) {
      throw ViewFailure(where + " has no device that opens for reading\nthe server has:\n" + device_lines(entries));
    }
  } catch (const client::TimeoutError&) {
    throw;
  } catch (const client::ClientError& e) {
    // A server started with -k hangs up on a first message that is not its key.
    if (options.key) throw;
    throw ViewFailure(std::string(e.what()) + "; if the server was started with -k, pass --key");
  }
  return session;
}

protocol::DeviceAddress open_base_for_driving(Session& session, const ViewOptions& options) {
  const auto base = std::find_if(session.devices.begin(), session.devices.end(), [](protocol::DeviceAddress device) {
    return device.interface == protocol::kPositionCode;
  });
  const std::string where = client::to_string(options.server);
  if (base == session.devices.end()) throw ViewFailure("--drive: no position device to drive on " + where);
  const auto grant = session.connection.request_access(*base, protocol::Access::kAll);
  if (grant.access != protocol::Access::kAll) {
    throw ViewFailure("--drive: " + protocol::to_string(*base) + " on " + where + " refused to be opened for writing");
  }
  return *base;
}

int report_failures(const ViewOptions& options, std::ostream& err, const std::function<void()>& work) {
  try {
    work();
    return kExitOk;
  } catch (const ViewFailure& e) {
    err << "player-view: " << e.what() << (std::string_view(e.what()).ends_with('\n') ? "" : "\n");
  } catch (const client::ClientError& e) {
    // Connection errors name the address; a lost connection's do not.
    const std::string where = client::to_string(options.server);
    const std::string what = e.what();
    err << "player-view: " << (what.find(where) == std::string::npos ? where + ": " : "") << what << "\n";
  } catch (const std::exception& e) {
    // Map files, pictures, the HTTP port: their messages name the file or address.
    err << "player-view: " << e.what() << "\n";
  }
  return kExitFailure;
}

void ask_geometry(Session& session, view::Scene& scene, std::chrono::milliseconds timeout) {
  session.connection.set_timeout(timeout);
  for (const auto device : session.devices) {
    scene.add_device(device);
    try {
      switch (device.interface) {
        case protocol::kLaserCode:
          if (auto reply = ask(session.connection, device, protocol::kLaserGetGeom)) {
            scene.set_mount_pose(device, client::to_si(client::reply_as<protocol::LaserGeom>(*reply)).pose);
          }
          break;
        case protocol::kFiducialCode:
          if (auto reply = ask(session.connection, device, protocol::kFiducialGetGeom)) {
            scene.set_mount_pose(device, client::to_si(client::reply_as<protocol::FiducialGeom>(*reply)).pose);
          }
          break;
        case protocol::kSonarCode:
          if (auto reply = ask(session.connection, device, protocol::kSonarGetGeomReq)) {
            scene.set_sensor_poses(device, client::to_si(client::reply_as<protocol::SonarGeom>(*reply)).poses);
          }
          break;
        case protocol::kIrCode:
          if (auto reply = ask(session.connection, device, protocol::kIrPoseReq)) {
            scene.set_sensor_poses(device, client::to_si(client::reply_as<protocol::IrPoseRequest>(*reply)).poses);
          }
          break;
        case protocol::kPositionCode:
          if (auto reply = ask(session.connection, device, protocol::kPositionGetGeomReq)) {
            const auto geometry = client::to_si(client::reply_as<protocol::PositionGeom>(*reply));
            scene.set_robot_size(geometry.length, geometry.width);
          }
          break;
        default:
          break;
      }
    } catch (const client::MessageKindError&) {
      // A reply of another shape: draw with the defaults.
    } catch (const protocol::DecodeError&) {
    }
  }
}

}  // namespace playerkit::player_view
