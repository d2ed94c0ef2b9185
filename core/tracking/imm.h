#pragma once
// An interacting multiple model filter (Blom and Bar-Shalom) with two modes, constant velocity and
// coordinated turn (estimation/models/coordinated_turn.h), updated with radar plots (range, true
// bearing from a known own-ship position): the modern baseline that tracking frameworks offer, for
// comparison with seed 001's input estimation and seed 003's alpha-beta-gamma (docs/manoeuvres.md).
// Mode transitions follow expected sojourn times: p_ii = exp(-dt / tau_i) for the interval dt.
#include <array>
#include <string>

#include "common/time.h"
#include "estimation/models/coordinated_turn.h"
#include "estimation/update_report.h"

namespace reckoner::track {

struct ImmConfig {
  double rangeSdM = 20.0;
  double bearingSdRad = 0.008726646259971648;  ///< 0.5 degree
  double cvAccelQ = 0.001;                     ///< CV white-acceleration density, m^2/s^3
  double ctAccelQ = 0.01;                      ///< CT white-acceleration density, m^2/s^3
  double ctTurnQ = 1e-6;                       ///< CT turn-rate random walk, rad^2/s^3
  double cvSojournS = 300.0;                   ///< expected time in constant velocity
  double ctSojournS = 60.0;                    ///< expected time in a turn
  double initialSpeedSdMps = 10.0;
  double initialTurnSdRadPerS = 0.02;       ///< about 1.1 deg/s
  double manoeuvreProbability = 0.5;        ///< the manoeuvre flag: CT probability above this
  [[nodiscard]] std::string check() const;  ///< empty when valid
};

class ImmTracker {
 public:
  enum Mode : int { kCv = 0, kCt = 1, kModes = 2 };

  /// Throws std::invalid_argument for an invalid configuration.
  explicit ImmTracker(const ImmConfig& config);

  /// A plot: true bearing and range from own ship at (ownX, ownY), grid frame (the bearing given
  /// relative to grid north), with the configured noise. The first plot initialises the position with
  /// zero mean velocity and initialSpeedSdMps. Returns the combined update's NIS (NaN when nothing was
  /// applied).
  double update(TimeUs t, double bearingRad, double rangeM, double ownXM, double ownYM);

  /// Starts at t from a position estimate (grid metres) with zero mean velocity (initialSpeedSdMps)
  /// and the turn rate's prior.
  void initialise(TimeUs t, const est::Vec<2>& position, const est::Mat<2>& positionCov);
  /// One IMM cycle with the plot's own noise R (bearing, range: rad^2, m^2, possibly correlated).
  /// gate > 0: the plot is refused (state unchanged) when the NIS of the combined prediction
  /// exceeds it. The report carries that combined innovation, its S and NIS.
  est::UpdateReport<2> updatePlot(TimeUs t, double bearingRad, double rangeM, double ownXM, double ownYM,
                                  const est::Mat<2>& R, double gate);
  /// The combined estimate predicted to t (no change; t before the filter time: the current one).
  [[nodiscard]] est::Gaussian<est::ct::kStateDim> predicted(TimeUs t) const;
  [[nodiscard]] TimeUs timeUs() const { return timeUs_; }

  [[nodiscard]] bool initialised() const { return initialised_; }
  /// The combined estimate (moment-matched over the modes).
  [[nodiscard]] est::Gaussian<est::ct::kStateDim> combined() const;
  [[nodiscard]] const std::array<double, kModes>& modeProbabilities() const { return mu_; }
  [[nodiscard]] bool manoeuvring() const { return mu_[kCt] > config_.manoeuvreProbability; }

 private:
  struct Prediction {
    std::array<est::Gaussian<est::ct::kStateDim>, kModes> modes{};
    std::array<double, kModes> cbar{};
    bool ok = false;
  };
  /// Mixing and the mode-matched predictions over dt >= 0.
  [[nodiscard]] Prediction predictModes(double dt) const;
  static est::Gaussian<est::ct::kStateDim> combine(
      const std::array<est::Gaussian<est::ct::kStateDim>, kModes>& m, const std::array<double, kModes>& w);

  ImmConfig config_;
  bool initialised_ = false;
  TimeUs timeUs_ = 0;
  std::array<est::Gaussian<est::ct::kStateDim>, kModes> modes_{};
  std::array<double, kModes> mu_{0.9, 0.1};
};

}  // namespace reckoner::track
