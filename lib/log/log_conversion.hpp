#pragma once
// Conversion between CARMEN logs and Player 1.5 data messages, for
// `player-log convert` (and anything else that replays CARMEN data as Player
// devices).
//
// CARMEN -> Player (carmen_to_player):
//   FLASER         laser:0 (the scan), position:0 (the odometry pose at scan
//                  time), truth:0 (the laser's own pose), so nothing is lost;
//   RLASER         laser:1, position:0, truth:1; LASER3/4 laser:2/3 (no poses);
//   RAWLASERn      laser:n-1; ROBOTLASERn laser:n-1 + position:0 + truth:n-1;
//   ODOM           position:0 (pose, tv -> xspeed, rv -> yawspeed);
//   PARAM, TRUEPOS nothing (Player 1.5 has no place for them).
// Times: the header time (a text log's token 0) is CARMEN's logger_timestamp,
// the data timestamp (token 5) its ipc_timestamp; the host is CARMEN's host.
//
// Player -> CARMEN (PlayerToCarmen): position:0 -> ODOM; laser:0 -> FLASER
// with the robot pose of the position:0 message that follows it at the same
// data time (as carmen_to_player writes it) or else the latest one, and the
// laser pose of truth:0 likewise (else the robot pose).
//
// What the Player wire units cannot hold: positions in whole mm, headings in
// whole degrees, speeds in mm/s and deg/s, CARMEN's acceleration (lost), ranges
// in mm, or in cm for scans with a reading beyond 65.535 m (range_res 10;
// CARMEN's "no return" readings are 81.83 m), remissions (lost).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "log/carmen_log.hpp"
#include "protocol/message.hpp"

namespace playerkit::log {

struct PlayerMessages {
  std::vector<protocol::Message> messages;  // data messages, in the order to write them
  std::string host;                          // CARMEN's host, for the log line
};

// Throws std::invalid_argument for a scan Player cannot carry (more than 401
// beams, a range beyond 6553.5 m, a time before 1970 or past 2106).
PlayerMessages carmen_to_player(const CarmenRecord& record);

// The Player laser scan of a CARMEN laser record (see above for range_res).
protocol::Message carmen_laser_to_player(const CarmenLaser& laser, std::uint16_t index,
                                         protocol::Timestamp server_time, protocol::Timestamp data_time);

// Player -> CARMEN, message by message (a laser waits for the poses that
// follow it). Only data messages of position:0, truth:0 and laser:0 are used;
// feed() tells whether the message was (so a caller can count what was not).
class PlayerToCarmen {
 public:
  // Records ready to write (CarmenOdometry or CarmenLaser), oldest first.
  bool feed(const protocol::Message& message, const std::string& host);
  // At the end of the log: the laser still waiting for its poses, if any.
  void finish();
  // Takes the records made so far.
  std::vector<CarmenRecord> take_records();
  // Scans whose beam layout is not what FLASER readers guess from their beam
  // count (their angles are lost in FLASER).
  [[nodiscard]] std::size_t layout_mismatches() const { return layout_mismatches_; }
  // Scans written before any position message: their poses are 0.
  [[nodiscard]] std::size_t scans_without_pose() const { return scans_without_pose_; }

 private:
  void flush_pending();

  struct PendingScan {
    CarmenLaser laser;
    protocol::Timestamp data_time;
    bool has_robot_pose = false;
    bool has_laser_pose = false;
  };
  std::optional<PendingScan> pending_;
  std::optional<CarmenPose> latest_robot_pose_;
  std::optional<CarmenPose> latest_laser_pose_;
  std::vector<CarmenRecord> records_;
  std::size_t layout_mismatches_ = 0;
  std::size_t scans_without_pose_ = 0;
};

}  // namespace playerkit::log
