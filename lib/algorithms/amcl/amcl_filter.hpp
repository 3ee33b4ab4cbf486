#pragma once
// Adaptive Monte-Carlo localization (Fox 2001; Probabilistic Robotics ch. 8):
// a particle filter over the robot's pose in a known occupancy map, moved by
// odometry, weighted by laser scans, resampled with KLD-sampling for an
// adaptive particle count, with augmented MCL's random particles for
// recovery from a wrong or lost estimate. Deterministic for a given seed
// and input sequence.

#include "algorithms/amcl/amcl_parameters.hpp"
#include "algorithms/amcl/augmented_recovery.hpp"
#include "algorithms/amcl/beam_model.hpp"
#include "algorithms/amcl/laser_scan.hpp"
#include "algorithms/amcl/likelihood_field_model.hpp"
#include "algorithms/amcl/particle_set.hpp"
#include "algorithms/amcl/pose_estimate.hpp"
#include "algorithms/amcl/short_readings.hpp"
#include "algorithms/geometry/pose2.hpp"
#include "algorithms/grid/occupancy_grid.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <memory>
#include <optional>
#include <random>
#include <span>
#include <vector>

namespace playerkit::amcl {

// A pose and its uncertainty (x, y, yaw: m^2, rad^2) to start from.
struct StartPose {
  geometry::Pose2 mean;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Identity();
};

class AmclFilter {
 public:
  // Starts at `start` when given (set_pose), else with a global search
  // (set_global()); the particles are drawn once. Throws
  // std::invalid_argument for invalid parameters or a map without free
  // cells.
  AmclFilter(AmclParameters parameters, std::shared_ptr<const grid::OccupancyGrid> map,
             std::uint64_t seed, const std::optional<StartPose>& start = std::nullopt);

  // max_particles drawn from N(mean, covariance) over (x, y, yaw).
  void set_pose(const geometry::Pose2& mean, const Eigen::Matrix3d& covariance);
  // max_particles drawn from N(mean, covariance) ends a global search.
  // A global search: global_particles() uniform over free cells with
  // uniform yaw, searched as AmclParameters' "global start" says. On a map
  // they cover thinly, the first scan with returns then puts all but a
  // share of them where it fits (seed_search_* parameters).
  void set_global();
  // What a global start draws: global_particles_per_square_metre of the
  // map's free area, clamped to [max_particles, global_particles_most].
  std::size_t global_particles() const;
  // True from set_global() until one cluster holds the belief.
  bool searching() const { return searching_; }
  // True from set_global() until the first scan seeds the search, when the
  // map is too large for a dense uniform draw (seed_search_below_density).
  bool seed_search_pending() const { return seed_search_pending_; }

  // Feed odometry (robot pose in the odometry frame) and optionally the scan
  // taken at that pose. The first call (and the first after set_pose or
  // set_global) only records the odometry origin — no motion — though it
  // runs a laser update if it carries a scan. Later calls run motion, laser
  // update and (every resample_interval updates, or on an effective sample
  // size drop) resampling once the robot has moved more than
  // update_min_distance or turned more than update_min_angle since the last
  // laser update, or while the belief is too uncertain to wait for that
  // (AmclParameters' uncertain_* settings). Without a scan, motion past those thresholds is still
  // applied, so odometry does not pile up. Returns true when a laser update
  // ran.
  bool update(const geometry::Pose2& odometry, const LaserScan* scan);

  // Clusters heaviest first, at most max_hypotheses; weights sum to 1.
  std::vector<Hypothesis> hypotheses() const;
  Hypothesis best() const;
  // best() carried forward by the odometry delta from where the particles
  // last moved to `odometry` (for publishing "now" while scans queue up).
  Hypothesis predict(const geometry::Pose2& odometry) const;

  std::span<const Particle> particles() const { return particles_; }
  const AmclParameters& parameters() const { return parameters_; }
  // Takes effect from the next update (Player 1.5's live set config).
  void set_parameters(const AmclParameters& parameters);
  // Laser updates run so far.
  std::size_t update_count() const { return update_count_; }
  // 1 - w_fast / w_slow as of the last laser update (0 when recovery is off).
  double injection_probability() const { return recovery_.injection_probability(); }

 private:
  void move_particles(const geometry::Pose2& odometry);
  void laser_update(const LaserScan& scan);
  void leave_out_short_readings(const LaserScan& scan);
  void resample();
  void refresh_hypotheses();
  void end_search_once_found();
  void apply_recovery_rates();
  // The heaviest cluster is wider than the uncertain_* deviations: the next
  // scan updates without waiting for motion.
  bool belief_uncertain() const;
  LikelihoodFieldModel& likelihood_field();
  BeamModel& beam_model();
  void restart();
  // Keeps the prepared beams for the seed search; once they span
  // seed_search_distance of travel, replaces the uniform draw by the
  // candidates on a coarse grid of poses that best fit them all
  // (AmclParameters' seed_search_*).
  void gather_seed_evidence();
  void seed_search_from_scans();

  AmclParameters parameters_;
  std::shared_ptr<const grid::OccupancyGrid> map_;
  std::mt19937_64 rng_;
  FreeSpaceSampler free_space_;
  std::unique_ptr<BeamModel> beam_model_;  // built on first use
  std::unique_ptr<LikelihoodFieldModel> likelihood_field_;  // built on first use
  std::unique_ptr<ReadingClassifier> reading_classifier_;  // built on first use
  AugmentedRecovery recovery_;
  AdaptiveResampler resampler_;
  PoseClusterer clusterer_;

  std::vector<Particle> particles_;
  std::vector<double> log_likelihoods_;
  PreparedBeams beams_;
  std::vector<unsigned char> short_readings_;  // per reading of the scan being used
  std::vector<Hypothesis> clusters_;  // every cluster, heaviest first

  bool have_odometry_reference_ = false;
  bool laser_update_pending_ = true;  // the next scan updates regardless of motion
  geometry::Pose2 particle_odometry_;  // odometry the particles were last moved to
  geometry::Pose2 laser_odometry_;     // odometry at the last laser update
  geometry::Pose2 cluster_odometry_;   // odometry the clusters were taken at
  std::size_t update_count_ = 0;
  std::size_t unmoved_updates_ = 0;  // laser updates in a row short of the motion thresholds
  bool searching_ = false;
  std::size_t search_particles_ = 0;  // KLD's ceiling while searching
  std::size_t found_updates_ = 0;     // laser updates in a row the search's end held
  bool seed_search_pending_ = false;
  std::vector<Particle> seed_candidates_;  // a chunk of the seed search's poses
  std::vector<double> seed_chunk_scores_;
  std::vector<float> seed_scores_;          // every candidate's, for ranking
  std::vector<std::uint32_t> seed_order_;
  struct SeedScan {
    PreparedBeams beams;
    geometry::Pose2 odometry;  // where the particles' odometry stood at this scan
  };
  std::vector<SeedScan> seed_scans_;  // the evidence gathered so far
  double seed_travel_ = 0.0;          // m of odometry path across seed_scans_
};

}  // namespace playerkit::amcl
