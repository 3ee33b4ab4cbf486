#include "algorithms/amcl/augmented_recovery.hpp"

#include <algorithm>
#include <cmath>

namespace playerkit::amcl {
namespace {

// log((1 - alpha) exp(log_average) + alpha exp(log_sample)), without leaving
// the log domain.
double blend_log(double log_average, double log_sample, double alpha) {
  if (alpha >= 1.0) return log_sample;
  const double a = std::log1p(-alpha) + log_average;
  const double b = std::log(alpha) + log_sample;
  const double high = std::max(a, b);
  return high + std::log1p(std::exp(std::min(a, b) - high));
}

}  // namespace

AugmentedRecovery::AugmentedRecovery(double alpha_slow, double alpha_fast)
    : alpha_slow_(alpha_slow), alpha_fast_(alpha_fast) {}

void AugmentedRecovery::set_rates(double alpha_slow, double alpha_fast) {
  alpha_slow_ = alpha_slow;
  alpha_fast_ = alpha_fast;
}

void AugmentedRecovery::reset() {
  initialised_ = false;
  log_slow_ = log_fast_ = 0.0;
}

void AugmentedRecovery::observe(double log_average_likelihood) {
  if (!enabled() || !std::isfinite(log_average_likelihood)) return;
  if (!initialised_) {
    // Starting both averages at the first sample (rather than at 0, as the
    // book does) avoids a burst of random particles while they warm up.
    log_slow_ = log_fast_ = log_average_likelihood;
    initialised_ = true;
    return;
  }
  log_slow_ = blend_log(log_slow_, log_average_likelihood, alpha_slow_);
  log_fast_ = blend_log(log_fast_, log_average_likelihood, alpha_fast_);
}

double AugmentedRecovery::injection_probability() const {
  if (!enabled() || !initialised_) return 0.0;
  return std::max(0.0, 1.0 - std::exp(log_fast_ - log_slow_));
}

}  // namespace playerkit::amcl
