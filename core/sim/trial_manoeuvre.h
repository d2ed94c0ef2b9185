#pragma once
// Trial manoeuvre (IMO MSC.192(79) 5.32, docs/trial.md): the effect on every tracked and reported target
// of a proposed own-ship course and speed, ordered after a delay and carried out with own ship's turn
// rate and acceleration (the vessel model of vessel_motion.h, the same the simulation steers with).
// Per target: the predicted CPA and TCPA with their standard deviations, and the probability that the
// CPA falls below the limit; around own ship, the collision-danger sectors: the courses and speeds
// (taken after the delay) that would bring any target inside the CPA limit within the TCPA limit.
// Nothing here touches the tracking: it works on a copy of the estimates.
//
// Geometry: the target keeps its estimated velocity; own ship follows the trial path. After the
// manoeuvre the relative motion is straight again, with an equivalent start r' and velocity u, so the
// CPA's sd and the probability come from that straight encounter's covariance (tracking/cpa.h). Own
// ship's velocity error counts until the order takes over (t_d: the delay plus half the manoeuvre);
// after it own ship sails the ordered velocity through the water, so only the current's error counts:
//   e_r' = e_r - t_d e_vown + t_d e_current,   e_u = e_vtarget - e_current.
// The probability uses the signed miss distance s across the relative motion,
// P = Phi((L - s) / sd) - Phi((-L - s) / sd). The sd covers the estimates' errors, not future
// manoeuvres of the target.
#include <cstdint>
#include <utility>
#include <vector>

#include "common/time.h"
#include "estimation/gaussian.h"
#include "geo/local_frame.h"
#include "sim/scenario.h"

namespace reckoner::sim {

struct SimFrame;

/// The proposed order: heading (true) and speed through the water, after a delay.
struct TrialOrder {
  double courseRad = 0.0;  ///< true, [0, 2 pi)
  double speedMps = 0.0;   ///< >= 0
  double delayS = 0.0;     ///< >= 0
};

struct TrialSettings {
  double cpaLimitM = 1852.0;
  double tcpaLimitS = 720.0;
  double stepS = 0.5;              ///< sampling of own ship's path during the manoeuvre
  int sectorCourses = 180;         ///< courses of the danger display (every 2 degrees)
  int sectorSpeeds = 8;            ///< speed rings, up to sectorMaxSpeedMps
  double sectorMaxSpeedMps = 0.0;  ///< 0: 1.5 x the ordered or present speed, at least 10 kn
};

/// Own ship as the DRKF has it, and its manoeuvring limits.
struct TrialOwnShip {
  geo::GridPoint position;
  double waterVxMps = 0.0, waterVyMps = 0.0;  ///< velocity through the water, grid
  double currentXMps = 0.0, currentYMps = 0.0;
  est::Mat<2> currentCovariance = est::Mat<2>::Zero();
  double convergenceRad = 0.0;       ///< true = grid + this
  double maxTurnRateRadPerS = 0.0;   ///< 0: turns at once
  double maxAccelerationMps2 = 0.0;  ///< 0: changes speed at once
};

/// A target: [rx, ry, vtx, vty, vox, voy] (target minus own position; target's and own ship's ground
/// velocities; grid, SI) and its covariance.
struct TrialTargetInput {
  int trackId = 0;         ///< radar track, or 0 for an AIS target alone
  std::uint32_t mmsi = 0;  ///< AIS station (associated or alone), 0 none
  est::Vec<6> state = est::Vec<6>::Zero();
  est::Mat<6> covariance = est::Mat<6>::Identity();
  /// Relative position and velocity [rx, ry, vx, vy] and their covariance.
  [[nodiscard]] est::Gaussian<4> relative() const;
};

struct TrialTargetResult {
  int trackId = 0;
  std::uint32_t mmsi = 0;
  double presentCpaM = 0.0, presentTcpaS = 0.0;  ///< without the manoeuvre
  double sdPresentCpaM = 0.0;
  double cpaM = 0.0, tcpaS = 0.0;  ///< with it (TCPA from now; 0: opening now)
  double sdCpaM = 0.0, sdTcpaS = 0.0;
  double probabilityBelowLimit = 0.0;
  bool dangerous = false;  ///< CPA within the limit and TCPA within its limit
  geo::GridPoint targetAtCpa, ownAtCpa;
};

struct DangerSectors {
  std::vector<double> speedsMps;     ///< ring speeds, increasing
  int courses = 0;                   ///< course cells, cell j centred on j * 360 / courses degrees true
  std::vector<std::uint8_t> danger;  ///< speeds x courses, row per speed: 1 when some target is dangerous
  /// The runs of consecutive dangerous cells of a ring, [first, last] cell indices, in course order.
  [[nodiscard]] std::vector<std::pair<int, int>> dangerousRuns(std::size_t ring) const;
};

struct TrialResult {
  TimeUs timeUs = 0;
  TrialOrder order;
  double manoeuvreEndS = 0.0;           ///< from now: the order reached
  std::vector<geo::GridPoint> ownPath;  ///< every 10 s up to the manoeuvre's end plus 10 minutes
  std::vector<TrialTargetResult> targets;
  DangerSectors sectors;
};

/// The trial at timeUs. Non-finite or negative inputs give an empty result (no targets).
TrialResult trialManoeuvre(TimeUs timeUs, const TrialOwnShip& own,
                           const std::vector<TrialTargetInput>& targets, const TrialOrder& order,
                           const TrialSettings& settings);

/// Own ship from a frame's DRKF estimate, with the scenario's vessel limits.
TrialOwnShip trialOwnShipOf(const SimFrame& f, const VesselMotionSpec& vessel, const geo::LocalFrame& frame);
/// The targets of a frame: confirmed radar tracks (with their AIS station if associated) and the AIS
/// targets associated with none (their latest report carried to the frame's time, with the AIS error
/// model's covariance plus own ship's).
std::vector<TrialTargetInput> trialTargetsOf(const SimFrame& f, const track::AisErrorModel& errors,
                                             const geo::LocalFrame& frame);

}  // namespace reckoner::sim
