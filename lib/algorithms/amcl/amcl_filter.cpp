#include "algorithms/amcl/amcl_filter.hpp"

#include "algorithms/amcl/motion_model.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace playerkit::amcl {
namespace {

std::shared_ptr<const grid::OccupancyGrid> require_nonempty_map(
    std::shared_ptr<const grid::OccupancyGrid> map) {
  if (!map || map->empty()) throw std::invalid_argument("AmclFilter: no map");
  return map;
}

const AmclParameters& validated(const AmclParameters& parameters) {
  validate(parameters);
  return parameters;
}

// `factor` x `factor` cells of `map` as one: an obstacle if any of them is,
// else free if any is, else unknown.
grid::OccupancyGrid coarsened(const grid::OccupancyGrid& map, int factor) {
  if (factor <= 1) return map;
  const int width = (map.width() + factor - 1) / factor;
  const int height = (map.height() + factor - 1) / factor;
  grid::OccupancyGrid coarse(width, height, map.resolution() * factor, map.origin(), grid::CellState::unknown);
  for (int row = 0; row < map.height(); ++row) {
    for (int col = 0; col < map.width(); ++col) {
      const grid::CellState cell = map.at(col, row);
      if (cell == grid::CellState::unknown) continue;
      const int coarse_col = col / factor, coarse_row = row / factor;
      const grid::CellState was = coarse.at(coarse_col, coarse_row);
      if (was != grid::CellState::occupied) coarse.set(coarse_col, coarse_row, cell);
    }
  }
  return coarse;
}

}  // namespace

AmclFilter::AmclFilter(AmclParameters parameters, std::shared_ptr<const grid::OccupancyGrid> map,
                       std::uint64_t seed, const std::optional<StartPose>& start)
    : parameters_(validated(parameters)),
      map_(require_nonempty_map(std::move(map))),
      rng_(seed),
      free_space_(*map_),
      recovery_(parameters_.alpha_slow, parameters_.alpha_fast) {
  if (free_space_.empty()) throw std::invalid_argument("AmclFilter: the map has no free cell");
  if (start) {
    set_pose(start->mean, start->covariance);
  } else {
    set_global();
  }
}

void AmclFilter::restart() {
  recovery_.reset();
  have_odometry_reference_ = false;
  laser_update_pending_ = true;
  refresh_hypotheses();
}

void AmclFilter::set_pose(const geometry::Pose2& mean, const Eigen::Matrix3d& covariance) {
  sample_gaussian(mean, covariance, parameters_.max_particles, rng_, particles_);
  searching_ = false;
  seed_search_pending_ = false;
  seed_scans_.clear();
  found_updates_ = 0;
  apply_recovery_rates();
  restart();
}

void AmclFilter::set_global() {
  search_particles_ = global_particles();
  sample_uniform(free_space_, search_particles_, rng_, particles_);
  searching_ = true;
  const double free_area = static_cast<double>(free_space_.free_cell_count()) * map_->resolution() *
                           map_->resolution();
  seed_search_pending_ = parameters_.seed_search_position_step > 0.0 &&
                         static_cast<double>(search_particles_) < parameters_.seed_search_below_density * free_area;
  seed_scans_.clear();
  seed_travel_ = 0.0;
  found_updates_ = 0;
  apply_recovery_rates();
  restart();
}

std::size_t AmclFilter::global_particles() const {
  const double cell_area = map_->resolution() * map_->resolution();
  const double wanted = parameters_.global_particles_per_square_metre *
                        static_cast<double>(free_space_.free_cell_count()) * cell_area;
  const double least = static_cast<double>(parameters_.max_particles);
  const double most = std::max(least, static_cast<double>(parameters_.global_particles_most));
  return static_cast<std::size_t>(std::clamp(wanted, least, most));
}

