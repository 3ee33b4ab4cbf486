#include "algorithms/amcl/likelihood_field_model.hpp"

#include "algorithms/amcl/likelihood_field_lanes.hpp"
#include "algorithms/geometry/sin_cos.hpp"
#include "algorithms/grid/distance_map.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace playerkit::amcl {
namespace {

// Per row of `values` (one particle's beam values, `stride` apart), the sum
// of the entries at `beams`, in their order. A sum is a chain of dependent
// additions; four rows at a time make four chains the processor runs side by
// side, each in the same order as alone, so every sum is bit for bit the
// one-row sum.
void sum_rows(const float* values, std::size_t stride, std::size_t rows, const std::size_t* beams,
              std::size_t beam_count, double* out) {
  std::size_t i = 0;
  for (; i + 4 <= rows; i += 4) {
    const float* v0 = values + i * stride;
    const float* v1 = v0 + stride;
    const float* v2 = v1 + stride;
    const float* v3 = v2 + stride;
    double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
    for (std::size_t k = 0; k < beam_count; ++k) {
      const std::size_t b = beams[k];
      s0 += v0[b];
      s1 += v1[b];
      s2 += v2[b];
      s3 += v3[b];
    }
    out[i] = s0;
    out[i + 1] = s1;
    out[i + 2] = s2;
    out[i + 3] = s3;
  }
  for (; i < rows; ++i) {
    const float* v = values + i * stride;
    double sum = 0.0;
    for (std::size_t k = 0; k < beam_count; ++k) sum += v[beams[k]];
    out[i] = sum;
  }
}

}  // namespace

LikelihoodFieldModel::LikelihoodFieldModel(const grid::OccupancyGrid& map, double max_distance)
    : width_(map.width()), height_(map.height()), resolution_(map.resolution()), origin_(map.origin()) {
  const grid::DistanceMap distances(map, max_distance);
  max_distance_ = distances.max_distance();
  const double codes_per_metre = max_distance_ > 0.0 ? (kDistanceCodes - 1) / max_distance_ : 0.0;
  distance_codes_.resize(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_) +
                         field_lanes::kReadPadding);
  for (int row = 0; row < height_; ++row) {
    for (int col = 0; col < width_; ++col) {
      const double code = std::min(std::round(distances.at(col, row) * codes_per_metre), kDistanceCodes - 1.0);
      distance_codes_[static_cast<std::size_t>(row) * static_cast<std::size_t>(width_) +
                      static_cast<std::size_t>(col)] = static_cast<std::uint8_t>(code);
    }
  }
}

double LikelihoodFieldModel::log_endpoint_likelihood(double distance, double max_range,
                                                     const LaserModelSettings& settings) {
  const double sigma = settings.sigma_hit;
  const double hit = std::exp(-0.5 * distance * distance / (sigma * sigma)) /
                     (std::sqrt(2.0 * std::numbers::pi) * sigma);
  const double p = settings.z_hit * hit + settings.z_rand / max_range;
  // A zero z_rand and a far endpoint would give log 0; floor it so one
  // stray beam cannot veto a particle outright.
  return std::log(std::max(p, 1e-300));
}

void LikelihoodFieldModel::refresh_table(const LaserModelSettings& settings, double max_range) {
  if (table_valid_ && settings == table_settings_ && max_range == table_max_range_) return;
  for (int code = 0; code < kDistanceCodes; ++code) {
    const double distance = max_distance_ * code / (kDistanceCodes - 1);
    log_by_code_[static_cast<std::size_t>(code)] =
        static_cast<float>(log_endpoint_likelihood(distance, max_range, settings));
  }
  table_settings_ = settings;
  table_max_range_ = max_range;
  table_valid_ = true;
}

