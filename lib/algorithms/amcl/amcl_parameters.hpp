#pragma once
// Every tunable of the Monte-Carlo localization filter. Names say what they
// do; each comment gives Player 1.5's configuration name (or ROS amcl's, for
// what 1.5 lacked) so old configuration files translate one to one.

#include <cstddef>
#include <numbers>

namespace playerkit::amcl {

enum class LaserModelType { beam, likelihood_field };
enum class MotionModelType { differential, omni };

struct AmclParameters {
  // --- particle count (KLD-sampling, Fox 2001) ---
  std::size_t min_particles = 100;   // 1.5: pf_min_samples (100)
  std::size_t max_particles = 5000;  // 1.5: pf_max_samples (10000 in 1.5; ROS's 5000 here)
  double kld_error = 0.01;           // 1.5: pf_err (0.01)
  double kld_z = 3.0;                // 1.5: pf_z (3), upper standard normal quantile

  // --- recovery by augmented MCL (Probabilistic Robotics table 8.3) ---
  // Decay rates of the slow and fast averages of the measurement likelihood;
  // 0 and 0 disable random-particle injection. ROS: recovery_alpha_slow/fast.
  // Off by default, as in ROS: on real logs (Radish Intel) a scan full of
  // people makes any belief look lost, and the random particles it brings
  // in win in look-alike corridors. Turn it on (0.001, 0.1) for kidnapping.
  double alpha_slow = 0.0;
  double alpha_fast = 0.0;

  // --- global start (set_global()): a search of the whole free space ---
  // Until one place holds the belief, a global start needs particles near
  // the true pose in every look-alike corridor, not max_particles spread
  // over a building (5000 over Radish Edmonton's 1000 m^2 found it in 3
  // runs of 6). So it draws global_particles_per_square_metre of free
  // space (at least max_particles, at most global_particles_most unless
  // max_particles is more), keeps KLD-sampling's ceiling there, and brings
  // in random particles with search_alpha_slow/search_alpha_fast where
  // alpha_slow/alpha_fast are 0. The search ends, and max_particles and the
  // configured recovery take over, once one cluster has held
  // search_end_weight of the belief within search_end_spread (its
  // position's standard deviation, m) for search_end_updates laser updates
  // in a row. On the six Radish logs, six perturbed logs each, four sets of
  // filter seeds (docs/amcl.md): 200 per m^2 found the robot in 144 runs
  // of 144, 150 in 143 of 144, 100 in 106 of 108; ending the search at the
  // first such update instead of the 30th left 3 of 36 locked in a wrong
  // place. Not in 1.5 or ROS, which draw pf_max_samples / max_particles and
  // leave recovery as configured; 0 particles per m^2 and 0 search rates
  // give theirs.
  double global_particles_per_square_metre = 200.0;
  std::size_t global_particles_most = 100000;
  double search_alpha_slow = 0.001;
  double search_alpha_fast = 0.1;
  double search_end_weight = 0.9;
  double search_end_spread = 0.5;
  std::size_t search_end_updates = 30;
  // The search starts where the first scan fits (coarse to fine). On a map
  // too large for global_particles_most to cover densely, Player 1.5's
  // uniform draw leaves about 5 particles per m^2, one per 70 degrees, on a
  // 150 m office floor, and the filter locks onto some other corridor (0
  // of 12 runs converged on two such floors, docs/amcl.md 2026-12-08).
  // Instead the first scan with returns scores a grid of candidate poses
  // over all free space, seed_search_position_step apart (m) at every
  // seed_search_heading_step (rad), with the likelihood field widened by
  // half a step (sigma_hit and seed_search_position_step / 2 added in
  // quadrature) so that a candidate up to half a step off the true pose
  // still scores as the place it is. The seed_search_candidates best each
  // move to the best pose of a 3 x 3 x 3 grid over their cell and heading
  // step at sigma_hit, and the search's particles spread a third of a
  // step around those, but for seed_search_uniform_share that stays
  // uniform in case the scan misleads (people, an open door). The
  // filter's own updates then pick among them as the robot moves. With
  // seed_search_distance above 0 the search waits until the robot has
  // travelled that far (or seed_search_scans_most scans) and ranks the
  // seed_search_pool_factor * seed_search_candidates best of the first
  // scan by every scan since, each where odometry moved it: more evidence
  // against look-alikes, at the price of a later start (on the test floors
  // 4 m converged in 24 runs of 24 as 0 m did, after 4-13 m instead of
  // 0-7 m). It runs when the uniform draw would be thinner than
  // seed_search_below_density particles per m^2 (the bundled logs were
  // measured to need 100-200: "global start" above); 0 for
  // seed_search_position_step turns it off (1.5's and ROS's uniform
  // start). Not in 1.5 or ROS: correlative scan matching (Olson 2009) as
  // the proposal of the first particles, in the spirit of Thrun, Fox and
  // Burgard's mixture MCL, which draws particles from the scan.
  double seed_search_position_step = 0.5;
  double seed_search_heading_step = 10.0 * std::numbers::pi / 180;
  std::size_t seed_search_candidates = 10000;
  double seed_search_distance = 0.0;  // m
  std::size_t seed_search_scans_most = 40;
  std::size_t seed_search_pool_factor = 5;
  double seed_search_uniform_share = 0.1;
  double seed_search_below_density = 100.0;