// The configured rates, or the search's while searching with recovery off.
void AmclFilter::apply_recovery_rates() {
  const bool search_rates = searching_ && parameters_.alpha_slow == 0.0 && parameters_.alpha_fast == 0.0;
  recovery_.set_rates(search_rates ? parameters_.search_alpha_slow : parameters_.alpha_slow,
                      search_rates ? parameters_.search_alpha_fast : parameters_.alpha_fast);
}

void AmclFilter::end_search_once_found() {
  // Nor before the seed search has run: the uniform draw's clusters until then mean nothing.
  if (!searching_ || clusters_.empty() || seed_search_pending_) return;
  const Hypothesis& heaviest = clusters_.front();
  const double spread = std::sqrt(std::max(0.0, heaviest.covariance(0, 0) + heaviest.covariance(1, 1)));
  if (heaviest.weight < parameters_.search_end_weight || !(spread <= parameters_.search_end_spread)) {
    found_updates_ = 0;
    return;
  }
  if (++found_updates_ < parameters_.search_end_updates) return;
  searching_ = false;
  // The search's averages would read the found belief's likelihood against
  // the search's; recovery as configured starts afresh.
  recovery_.reset();
  apply_recovery_rates();
}

void AmclFilter::set_parameters(const AmclParameters& parameters) {
  validate(parameters);
  if (parameters.likelihood_max_distance != parameters_.likelihood_max_distance) {
    likelihood_field_.reset();
  }
  parameters_ = parameters;
  apply_recovery_rates();
  refresh_hypotheses();
}

LikelihoodFieldModel& AmclFilter::likelihood_field() {
  if (!likelihood_field_) {
    likelihood_field_ =
        std::make_unique<LikelihoodFieldModel>(*map_, parameters_.likelihood_max_distance);
  }
  return *likelihood_field_;
}

BeamModel& AmclFilter::beam_model() {
  if (!beam_model_) beam_model_ = std::make_unique<BeamModel>(map_);
  return *beam_model_;
}

bool AmclFilter::update(const geometry::Pose2& odometry, const LaserScan* scan) {
  if (!have_odometry_reference_) {
    have_odometry_reference_ = true;
    particle_odometry_ = laser_odometry_ = cluster_odometry_ = odometry;
    if (scan == nullptr) return false;
    laser_update(*scan);
    return true;
  }
  const auto moved_since = [&](const geometry::Pose2& reference) {
    return std::hypot(odometry.x - reference.x, odometry.y - reference.y) >
               parameters_.update_min_distance ||
           std::abs(geometry::angle_difference(odometry.yaw, reference.yaw)) >
               parameters_.update_min_angle;
  };
  if (scan != nullptr && (laser_update_pending_ || moved_since(laser_odometry_))) {
    unmoved_updates_ = moved_since(laser_odometry_) ? 0 : unmoved_updates_ + 1;
    move_particles(odometry);
    laser_update(*scan);
    laser_odometry_ = odometry;
    return true;
  }
  if (scan == nullptr && moved_since(particle_odometry_)) {
    move_particles(odometry);
    refresh_hypotheses();
  }
  return false;
}

void AmclFilter::move_particles(const geometry::Pose2& odometry) {
  apply_motion(parameters_.motion_model, particles_, particle_odometry_, odometry,
               MotionNoise::from(parameters_), rng_);
  particle_odometry_ = odometry;
}