void LikelihoodFieldModel::log_likelihoods(std::span<const Particle> particles,
                                           const PreparedBeams& beams,
                                           const LaserModelSettings& settings,
                                           std::span<double> out) {
  if (out.size() != particles.size()) {
    throw std::invalid_argument("LikelihoodFieldModel: output size differs from particle count");
  }
  if (!(beams.max_range > 0.0)) throw std::invalid_argument("LikelihoodFieldModel: max_range <= 0");
  refresh_table(settings, beams.max_range);

  hit_x_.clear();
  hit_y_.clear();
  for (std::size_t b = 0; b < beams.size(); ++b) {
    if (beams.no_return[b]) continue;
    hit_x_.push_back(beams.end_x[b]);
    hit_y_.push_back(beams.end_y[b]);
  }
  const std::size_t hits = hit_x_.size();
  // The vector scoring takes beams four at a time: padded with endpoints at
  // the robot, whose values are never read.
  const std::size_t padded = (hits + 3) / 4 * 4;
  hit_x_.resize(padded, 0.0);
  hit_y_.resize(padded, 0.0);
  const double inverse_resolution = 1.0 / resolution_;
  const double* hx = hit_x_.data();
  const double* hy = hit_y_.data();
  const std::uint8_t* codes = distance_codes_.data();
  const float* log_by_code = log_by_code_.data();
  const float log_outside = log_by_code_[kDistanceCodes - 1];
  const field_lanes::FieldTable table{codes, log_by_code, log_outside, width_, height_};
  // 32-bit cell indices in the vector scoring.
  const bool vector = vector_scoring_ &&
                      static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_) < (std::size_t{1} << 31) &&
                      field_lanes::available();

  // values[b] for every beam b of the particle at `pose` (and, with the
  // vector scoring, the padding after them).
  const auto endpoint_values = [&](const geometry::Pose2& pose, float* values) {
    const auto [s, c] = geometry::sin_cos(pose.yaw);
    // Cell coordinates of the particle, so each endpoint is one rotation away.
    const field_lanes::CellPose cell{(pose.x - origin_.x()) * inverse_resolution,
                                     (pose.y - origin_.y()) * inverse_resolution, c * inverse_resolution,
                                     s * inverse_resolution};
    if (vector) {
      field_lanes::endpoint_values(table, cell, hx, hy, padded, values);
      return;
    }
    for (std::size_t b = 0; b < hits; ++b) {
      const int col = static_cast<int>(std::floor(cell.col + cell.cos_r * hx[b] - cell.sin_r * hy[b]));
      const int row = static_cast<int>(std::floor(cell.row + cell.sin_r * hx[b] + cell.cos_r * hy[b]));
      const bool inside = col >= 0 && row >= 0 && col < width_ && row < height_;
      values[b] = inside ? log_by_code[codes[static_cast<std::size_t>(row) * static_cast<std::size_t>(width_) +
                                             static_cast<std::size_t>(col)]]
                         : log_outside;
    }
  };

  if (!settings.beam_skip || hits == 0) {
    // A few particles' values at a time, summed side by side (sum_rows).
    constexpr std::size_t kBatch = 16;
    every_beam_.resize(hits);
    for (std::size_t b = 0; b < hits; ++b) every_beam_[b] = b;
    particle_values_.resize(kBatch * padded);
    float* values = particle_values_.data();
    for (std::size_t first = 0; first < particles.size(); first += kBatch) {
      const std::size_t count = std::min(kBatch, particles.size() - first);
      for (std::size_t j = 0; j < count; ++j) endpoint_values(particles[first + j].pose, values + j * padded);
      sum_rows(values, padded, count, every_beam_.data(), hits, out.data() + first);
    }
    return;
  }

  // Beam skipping: first every particle's value of every beam, and how much
  // of the weight explains each beam; then the sums over the beams kept.
  const auto explained = static_cast<float>(
      log_endpoint_likelihood(settings.beam_skip_distance, beams.max_range, settings));
  beam_values_.resize(particles.size() * padded);
  explained_weight_.assign(hits, 0.0);
  double* explained_weight = explained_weight_.data();
  double total_weight = 0.0;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    float* values = beam_values_.data() + i * padded;
    const double weight = particles[i].weight;
    total_weight += weight;
    endpoint_values(particles[i].pose, values);
    for (std::size_t b = 0; b < hits; ++b) explained_weight[b] += values[b] >= explained ? weight : 0.0;
  }
  kept_beams_.clear();
  for (std::size_t b = 0; b < hits; ++b) {
    if (explained_weight[b] >= settings.beam_skip_threshold * total_weight) kept_beams_.push_back(b);
  }
  const std::size_t skipped = hits - kept_beams_.size();
  const bool skip = static_cast<double>(skipped) <= settings.beam_skip_error_threshold * static_cast<double>(hits);
  if (!skip) {
    kept_beams_.resize(hits);
    for (std::size_t b = 0; b < hits; ++b) kept_beams_[b] = b;
  }
  sum_rows(beam_values_.data(), padded, particles.size(), kept_beams_.data(), kept_beams_.size(), out.data());
}

}  // namespace playerkit::amcl
