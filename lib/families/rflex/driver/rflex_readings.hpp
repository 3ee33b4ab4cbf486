#pragma once
// What the RFLEX reports, kept and turned into Player 1.5's structs
// (rflex.md §3) with the robot's conversions from the configuration. Pure:
// reports in, structs out; the connection feeds it on its I/O thread.
//
// Odometry is the driver's own, as in 1.5 (the controller's heading is not
// trusted): each pair of motion reports moves it by the counters' steps, the
// distance along the heading halfway through the turn (1.5 used the new
// heading), the 32-bit counters followed across their wrap (1.5 was not).

#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

#include "families/rflex/driver/rflex_options.hpp"
#include "families/rflex/protocol/rflex_messages.hpp"
#include "interfaces/odometry_integrator.hpp"
#include "protocol/messages/aio.hpp"
#include "protocol/messages/bumper.hpp"
#include "protocol/messages/dio.hpp"
#include "protocol/messages/ir.hpp"
#include "protocol/messages/position.hpp"
#include "protocol/messages/power.hpp"
#include "protocol/messages/sonar.hpp"

namespace playerkit::drivers::rflex {

class RflexReadings {
 public:
  explicit RflexReadings(const RflexSettings& settings);

  // A motion report; true when it completed a pair (the rotation axis came):
  // the odometry moved.
  bool take_motion(const hardware::rflex::MotionReport& report);
  void take_status(const hardware::rflex::SystemStatus& status) { status_ = status; }
  // Echoes with ids beyond max_num_sonars are dropped and counted.
  void take_sonar(const std::vector<hardware::rflex::SonarEcho>& echoes);
  // False for an address outside the bumper panels.
  bool take_dio(const hardware::rflex::DioReport& report);
  void take_ir(const std::vector<hardware::rflex::IrBank>& banks) { ir_banks_ = banks; }
  // The counters start afresh (a new session): the reported pose stays.
  void restart_counters();

  [[nodiscard]] bool odometry_ready() const { return odometry_started_; }
  interfaces::OdometryIntegrator& odometry() { return odometry_; }

  [[nodiscard]] protocol::PositionData position() const;
  [[nodiscard]] protocol::SonarData sonar() const;
  [[nodiscard]] protocol::IrData ir() const;
  [[nodiscard]] protocol::BumperData bumper() const;
  [[nodiscard]] protocol::PowerData power() const;
  [[nodiscard]] std::optional<hardware::rflex::SystemStatus> status() const { return status_; }
  [[nodiscard]] std::uint64_t unknown_sonar_ids() const { return unknown_sonar_ids_; }

  // Geometry for the requests, in SI units.
  [[nodiscard]] std::vector<geometry::Pose2> sonar_poses() const;
  [[nodiscard]] std::vector<geometry::Pose2> ir_poses() const;
  [[nodiscard]] protocol::BumperGeom bumper_geometry() const;

 private:
  const RflexSettings* settings_;  // the connection's, which outlives this
  // counters of the last pair, and the velocities
  std::optional<std::int32_t> distance_;
  std::optional<std::int32_t> bearing_;
  std::optional<std::int32_t> pending_distance_;
  std::int32_t distance_velocity_ = 0;
  std::int32_t bearing_velocity_ = 0;
  bool odometry_started_ = false;
  interfaces::OdometryIntegrator odometry_;  // mm, rad

  std::optional<hardware::rflex::SystemStatus> status_;
  std::vector<std::deque<std::uint16_t>> sonar_history_;  // per raw id, newest last
  std::uint64_t unknown_sonar_ids_ = 0;
  std::vector<std::uint8_t> bumpers_;
  std::vector<hardware::rflex::IrBank> ir_banks_;
};

}  // namespace playerkit::drivers::rflex