void AmclFilter::laser_update(const LaserScan& scan) {
  laser_update_pending_ = false;
  ++update_count_;
  prepare_beams(scan, parameters_.laser_max_beams, beams_);
  const bool tracking = !searching_ && !clusters_.empty() && clusters_.front().weight >= 0.5;
  if (parameters_.short_reading_filter && tracking) leave_out_short_readings(scan);
  LaserModelSettings settings = LaserModelSettings::from(parameters_);
  // Skipping beams few particles explain helps only a belief that is mostly
  // in one place; a spread one (global start) explains no beam in majority.
  settings.beam_skip = settings.beam_skip && !clusters_.empty() && clusters_.front().weight >= 0.5;
  const auto returned_beams =
      static_cast<std::size_t>(std::count(beams_.no_return.begin(), beams_.no_return.end(), 0));
  if (seed_search_pending_ && searching_ && returned_beams > 0) gather_seed_evidence();
  log_likelihoods_.resize(particles_.size());
  std::size_t informative_beams = beams_.size();
  if (parameters_.laser_model == LaserModelType::beam) {
    beam_model().log_likelihoods(particles_, beams_, settings, log_likelihoods_);
  } else {
    informative_beams = returned_beams;
    likelihood_field().log_likelihoods(particles_, beams_, settings, log_likelihoods_);
  }

  if (informative_beams > 0 && !particles_.empty()) {
    normalize_weights(particles_);
    // The scan's likelihood under the current belief, sum_i w_i p(z | x_i),
    // from the untempered model and taken per beam (a geometric mean) so the
    // recovery averages do not swing by orders of magnitude with the beam
    // count or one odd scan.
    const double highest = *std::max_element(log_likelihoods_.begin(), log_likelihoods_.end());
    double expected = 0.0;
    for (std::size_t i = 0; i < particles_.size(); ++i) {
      expected += particles_[i].weight * std::exp(log_likelihoods_[i] - highest);
    }
    recovery_.observe((highest + std::log(expected)) / static_cast<double>(informative_beams));

    const double exponent = parameters_.laser_model == LaserModelType::beam
                                ? parameters_.beam_scan_likelihood_exponent
                                : parameters_.scan_likelihood_exponent;
    for (std::size_t i = 0; i < particles_.size(); ++i) {
      particles_[i].weight *= std::exp(exponent * (log_likelihoods_[i] - highest));
    }
    normalize_weights(particles_);
  }

  const bool due =
      parameters_.selective_resampling
          ? effective_sample_size(particles_) < 0.5 * static_cast<double>(particles_.size())
          : update_count_ % parameters_.resample_interval == 0;
  if (due) resample();
  refresh_hypotheses();
  end_search_once_found();
  laser_update_pending_ = belief_uncertain() && unmoved_updates_ < parameters_.uncertain_updates_most;
}

void AmclFilter::gather_seed_evidence() {
  if (!seed_scans_.empty()) {
    const geometry::Pose2& last = seed_scans_.back().odometry;
    seed_travel_ += std::hypot(particle_odometry_.x - last.x, particle_odometry_.y - last.y);
  }
  seed_scans_.push_back({beams_, particle_odometry_});
  if (seed_travel_ >= parameters_.seed_search_distance || seed_scans_.size() >= parameters_.seed_search_scans_most) {
    seed_search_from_scans();
  }
}

