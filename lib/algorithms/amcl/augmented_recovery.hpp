#pragma once
// Augmented MCL's recovery rule (Probabilistic Robotics table 8.3): a slow
// and a fast exponential average of the measurement likelihood; when the
// fast one drops below the slow one the robot has likely been kidnapped or
// lost, and a fraction 1 - w_fast / w_slow of the resampled particles is
// replaced by random poses.
//
// Likelihoods here are in the log domain: a product over dozens of beams
// under- or overflows a double long before the averages mean anything.

namespace playerkit::amcl {

class AugmentedRecovery {
 public:
  AugmentedRecovery(double alpha_slow, double alpha_fast);

  void set_rates(double alpha_slow, double alpha_fast);
  // Forget the averages (e.g. after a new initial pose).
  void reset();
  // Feed the log of the average measurement likelihood of one update.
  void observe(double log_average_likelihood);
  // max(0, 1 - w_fast / w_slow); 0 while disabled or before any observation.
  double injection_probability() const;

  bool enabled() const { return alpha_slow_ > 0.0 && alpha_fast_ > 0.0; }
  double log_slow() const { return log_slow_; }
  double log_fast() const { return log_fast_; }

 private:
  double alpha_slow_;
  double alpha_fast_;
  bool initialised_ = false;
  double log_slow_ = 0.0;
  double log_fast_ = 0.0;
};

}  // namespace playerkit::amcl
