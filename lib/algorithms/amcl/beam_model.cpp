#include "algorithms/amcl/beam_model.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace playerkit::amcl {

namespace {

const grid::OccupancyGrid& require_map_for_beams(const std::shared_ptr<const grid::OccupancyGrid>& map) {
  if (!map) throw std::invalid_argument("BeamModel: no map");
  return *map;
}

}  // namespace

BeamModel::BeamModel(std::shared_ptr<const grid::OccupancyGrid> map)
    : caster_(require_map_for_beams(map), grid::RayStop::occupied) {}

double BeamModel::log_beam_likelihood(double range, bool no_return, double expected,
                                      double max_range, const LaserModelSettings& settings) {
  const double sigma = settings.sigma_hit;
  const double error = range - expected;
  double p = settings.z_hit * std::exp(-0.5 * error * error / (sigma * sigma)) /
             (std::sqrt(2.0 * std::numbers::pi) * sigma);
  if (range < expected) {
    p += settings.z_short * settings.lambda_short * std::exp(-settings.lambda_short * range);
  }
  if (no_return) {
    p += settings.z_max;
  } else {
    p += settings.z_rand / max_range;
  }
  return std::log(std::max(p, 1e-300));
}

void BeamModel::log_likelihoods(std::span<const Particle> particles, const PreparedBeams& beams,
                                const LaserModelSettings& settings, std::span<double> out) const {
  if (out.size() != particles.size()) {
    throw std::invalid_argument("BeamModel: output size differs from particle count");
  }
  if (!(beams.max_range > 0.0)) throw std::invalid_argument("BeamModel: max_range <= 0");
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const geometry::Pose2 sensor = particles[i].pose.compose(beams.sensor_pose);
    const Eigen::Vector2d origin(sensor.x, sensor.y);
    const double yaw = particles[i].pose.yaw;
    double sum = 0.0;
    for (std::size_t b = 0; b < beams.size(); ++b) {
      const double expected = caster_.range(origin, yaw + beams.robot_angle[b], beams.max_range);
      sum += log_beam_likelihood(beams.ranges[b], beams.no_return[b] != 0, expected,
                                 beams.max_range, settings);
    }
    out[i] = sum;
  }
}

}  // namespace playerkit::amcl