void AmclFilter::seed_search_from_scans() {
  seed_search_pending_ = false;
  const double resolution = map_->resolution();
  const int block = std::max(1, static_cast<int>(std::lround(parameters_.seed_search_position_step / resolution)));
  const double position_step = block * resolution;
  const auto headings = static_cast<std::size_t>(
      std::max(1L, std::lround(2.0 * std::numbers::pi / parameters_.seed_search_heading_step)));
  const double heading_step = 2.0 * std::numbers::pi / static_cast<double>(headings);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double heading_offset = unit(rng_) * heading_step;

  // One candidate position per block of the grid whose middle cell is free.
  std::vector<Eigen::Vector2d> positions;
  for (int row = block / 2; row < map_->height(); row += block) {
    for (int col = block / 2; col < map_->width(); col += block) {
      if (map_->at(col, row) == grid::CellState::free) positions.push_back(map_->cell_centre({col, row}));
    }
  }
  if (positions.empty()) return;

  // The coarse passes read a field of cells half a step wide, made from a
  // map whose cell is an obstacle where any of its fine cells is: a 3000 x
  // 3000 map's field is 9 MB, read at random, and its coarse copy a
  // twenty-fifth of that stays in cache (the coarse pass took 1 s of a
  // 150 m floor's run at 0.05 m cells).
  const int coarse_factor = std::max(1, block / 2);
  const grid::OccupancyGrid coarse_map = coarsened(*map_, coarse_factor);
  LikelihoodFieldModel coarse_field(coarse_map, parameters_.likelihood_max_distance);

  // Coarse: every candidate scored with the field widened by half a step,
  // against the first scan; the best seed_search_pool_factor times
  // seed_search_candidates of them against every later scan too, each
  // where odometry says the robot went from there.
  LaserModelSettings coarse = LaserModelSettings::from(parameters_);
  coarse.beam_skip = false;
  coarse.sigma_hit = std::hypot(coarse.sigma_hit, 0.5 * position_step);
  const PreparedBeams& first_beams = seed_scans_.front().beams;
  const std::size_t candidates = positions.size() * headings;
  seed_scores_.resize(candidates);
  constexpr std::size_t kChunkPositions = 512;
  for (std::size_t first = 0; first < positions.size(); first += kChunkPositions) {
    const std::size_t count = std::min(kChunkPositions, positions.size() - first);
    seed_candidates_.resize(count * headings);
    for (std::size_t i = 0; i < count; ++i) {
      for (std::size_t h = 0; h < headings; ++h) {
        const double yaw = geometry::normalize_angle(heading_offset + static_cast<double>(h) * heading_step);
        seed_candidates_[i * headings + h].pose = {positions[first + i].x(), positions[first + i].y(), yaw};
      }
    }
    seed_chunk_scores_.resize(seed_candidates_.size());
    coarse_field.log_likelihoods(seed_candidates_, first_beams, coarse, seed_chunk_scores_);
    for (std::size_t k = 0; k < seed_candidates_.size(); ++k) {
      seed_scores_[first * headings + k] = static_cast<float>(seed_chunk_scores_[k]);
    }
  }
  seed_order_.resize(candidates);
  for (std::size_t k = 0; k < candidates; ++k) seed_order_[k] = static_cast<std::uint32_t>(k);
  // The best `count` of seed_order_ first, ties broken by index so a seed
  // picks the same set everywhere.
  const auto keep_best = [&](std::size_t count) {
    if (count == 0 || count >= seed_order_.size()) return;
    std::nth_element(seed_order_.begin(), seed_order_.begin() + static_cast<std::ptrdiff_t>(count - 1),
                     seed_order_.end(), [&](std::uint32_t a, std::uint32_t b) {
                       return seed_scores_[a] != seed_scores_[b] ? seed_scores_[a] > seed_scores_[b] : a < b;
                     });
    seed_order_.resize(count);
  };
  const auto candidate_pose = [&](std::uint32_t candidate) {
    const Eigen::Vector2d& position = positions[candidate / headings];
    return geometry::Pose2{position.x(), position.y(),
                           geometry::normalize_angle(heading_offset +
                                                     static_cast<double>(candidate % headings) * heading_step)};
  };
  if (seed_scans_.size() > 1) {
    keep_best(parameters_.seed_search_pool_factor * parameters_.seed_search_candidates);
    seed_candidates_.resize(seed_order_.size());
    seed_chunk_scores_.resize(seed_order_.size());
    for (std::size_t j = 1; j < seed_scans_.size(); ++j) {
      const geometry::Pose2 moved = seed_scans_.front().odometry.between(seed_scans_[j].odometry);
      for (std::size_t i = 0; i < seed_order_.size(); ++i) {
        seed_candidates_[i].pose = candidate_pose(seed_order_[i]).compose(moved);
      }
      coarse_field.log_likelihoods(seed_candidates_, seed_scans_[j].beams, coarse, seed_chunk_scores_);
      for (std::size_t i = 0; i < seed_order_.size(); ++i) {
        seed_scores_[seed_order_[i]] += static_cast<float>(seed_chunk_scores_[i]);
      }
    }
  }

  const auto uniform = static_cast<std::size_t>(
      std::lround(parameters_.seed_search_uniform_share * static_cast<double>(search_particles_)));
  const std::size_t seeded = search_particles_ - std::min(uniform, search_particles_);
  keep_best(std::min(seeded, parameters_.seed_search_candidates));
  const std::size_t kept = seed_order_.size();
  // Where each kept candidate stands now, by odometry since the first scan.
  const geometry::Pose2 since_first = seed_scans_.front().odometry.between(seed_scans_.back().odometry);
  const PreparedBeams& last_beams = seed_scans_.back().beams;

  // Fine: each kept candidate moves to the best pose of a 3 x 3 x 3 grid
  // over its cell and heading step, scored at sigma_hit; its particles
  // spread over a fine step around that. Jittered over the whole coarse
  // cell instead, the truth's particles scored below lucky look-alikes
  // elsewhere and the search lost it more often (docs/amcl.md,
  // 2026-12-08); a 5 x 5 x 5 grid found no more and cost five times as much.
  constexpr int kFine = 3;
  const double fine_position = position_step / kFine;
  const double fine_heading = heading_step / kFine;
  LaserModelSettings fine = LaserModelSettings::from(parameters_);
  fine.beam_skip = false;
  std::vector<geometry::Pose2> refined(kept);
  constexpr std::size_t kChunkCandidates = 64;
  constexpr std::size_t kFinePoses = kFine * kFine * kFine;
  for (std::size_t first = 0; first < kept; first += kChunkCandidates) {
    const std::size_t count = std::min(kChunkCandidates, kept - first);
    seed_candidates_.resize(count * kFinePoses);
    for (std::size_t i = 0; i < count; ++i) {
      const geometry::Pose2 now = candidate_pose(seed_order_[first + i]).compose(since_first);
      std::size_t k = i * kFinePoses;
      for (int a = 0; a < kFine; ++a) {
        for (int b = 0; b < kFine; ++b) {
          for (int c = 0; c < kFine; ++c) {
            seed_candidates_[k++].pose = {now.x + (a - kFine / 2) * fine_position, now.y + (b - kFine / 2) * fine_position,
                                          geometry::normalize_angle(now.yaw + (c - kFine / 2) * fine_heading)};
          }
        }
      }
    }
    seed_chunk_scores_.resize(seed_candidates_.size());
    likelihood_field().log_likelihoods(seed_candidates_, last_beams, fine, seed_chunk_scores_);
    for (std::size_t i = 0; i < count; ++i) {
      const auto begin = seed_chunk_scores_.begin() + static_cast<std::ptrdiff_t>(i * kFinePoses);
      const auto best = std::max_element(begin, begin + static_cast<std::ptrdiff_t>(kFinePoses));
      refined[first + i] = seed_candidates_[i * kFinePoses + static_cast<std::size_t>(best - begin)].pose;
    }
  }

  particles_.resize(search_particles_);
  const double weight = 1.0 / static_cast<double>(particles_.size());
  for (std::size_t i = 0; i < particles_.size(); ++i) {
    Particle& particle = particles_[i];
    particle.weight = weight;
    if (i >= seeded || kept == 0) {
      particle.pose = free_space_.sample(rng_);
      continue;
    }
    const geometry::Pose2& centre = refined[i % kept];
    const double dx = (unit(rng_) - 0.5) * fine_position;
    const double dy = (unit(rng_) - 0.5) * fine_position;
    const double dyaw = (unit(rng_) - 0.5) * fine_heading;
    particle.pose = {centre.x + dx, centre.y + dy, geometry::normalize_angle(centre.yaw + dyaw)};
  }
  // The ranking's buffers are large (tens of MB on a large map) and used once per search.
  std::vector<float>().swap(seed_scores_);
  std::vector<std::uint32_t>().swap(seed_order_);
  std::vector<Particle>().swap(seed_candidates_);
  std::vector<double>().swap(seed_chunk_scores_);
  std::vector<SeedScan>().swap(seed_scans_);
}