  // --- motion model (Probabilistic Robotics table 5.6) ---
  // Each is a variance coefficient: e.g. the translation's standard deviation
  // is sqrt(translation_noise_from_translation * d^2 + ...), applied once per
  // filter update (every ~0.2 m). ROS uses 0.2 for all five; that gives a
  // 0.2 m step 13 degrees of heading noise and a 30 degree turn 12 cm of
  // position noise, which spreads the particles on every turn for no gain.
  // These defaults still allow ~45% error on a turn and ~30% on a distance,
  // ample for uncalibrated wheel odometry, but only ~5 degrees of heading
  // and ~5 cm of position per 0.2 m step or 30 degree turn from the cross
  // terms. A move longer than two update_min_distance (or update_min_angle)
  // counts as so many moves of two: its variance grows with its
  // length, not its square (motion_model.hpp), so a log that keeps a scan
  // every few metres is not spread wider than one that keeps many.
  MotionModelType motion_model = MotionModelType::differential;  // ROS: odom_model_type
  double rotation_noise_from_rotation = 0.2;         // alpha1, ROS: odom_alpha1 (rad^2/rad^2)
  double rotation_noise_from_translation = 0.02;     // alpha2, ROS: odom_alpha2 (rad^2/m^2)
  double translation_noise_from_translation = 0.1;   // alpha3, ROS: odom_alpha3 (m^2/m^2)
  double translation_noise_from_rotation = 0.01;     // alpha4, ROS: odom_alpha4 (m^2/rad^2)
  double strafe_noise_from_translation = 0.1;        // alpha5, ROS: odom_alpha5 (omni only)

