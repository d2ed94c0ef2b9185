#pragma once
// Where own ship may be over the next minutes if she holds her course and speed (the anti-grounding
// look-ahead of MSC.232(82) 11.4.4, with its uncertainty): the DRKF's ground position and velocity now
// and their joint covariance, carried straight on, plus the wander of a ship holding a course (a white
// acceleration of spectral density courseKeeping, so its spread grows as t^3 / 3). The spread grows
// with the look-ahead time through the velocity's uncertainty and is larger from the start when the
// filter is dead reckoning. Not the filter's own process model over the horizon: that allows for the
// manoeuvres a ship may make (turns of tens of degrees in six minutes), which the look-ahead is not
// about; it asks where the ship goes on her present course.
//   p_i(t) = p + v t + dp_i + dv_i t + sqrt(q t^3 / 3) w_i,
// (dp_i, dv_i) drawn from the joint covariance (so a course error opens the paths like a fan), w_i a
// 2-vector drawn once per path. The draws are the same standard normals at every call (a fixed
// stream): the probability of an event along the paths then changes smoothly with the estimate instead
// of jittering from call to call (docs/routes.md, "Anti-grounding").
#include <vector>

#include "estimation/gaussian.h"
#include "geo/local_frame.h"
#include "navigation/drkf.h"

namespace reckoner::nav {

struct LookAheadSettings {
  double horizonS = 360.0;  ///< the look-ahead time (MSC.232(82): a setting; 6 minutes by default)
  double stepS = 20.0;      ///< between predicted points (the paths are all but straight between them)
  /// Sampled paths: 1000 put a probability of 2.3% (2 sd) at 23 +- 5 paths, so that the 5% alert is
  /// not reached by the sampling's noise.
  int samples = 1000;
  /// The course keeping's white acceleration, m^2/s^3 per axis: how far a ship holding a course and
  /// speed strays from them (2e-5: 17 m sd after six minutes, a heading held to some half a degree and
  /// a speed to 0.1 kn at 10 kn).
  double courseKeepingM2S3 = 2e-5;
  /// What makes the settings unusable, one line each (empty: none).
  [[nodiscard]] std::vector<std::string> problems() const;
  friend bool operator==(const LookAheadSettings&, const LookAheadSettings&) = default;
};

struct LookAheadPrediction {
  TimeUs t0Us = 0;
  std::vector<double> timesS;                      ///< 0, stepS, ..., horizonS
  std::vector<geo::GridPoint> mean;                ///< predicted position at each time
  std::vector<est::Mat<2>> covariance;             ///< its covariance (grid x, y; m^2)
  std::vector<std::vector<geo::GridPoint>> paths;  ///< samples x times
  bool valid = false;  ///< false when the prediction failed (non-finite): everything else empty
};

/// The look-ahead from the filter's belief at its time. Throws std::invalid_argument for settings
/// with problems().
LookAheadPrediction predictLookAhead(const Drkf& filter, const LookAheadSettings& settings);

}  // namespace reckoner::nav