bool AmclFilter::belief_uncertain() const {
  if (searching_ || clusters_.empty()) return false;
  const Eigen::Matrix3d& spread = clusters_.front().covariance;
  const double heading = std::sqrt(std::max(0.0, spread(2, 2)));
  const double position = std::sqrt(std::max(0.0, spread(0, 0) + spread(1, 1)));
  return (parameters_.uncertain_heading_deviation > 0.0 && heading > parameters_.uncertain_heading_deviation) ||
         (parameters_.uncertain_position_deviation > 0.0 && position > parameters_.uncertain_position_deviation);
}

void AmclFilter::leave_out_short_readings(const LaserScan& scan) {
  // The estimate as of now: the clusters were taken before this motion.
  const geometry::Pose2 estimate =
      clusters_.front().mean.compose(cluster_odometry_.between(particle_odometry_));
  const ReadingMargins margins{.short_of_map = parameters_.short_reading_margin,
                               .through_wall = parameters_.short_reading_through_wall_margin};
  if (!reading_classifier_) reading_classifier_ = std::make_unique<ReadingClassifier>(*map_);
  const BeamFits fits = reading_classifier_->classify_beams(estimate, beams_, margins);
  const bool estimate_doubted =
      static_cast<double>(fits.through_wall) >
      parameters_.short_reading_through_wall_share * static_cast<double>(fits.returned);
  if (fits.short_of_map == 0 || estimate_doubted) return;
  // Left out before subsampling, so the beams kept are the scan's readings
  // of the map, however few, not what survives of max_beams.
  reading_classifier_->mark_short_readings(estimate, scan, margins, 4 * parameters_.laser_max_beams,
                                           short_readings_);
  prepare_beams(scan, parameters_.laser_max_beams, beams_, &short_readings_);
}

