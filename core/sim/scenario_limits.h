#pragma once
// The limits every scenario value is checked against (sim::checkScenario, docs/scenarios.md "Limits"),
// in the units of the scenario file. They are physical sense, not taste: a rate of 1e6 Hz asks for a
// sample every microsecond, a correlation time of 1e-300 s for a matrix exponential that overflows, a
// sweep of 0.1 us for a loop that never advances. Each kind of quantity has one range, used by every
// field of that kind; the few fields with a range of their own say why beside it.
#include <cstdint>

namespace reckoner::sim::limits {

struct Range {
  double lo = 0.0;
  double hi = 0.0;
  bool loOpen = false;  ///< (lo, hi] instead of [lo, hi]
  const char* unit = "";
};

// Run length and output.
inline constexpr double kMaxDurationS = 30.0 * 86400.0;   ///< a month: the longest scenario
inline constexpr Range kStepS{1e-3, 3600.0, false, "s"};  ///< filter output cycle
/// Rows a run may hold (one per step, one per track per sweep): about 1 GB of output.
inline constexpr double kMaxOutputRows = 5e6;

// Rates, correlation and time constants.
inline constexpr Range kRateHz{1e-4, 100.0, false, "Hz"};      ///< one sample per 2.8 h to 100 Hz
inline constexpr Range kBetaPerS{1e-7, 10.0, false, "1/s"};    ///< correlation 0.1 s to 116 days
inline constexpr Range kSweepPeriodS{0.1, 600.0, false, "s"};  ///< fast radar to slow sonar pings
inline constexpr Range kHoldS{0.0, 86400.0, false, "s"};       ///< hold and re-open delays
inline constexpr Range kSojournS{0.1, 1e7, false, "s"};        ///< IMM expected mode durations

// Kinematics.
inline constexpr double kMaxSpeedMps = 51.44;  ///< 100 kn: no surface craft is faster
inline constexpr Range kSpeedMps{0.0, kMaxSpeedMps, false, "m/s"};
inline constexpr Range kPositionM{-1e6, 1e6, false, "m"};             ///< within the grid frame's reach
inline constexpr Range kAccelerationMps2{0.0, 10.0, false, "m/s^2"};  ///< a ship manages under 1
inline constexpr Range kTurnRateDps{-30.0, 30.0, false, "deg/s"};     ///< fast craft turn at up to ~10
inline constexpr Range kHeadingDeg{-360.0, 720.0, false, "deg"};
inline constexpr Range kBearingDeg{-360.0, 720.0, false, "deg"};

// Noise: standard deviations (and variances as their squares).
inline constexpr Range kCurrentSdMps{0.0, 5.0, false, "m/s"};
inline constexpr Range kAccelSdMps2{0.0, 10.0, false, "m/s^2"};
inline constexpr Range kPositionSdM{1e-2, 1e4, false, "m"};       ///< a fix: 1 cm to 10 km
inline constexpr Range kMarkovPositionSdM{0.0, 1e4, false, "m"};  ///< a correlated fix error (0: none)
inline constexpr Range kVelocitySdMps{1e-3, 10.0, false, "m/s"};
inline constexpr Range kMarkovVelocitySdMps{0.0, 10.0, false, "m/s"};
inline constexpr Range kAngleSdDeg{1e-4, 45.0, false, "deg"};
inline constexpr Range kAngleErrorDeg{0.0, 45.0, false, "deg"};  ///< backlash, quanta, scatter (0: none)
inline constexpr Range kHeadingBiasSdDeg{0.0, 30.0, false,
                                         "deg"};          ///< a heading sensor's calibration (0: none)
inline constexpr Range kLogScaleSd{0.0, 0.2, false, ""};  ///< a log 20% wrong is broken (0: none)
inline constexpr Range kSignedAngleErrorDeg{-45.0, 45.0, false, "deg"};
inline constexpr Range kRangeSdM{1e-2, 1e4, false, "m"};
inline constexpr Range kRangeQuantumM{0.0, 1e4, false, "m"};
inline constexpr Range kInitialPositionSdM{1e-2, 1e6, false, "m"};
inline constexpr Range kInitialSpeedSdMps{1e-3, 100.0, false, "m/s"};

// Radar.
inline constexpr Range kRadarRangeNm{0.0, 200.0, true, "NM"};
inline constexpr Range kClutterPerKm2{0.0, 100.0, false, "per km^2 per sweep"};
/// Expected clutter plots in one sweep (density times area): beyond it a sweep is noise, and its cost.
inline constexpr double kMaxClutterPerSweep = 1e4;
inline constexpr Range kProbability{0.0, 1.0, false, ""};
inline constexpr Range kDistanceNm{0.0, 200.0, false, "NM"};
inline constexpr Range kTcpaMin{0.0, 1440.0, false, "min"};
inline constexpr double kMaxTrackCapacity = 1e4;  ///< tracks in the bank (MSC.192(79) asks for 40)

// Filter tuning.
inline constexpr Range kSpeedThresholdMps{0.0, 50.0, false, "m/s"};
inline constexpr Range kImmAccelQ{0.0, 1e4, true, "m^2/s^3"};
inline constexpr Range kImmTurnQDeg2{0.0, 1e4, false, "deg^2/s^3"};
inline constexpr Range kTurnSdDps{0.0, 90.0, true, "deg/s"};
inline constexpr Range kMatchingDistanceM{0.0, 1e4, true, "m"};

}  // namespace reckoner::sim::limits
