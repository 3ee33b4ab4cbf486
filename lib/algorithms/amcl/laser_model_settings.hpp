#pragma once
// The mixture weights and shape parameters both laser models share
// (Probabilistic Robotics ch. 6.3 and 6.4).

#include "algorithms/amcl/amcl_parameters.hpp"

namespace playerkit::amcl {

struct LaserModelSettings {
  double z_hit = 0.95;
  double z_short = 0.1;
  double z_max = 0.05;
  double z_rand = 0.05;
  double sigma_hit = 0.2;
  double lambda_short = 0.1;
  bool beam_skip = false;  // likelihood field only; see AmclParameters
  double beam_skip_distance = 0.5;
  double beam_skip_threshold = 0.3;
  double beam_skip_error_threshold = 0.9;

  static LaserModelSettings from(const AmclParameters& p) {
    return {p.z_hit,     p.z_short,           p.z_max,
            p.z_rand,    p.sigma_hit,         p.lambda_short,
            p.beam_skip, p.beam_skip_distance, p.beam_skip_threshold,
            p.beam_skip_error_threshold};
  }
  friend bool operator==(const LaserModelSettings&, const LaserModelSettings&) = default;
};

}  // namespace playerkit::amcl
