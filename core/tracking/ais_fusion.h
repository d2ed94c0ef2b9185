#pragma once
// One picture from AIS and radar (docs/fusion.md): association of AIS stations with radar tracks after
// IMO MSC.192(79) 5.31 (position, course and speed within limits, persistent, with hysteresis), and the
// fusion of an associated station's reports into its track's TTKF.
//
// An AIS position report is turned into a measurement of the target's hull centre and ground velocity
// (AisObservation): the antenna's reported position corrected by the antenna's place on the hull (type
// 5 / 24 dimensions, rotated by the heading, else the COG), at the GNSS fix time the message's UTC
// second gives (the report arrives later), with the position's and velocity's errors, whose time
// correlation is taken into account by inflating each report's covariance by (1 + rho) / (1 - rho)
// (rho the correlation over the time since the station's previous report). The track fuses it as a
// linear measurement of its target block, extrapolated from the fix time to the filter's time with the
// reported velocity (the extrapolation's error in R).
//
// Association (AisRadarFusion::update, every own-ship cycle): each station heard since the last cycle
// is compared with every confirmed track at the same instant. A pair is a candidate when the position
// difference is within its limit and the course and speed differences are within theirs, or, while the
// track's velocity is still too uncertain to be judged by fixed limits, when the velocity difference is
// within its statistical gate (chi-square, 2 dof, 99.9%, with both sides' covariances). Candidates
// compete in an optimal one-to-one assignment by the Mahalanobis distance of the whole difference; a station
// takes a track after associateAfter consecutive reports choosing it, and leaves it after dissociateAfter
// consecutive reports outside releaseFactor times the limits (hysteresis), after rejectAfter consecutive
// fused reports rejected by the track's gate, or at once when the track is lost or the station falls silent.
// Plain C++; per-message calls never throw.
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "estimation/gaussian.h"
#include "geo/local_frame.h"
#include "io/ais.h"
#include "tracking/ais_targets.h"
#include "tracking/track_manager.h"

namespace reckoner::track {

/// What the receiver assumes of AIS errors (not the simulator's values: docs/fusion.md).
struct AisErrorModel {
  double positionSdAccurateM = 5.0;  ///< per axis, position accuracy flag 1 (better than 10 m)
  double positionSdM = 10.0;         ///< per axis, flag 0 or absent
  double positionCorrelationS = 120.0;
  double velocitySdClassAMps = 0.07;  ///< per axis
  double velocitySdClassBMps = 0.12;
  double velocityCorrelationS = 5.0;
  double headingSdDeg = 2.0;       ///< of the reported heading, for the antenna offset
  double cogOffsetSdDeg = 5.0;     ///< COG in place of the heading (drift angle)
  double unknownOffsetSdM = 25.0;  ///< per axis, when the station sends no dimensions
  double unknownLatencyS = 2.0;    ///< no UTC second in the report: assumed latency ...
  double unknownLatencySdS = 2.0;  ///< ... and its sd
  /// The target's unknown acceleration over the extrapolation from the fix time, for association and
  /// the AIS-only estimate (fusion uses the track's own model: TrackManagerConfig::fusedTargetAcceleration).
  double accelerationSdMps2 = 0.05;
  friend bool operator==(const AisErrorModel&, const AisErrorModel&) = default;
};

struct AisAssociationConfig {
  bool enabled = true;  ///< associate AIS stations with radar tracks
  bool fuse = true;     ///< fuse associated stations' reports into their tracks (ekf and ekf-ie)
  double positionLimitM = 300.0;
  double courseLimitDeg = 25.0;
  double speedLimitKn = 3.0;
  double courseMinSpeedKn = 3.0;  ///< the course is compared only when both speeds exceed this
  int associateAfter = 3;         ///< consecutive reports choosing the same track
  int dissociateAfter = 3;        ///< consecutive reports outside releaseFactor x the limits
  double releaseFactor = 1.5;
  int rejectAfter = 3;  ///< consecutive fused reports rejected by the gate
  /// A fused report whose NIS exceeds this quantile (4 dof) is a manoeuvre: the track's velocity and
  /// acceleration covariance is scaled up before the update (Ttkf::updateTargetState).
  double manoeuvreNisProbability = 0.99;
  double gateProbability = 0.9999;  ///< of the fused report (4 degrees of freedom)
  AisErrorModel errors;
  friend bool operator==(const AisAssociationConfig&, const AisAssociationConfig&) = default;
  /// Empty if valid, else the first problem (field names as in the scenario format).
  [[nodiscard]] std::string check() const;
};

/// An AIS report as a measurement of the hull centre's position and ground velocity (grid frame).
struct AisObservation {
  std::uint32_t mmsi = 0;
  TimeUs rxUs = 0;
  TimeUs fixUs = 0;                                         ///< when z holds
  est::Vec<4> z = est::Vec<4>::Zero();                      ///< x, y (m), vx, vy (m/s)
  est::Mat<4> R = est::Mat<4>::Identity();                  ///< of one report (correlation not counted)
  double inflationPosition = 1.0, inflationVelocity = 1.0;  ///< (1 + rho) / (1 - rho) since the last
  double accelerationSdMps2 = 0.05;
  bool offsetCorrected = false;  ///< dimensions known: the antenna offset removed
  /// z and its covariance carried to t (position by the velocity; an unknown acceleration of sd
  /// accelerationSd, default accelerationSdMps2, and, with inflate, the errors' time correlation in the
  /// covariance).
  [[nodiscard]] est::Gaussian<4> at(TimeUs t, bool inflate, double accelerationSd = -1.0) const;
};

/// The fix time of a report with UTC second `second` received at rxUs; utcOffsetUs: UTC minus the
/// clock (a simulation starts at a whole minute: 0). Empty when the second is not available (>= 60).
std::optional<TimeUs> aisFixTime(TimeUs rxUs, std::optional<int> second, TimeUs utcOffsetUs);

/// The observation from a position report (type 1-3, 18, 19, 27), or empty when it has no position or
/// velocity, or its position is not a fix (time stamp 61-63). info: the station's static data so far;
/// previousFixUs: of its previous report (< 0 none).
std::optional<AisObservation> aisObservation(const io::AisMessage& m, TimeUs rxUs, const AisStatic& info,
                                             const geo::LocalFrame& frame, const AisErrorModel& errors,
                                             TimeUs previousFixUs, TimeUs utcOffsetUs = 0);

struct AisAssociation {
  std::uint32_t mmsi = 0;
  int trackId = 0;
  TimeUs sinceUs = 0;
  int fused = 0;       ///< reports fused into the track
  int rejected = 0;    ///< reports the track's gate rejected
  double lastNis = 0;  ///< of the last fused report
};

struct AisAssociationEvent {
  enum class Kind : std::uint8_t { Associated, Dissociated };
  Kind kind = Kind::Associated;
  TimeUs timeUs = 0;
  std::uint32_t mmsi = 0;
  int trackId = 0;
  std::string reason;  ///< why a pair was dissociated
};

struct AisFusionCounters {
  long reports = 0, checks = 0, associated = 0, dissociated = 0, fused = 0, rejected = 0, notFusable = 0;
};

class AisRadarFusion {
 public:
  /// Throws std::invalid_argument when config.check() fails.
  explicit AisRadarFusion(const AisAssociationConfig& config);

