#pragma once
// Seed 001: the relative-state EKF with range and bearing, and manoeuvre detection and correction by
// input estimation (eqs. 14 to 29, after Bar-Shalom and Li). The filter runs the non-manoeuvring
// model; over a sliding window of the last s updates it estimates a constant target acceleration u by
// weighted least squares from the innovations, declares a manoeuvre when d(u) = u^T L^-1 u passes the
// chi-square threshold for the chosen false-alarm probability, and then corrects the state by M u and
// the covariance by M L M^T. The manoeuvre ends when the estimate is no longer significant.
// Besides the paper's correction, a declared manoeuvre can instead be corrected by re-filtering the
// window from its start with a velocity jump at the most likely time (Correction::Refilter): the
// window's evidence is used once, with the right geometry, where M u spreads a constant acceleration
// over the whole window.
// Deviations from the printed equations, with reasons, are in docs/manoeuvres.md.
#include <cstdint>
#include <deque>
#include <optional>
#include <string>

#include "common/angles.h"
#include "common/time.h"
#include "estimation/models/relative_polar.h"
#include "estimation/update_report.h"
#include "tracking/input_window.h"

namespace reckoner::track {

namespace rp = est::relpolar;

struct InputEstimationConfig {
  double bearingSdRad = degToRad(1.0);  ///< 1 degree
  double rangeSdM = 20.0;
  double processNoiseQ = 1e-6;  ///< white-acceleration spectral density of the target, m^2/s^3
  int window = 2;               ///< s, sliding window length (>= 1)
  /// Eq. 27 asks for 1e-2 or smaller (threshold 9.21 for 2 dof); section IV quotes the 90% point,
  /// 4.61 (docs/manoeuvres.md).
  double falseAlarmProbability = 0.01;
  /// The initial covariance: seed 001 eq. 32 (each state uniform on +-its initial value: x^2 / 3), or
  /// the covariance of the two-point difference itself (docs/manoeuvres.md).
  bool paperInitialCovariance = false;
  enum class Correction : std::uint8_t {
    None,      ///< the EKF alone: d(u) is computed and reported, nothing is declared or corrected
    Paper,     ///< x += M u, P += M L M' (eqs. 28 and 29)
    Refilter,  ///< the window again from its start, with a velocity jump at the likeliest time
  };
  Correction correction = Correction::Refilter;
  double jumpSdMps = 4.0;  ///< Refilter: sd of the velocity jump per axis (the prior of its size)
  /// Empty when valid, else the problem.
  [[nodiscard]] std::string check() const;
};

/// The outcome of one measurement.
struct InputEstimationStep {
  TimeUs timeUs = 0;
  est::UpdateReport<2> update;
  bool tested = false;                  ///< a full window was available
  double d = 0.0;                       ///< d(u) of eq. 25 (0 when not tested)
  est::Vec<2> u = est::Vec<2>::Zero();  ///< estimated acceleration, m/s^2 (east, north)
  bool detected = false;                ///< d >= threshold: the state was corrected
  bool manoeuvring = false;             ///< the filter's flag after this step
};

class InputEstimationEkf {
 public:
  /// Throws std::invalid_argument for an invalid configuration.
  explicit InputEstimationEkf(const InputEstimationConfig& config);

  /// One measurement (true bearing, range) at t with the observer's position (east, north, m) at t.
  /// The first measurement is only stored; the second initialises the state (eqs. 30 to 32); later
  /// ones run predict, update and input estimation.
  InputEstimationStep measure(TimeUs t, double bearingRad, double rangeM, double observerXM,
                              double observerYM);

  [[nodiscard]] bool initialised() const { return belief_.has_value(); }
  [[nodiscard]] const est::Gaussian<rp::kStateDim>& belief() const { return *belief_; }
  [[nodiscard]] bool manoeuvring() const { return manoeuvring_; }
  [[nodiscard]] double threshold() const { return threshold_; }
  [[nodiscard]] const InputEstimationConfig& config() const { return config_; }

 private:
  struct Sample {
    TimeUs timeUs;
    double bearingRad, rangeM, observerXM, observerYM;
  };
  /// Eqs. 30 to 32: the state from two measurements (position from the second, velocity from the
  /// difference), first before second.
  [[nodiscard]] est::Gaussian<rp::kStateDim> twoPointInitiation(const Sample& first,
                                                                const Sample& second) const;
  /// Predict (eqs. 2 to 4, 10), update (eqs. 11 to 13) and input estimation with a later sample. The
  /// belief becomes the prediction, updated when the update is accepted; a rejected update empties
  /// the window.
  void filterSample(InputEstimationStep& step, const Sample& to);
  void estimateInput(InputEstimationStep& step);
  /// Predicts g from one sample's time to the next's (the observer's displacement included); with a
  /// jump fraction f, a velocity jump (jumpSdMps) happens at from + f (to - from).
  [[nodiscard]] bool predict(est::Gaussian<rp::kStateDim>& g, const Sample& from, const Sample& to,
                             std::optional<double> jumpFraction) const;
  /// Correction::Refilter; false (nothing changed) when no hypothesis could be filtered.
  bool refilterWindow();

  InputEstimationConfig config_;
  double threshold_ = 0.0;
  std::optional<est::Gaussian<rp::kStateDim>> belief_;
  std::optional<Sample> previous_;
  InputWindow<rp::kStateDim> window_;
  /// Per window entry: the update's samples and the belief before it (Refilter).
  struct Stored {
    Sample from, to;
    est::Gaussian<rp::kStateDim> before;
  };
  std::deque<Stored> stored_;
  bool manoeuvring_ = false;
};

}  // namespace reckoner::track
