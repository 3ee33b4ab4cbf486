#pragma once
// The subcommands of amcl-offline, as functions of their options, so that
// main.cpp only turns flags into these structs. Each returns the exit status
// and reports on `err`; data goes to the output file or stdout.

#include <cstdint>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>

#include "exit_status.hpp"
#include "localization/odometry_perturbation.hpp"
#include "localization/offline_localizer.hpp"

namespace playerkit::amcl_offline {

// 1: unreadable input, cannot write.
using tools::kExitFailure;
using tools::kExitOk;
using tools::kExitUsage;
using tools::UsageError;

struct MapCommand {
  std::string log;
  std::string output;  // .pgm; the .yaml goes beside it
  double resolution = 0.05;
  double max_range = 30.0;
  double no_return_clears = 0.0;  // metres; 0: no-return readings leave the map alone
  bool use_odometry = false;  // logs without truth: trust their odometry
};

struct PerturbCommand {
  std::string log;
  std::string output;  // "-" = stdout
  std::uint64_t seed = 1;
  localization::OdometryErrorModel model;
};

struct LocalizeCommand {
  std::string log;
  std::string map;
  std::optional<double> scale;  // m/pixel for Player images
  bool negate = false;
  std::optional<std::string> init_pose;  // "X,Y,YAW_DEG" or "truth"
  std::optional<std::string> init_var;   // "SX,SY,SYAW_DEG" (standard deviations)
  bool global = false;
  std::optional<std::string> particles;  // "MIN,MAX"
  std::string model = "likelihood";
  std::optional<std::size_t> laser_beams;
  std::optional<double> alpha_slow, alpha_fast;  // augmented MCL (0,0: no random particles)
  std::optional<double> odom_noise_scale;         // multiplies the four motion-noise alphas
  std::optional<std::string> update_thresh;       // "D,A_DEG": update after this much motion
  std::optional<double> sigma_hit;                // laser hit noise (m)
  std::uint64_t seed = 0;
  std::string format = "csv";
  std::string output = "-";
  std::optional<std::string> plot;
  bool progress = false;  // stderr is a terminal
};

struct EvalCommand {
  std::string estimate;
  std::string truth;  // a log, or a CSV with time,x,y,yaw
  bool json = false;
};

int run_map(const MapCommand& command, std::ostream& err);
int run_perturb(const PerturbCommand& command, std::ostream& out, std::ostream& err);
int run_localize(const LocalizeCommand& command, std::ostream& out, std::ostream& err);
int run_eval(const EvalCommand& command, std::ostream& out, std::ostream& err);

}  // namespace playerkit::amcl_offline