  /// A message received at rxUs (after AisTargetTable::feed of the same message); position reports
  /// become observations. utcOffsetUs: UTC minus the run's clock.
  void addReport(const io::AisMessage& m, TimeUs rxUs, const AisStatic& info, const geo::LocalFrame& frame,
                 TimeUs utcOffsetUs = 0);
  /// At now, with the bank fed up to now: dissociation of lost tracks and silent stations, association
  /// checks for the stations heard since the last call, fusion of their reports.
  void update(TimeUs now, TrackManager& bank, const AisTargetTable& table);

  [[nodiscard]] std::vector<AisAssociation> associations() const;
  /// The station associated with a track (0: none).
  [[nodiscard]] std::uint32_t mmsiOfTrack(int trackId) const;
  /// The latest observation of a station (the AIS-only estimate), if any.
  [[nodiscard]] const AisObservation* latest(std::uint32_t mmsi) const;
  std::vector<AisAssociationEvent> takeEvents();
  [[nodiscard]] const AisFusionCounters& counters() const { return counters_; }
  [[nodiscard]] const AisAssociationConfig& config() const { return config_; }

 private:
  struct Station {
    std::optional<AisObservation> latest;
    std::vector<AisObservation> fresh;  ///< since the last update
    int pendingTrack = -1, pendingCount = 0;
    std::optional<AisAssociation> pair;
    int outside = 0, rejectedInRow = 0;
  };
  struct Difference {
    double positionM, speedKn, courseDeg;
    bool courseCompared;
    double mahalanobis2 = 0.0;          ///< of the position and velocity difference (4 dof)
    double velocityMahalanobis2 = 0.0;  ///< of the velocity difference (2 dof)
  };
  [[nodiscard]] Difference differenceAt(const AisObservation& o, const est::ttkf::Belief& track,
                                        TimeUs now) const;
  void dropBroken(TimeUs now, TrackManager& bank, const AisTargetTable& table);
  void check(TimeUs now, TrackManager& bank, const std::vector<std::uint32_t>& fresh);
  void fuse(Station& s, TrackManager& bank, TimeUs now);
  void dissociate(Station& s, TrackManager& bank, TimeUs now, std::uint32_t mmsi, std::string reason);

  AisAssociationConfig config_;
  double gate_;
  double velocityGate_ = 0.0;
  double manoeuvreNis_ = 0.0;
  std::unordered_map<std::uint32_t, Station> stations_;
  std::unordered_map<int, std::uint32_t> byTrack_;
  std::vector<AisAssociationEvent> events_;
  AisFusionCounters counters_;
};

}  // namespace reckoner::track