void AmclFilter::resample() {
  ResampleSettings settings;
  settings.min_particles = parameters_.min_particles;
  settings.max_particles = searching_ ? search_particles_ : parameters_.max_particles;
  settings.kld_error = parameters_.kld_error;
  settings.kld_z = parameters_.kld_z;
  settings.bin_cell_size = parameters_.cluster_cell_size;
  settings.bin_angle_size = parameters_.cluster_angle_size;
  settings.injection_probability = recovery_.injection_probability();
  resampler_.resample(particles_, settings, &free_space_, rng_);
}

void AmclFilter::refresh_hypotheses() {
  clusterer_.cluster(particles_, parameters_.cluster_cell_size, parameters_.cluster_angle_size,
                     clusters_);
  cluster_odometry_ = particle_odometry_;
}

std::vector<Hypothesis> AmclFilter::hypotheses() const {
  const std::size_t count = std::min(clusters_.size(), parameters_.max_hypotheses);
  std::vector<Hypothesis> result(clusters_.begin(),
                                 clusters_.begin() + static_cast<std::ptrdiff_t>(count));
  double total = 0.0;
  for (const Hypothesis& h : result) total += h.weight;
  for (Hypothesis& h : result) {
    h.weight = total > 0.0 ? h.weight / total : 1.0 / static_cast<double>(result.size());
  }
  return result;
}

Hypothesis AmclFilter::best() const {
  const std::vector<Hypothesis> all = hypotheses();
  return all.empty() ? Hypothesis{} : all.front();
}

Hypothesis AmclFilter::predict(const geometry::Pose2& odometry) const {
  Hypothesis estimate = best();
  if (have_odometry_reference_) {
    estimate.mean = estimate.mean.compose(particle_odometry_.between(odometry));
  }
  return estimate;
}

}  // namespace playerkit::amcl
