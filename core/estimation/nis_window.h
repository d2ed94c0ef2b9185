#pragma once
// Online consistency of one measurement stream: NIS summed over windows of a fixed number of updates,
// each window's sum tested against its chi-square band (sum of `updates` NIS values of their degrees of
// freedom). A window above the band says the innovations are larger than the filter's S: the sensor's
// noise (or the process) is larger than configured; below, smaller. Gated-out updates count too: a
// sensor rejected by its gate is the clearest case of noise larger than configured.
#include <cmath>

#include "estimation/chi_square.h"

namespace reckoner::est {

struct NisWindowCounts {
  long windows = 0;  ///< completed windows
  long above = 0;    ///< ... whose NIS sum lay above the band
  long below = 0;    ///< ... below it
  double nisSum = 0.0;
  long dof = 0;  ///< over every NIS added
  [[nodiscard]] double meanPerDof() const { return dof > 0 ? nisSum / static_cast<double>(dof) : NAN; }
};

class NisWindow {
 public:
  /// updates per window; the band holds `probability` of a consistent filter's window sums.
  NisWindow() = default;
  NisWindow(int updates, double probability) : size_(updates), p_(probability) {}

  /// Adds one update's NIS of `dof` degrees of freedom (ignored when not finite or dof < 1).
  void add(double nis, int dof) {
    if (!std::isfinite(nis) || dof < 1) return;
    counts_.nisSum += nis;
    counts_.dof += dof;
    sum_ += nis;
    windowDof_ += dof;
    if (++n_ < size_) return;
    const double k = static_cast<double>(windowDof_);
    ++counts_.windows;
    lastAbove_ = sum_ > chiSquareQuantile(0.5 + 0.5 * p_, k);
    if (lastAbove_) ++counts_.above;
    if (sum_ < chiSquareQuantile(0.5 - 0.5 * p_, k)) ++counts_.below;
    n_ = 0;
    sum_ = 0.0;
    windowDof_ = 0;
  }
  [[nodiscard]] const NisWindowCounts& counts() const { return counts_; }
  /// The most recent completed window lay above the band (false before the first).
  [[nodiscard]] bool lastAbove() const { return lastAbove_; }

 private:
  int size_ = 60;
  double p_ = 0.99;
  int n_ = 0;
  double sum_ = 0.0;
  long windowDof_ = 0;
  bool lastAbove_ = false;
  NisWindowCounts counts_;
};

}  // namespace reckoner::est