  // --- laser model (Probabilistic Robotics ch. 6) ---
  LaserModelType laser_model = LaserModelType::likelihood_field;  // ROS: laser_model_type
  std::size_t laser_max_beams = 30;  // 1.5: laser_max_samples (5 in 1.5); ROS: laser_max_beams
  double z_hit = 0.95;               // ROS: laser_z_hit
  double z_short = 0.1;              // ROS: laser_z_short (beam model only)
  double z_max = 0.05;               // ROS: laser_z_max (beam model only)
  double z_rand = 0.05;              // ROS: laser_z_rand
  double sigma_hit = 0.2;            // ROS: laser_sigma_hit (m)
  double lambda_short = 0.1;         // ROS: laser_lambda_short (1/m)
  double likelihood_max_distance = 2.0;  // ROS: laser_likelihood_max_dist (m)
  // Likelihood field only: a beam that too few particles can explain (it hit
  // a person or an open door the map does not have) is left out for every
  // particle, so that one unmapped obstacle cannot pull the belief to some
  // other place that happens to fit. A beam counts as explained for a
  // particle when its end lies within beam_skip_distance of an obstacle; it
  // is skipped when less than beam_skip_threshold of the weight explains it,
  // unless more than beam_skip_error_threshold of the beams would go (the
  // belief is wrong, not the scan). ROS: do_beamskip, beam_skip_distance,
  // beam_skip_threshold, beam_skip_error_threshold.
  bool beam_skip = true;
  double beam_skip_distance = 0.5;
  double beam_skip_threshold = 0.3;
  double beam_skip_error_threshold = 0.4;
  // While tracking (the belief mostly in one place, no global search), a
  // returned beam is left out, for both models, when from the estimate the map
  // is free along it out to its range plus short_reading_margin: something the
  // map does not have cut it short (short_readings.hpp; Fox, Burgard and
  // Thrun's distance filter). Unlike beam skipping this holds however much of
  // the scan goes, so a crowd hiding most of it for many scans cannot pull the
  // track away; a scan with nothing left only moves the particles. Beams that
  // run long (past a mapped wall by more than short_reading_through_wall_margin)
  // stay: they are the evidence against a wrong estimate, and when more than
  // short_reading_through_wall_share of the returned beams do, the estimate
  // is in doubt (a kidnapped robot) and nothing is left out. Not in 1.5 or
  // ROS.
  bool short_reading_filter = true;
  double short_reading_margin = 0.2;               // m
  double short_reading_through_wall_margin = 0.5;  // m
  double short_reading_through_wall_share = 0.2;
  // A scan weighs a particle by p(scan | pose)^scan_likelihood_exponent.
  // The models multiply beams as if independent; neighbouring beams are not
  // (one wall, one map error), so the plain product is overconfident: from a
  // global start one scan leaves a handful of particles, and tracking turns
  // brittle. An exponent below 1 counts the scan as fewer independent beams
  // (Probabilistic Robotics 6.3.4 suggests exactly this kind of damping).
  // 1 gives the textbook product. Not in 1.5 or ROS (ROS sums cubes instead).
  double scan_likelihood_exponent = 0.2;
  // The same for the beam model, which needs more damping: its beam
  // likelihoods are far steeper (a beam along a wall changes its expected
  // range by metres for a degree of heading, where the likelihood field
  // moves its endpoint by centimetres). At 0.2 it tracked Intel at
  // 0.125-0.311 m with 111 lost episodes over six seeds; at 0.07 it tracks
  // every bundled log better than the likelihood field but CSAIL
  // (docs/amcl.md).
  double beam_scan_likelihood_exponent = 0.07;

  // --- when to update (1.5: update_thresh [0.2 m, 30 deg]; not in the manual's table) ---
  double update_min_distance = 0.2;  // m; ROS: update_min_d
  double update_min_angle = std::numbers::pi / 6.0;  // rad; ROS: update_min_a
  // While the heaviest cluster is wider than this (heading standard
  // deviation, rad; or position, m), every scan updates, moved or not. A
  // fast turn spreads the particles over tens of degrees and one damped
  // scan cannot pull them in; waiting for the next 0.2 m or 30 degrees left
  // the estimate that far off for seconds while the robot crept or stood
  // (a 64 degree turn in a corridor stayed 80 degrees off for 9 s). Each
  // scan is a new reading, so counting it is not counting one twice; a
  // settled belief goes back to the motion thresholds. 0 turns it off
  // (1.5 and ROS update on motion only). Not used while a global start
  // searches: that search is paced by motion (search_end_updates). At most
  // uncertain_updates_most such scans in a row, then motion is needed
  // again: a robot standing still resamples without the motion model's
  // spread, and a cloud resampled on and on without it thins out to a few
  // copies of itself.
  double uncertain_heading_deviation = 8.0 * std::numbers::pi / 180;
  double uncertain_position_deviation = 0.3;
  std::size_t uncertain_updates_most = 5;

  // --- resampling ---
  std::size_t resample_interval = 2;  // resample every N laser updates; ROS: resample_interval
  // Resample only when the effective sample size falls below half the
  // particle count (Doucet); overrides resample_interval when on.
  bool selective_resampling = false;  // ROS (nav2): selective_resampling

  // --- pose estimate (clustering, also the KLD histogram's bins) ---
  double cluster_cell_size = 0.5;                             // m
  double cluster_angle_size = 10.0 * std::numbers::pi / 180;  // rad
  std::size_t max_hypotheses = 10;  // the localize interface carries at most 10
};

// Throws std::invalid_argument naming the first parameter that makes no sense
// (e.g. min_particles > max_particles, a non-positive bin size).
void validate(const AmclParameters& parameters);

}  // namespace playerkit::amcl
