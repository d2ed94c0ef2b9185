#pragma once
// The alert conditions of a simulation, replay or live run, read from each SimFrame and reported to an
// alerts::AlertManager (docs/alerts.md), so that the window and the command line raise the same alerts:
//   CPA/TCPA            per confirmed track, with hysteresis (alerts::CpaAlertCondition)
//   LOST TARGET         per track while it is lost
//   GUARD ZONE          per track while it is a new (tentative, automatically acquired) track, while the
//                       tracker acquires in zones only (SimFrame::zones not empty)
//   POSITION SOURCE LOST while own ship is dead reckoning (nav::DeadReckoningMonitor's rule)
//   DEAD RECKONING LIMIT while the 95% position radius is above the limit (when one is set)
//   POSITION DISCREPANCY while the primary (GPS) and secondary (Loran-C) fixes are further apart than
//                       the limit (both fresh; the older moved to the newer's time by the estimated
//                       velocity over ground; it clears after 30 s below 80% of the limit)
//   SENSOR NOISE        per DRKF block while its NIS window is above its band
//   CAPACITY            while the track bank is at its warning level
//   SAFETY CONTOUR AHEAD while the look-ahead's probability of crossing the safety contour (or entering
//                       land, a prohibited area) is at least the alert probability (kept between
//                       look-aheads)
//   DANGER AHEAD        the same for passing within the clearance of an isolated danger
//   GROUNDED            own ship aground (the simulator's)
//   OFF TRACK           while the cross-track distance is beyond the leg's limit (with hysteresis)
//   WAYPOINT APPROACH   per waypoint, once, when its wheel-over point is within the warning time
//   ARRIVAL             once, at the route's last waypoint
//   DR FILTER RESET     while the DRKF's divergence guard has it marked diverged, and in the frame of
//                       its restart at a GNSS fix (then waiting for acknowledgement)
//   TRACK FILTER RESET  per track, in the frame its filter was restarted by its divergence guard
//   AIS SART/MOB/EPIRB  per search and rescue device heard active and not lost (the frame's AIS targets;
//                       the other AIS conditions are the radar tracks', docs/alerts.md)
#include <optional>
#include <set>

#include "alerts/ais_alert.h"
#include "alerts/alert_manager.h"
#include "alerts/cpa_alert.h"
#include "sim/simulation_engine.h"

namespace reckoner::sim {

struct AlertFeedSettings {
  alerts::CpaAlertLimits cpa;
  double drLimitM = 0.0;   ///< the 95% radius above which DEAD RECKONING LIMIT holds; 0: no such alert
  bool guardZones = true;  ///< new tracks are guard-zone intrusions while the tracker acquires in zones
  /// GPS and Loran-C fixes further apart than this raise POSITION DISCREPANCY; 0: no such alert.
  double positionDiscrepancyM = kDefaultPositionDiscrepancyM;
  static constexpr double kDefaultPositionDiscrepancyM = 185.2;  ///< 0.1 NM
  /// SAFETY CONTOUR AHEAD and DANGER AHEAD hold once the look-ahead's probability has been at least
  /// this for the confirmation time (the voyage's alert_probability and alert_confirmation_s).
  double groundingAlertProbability = 0.05;
  double groundingConfirmationS = 60.0;
};
/// The discrepancy alert clears when the fixes come closer than this fraction of the limit.
inline constexpr double kDiscrepancyClearFraction = 0.8;
/// ... and only after this long (s) below it, so that fixes wandering about the limit raise one alert.
inline constexpr double kDiscrepancyClearAfterS = 30.0;
/// Fixes older than this (s) are not compared.
inline constexpr double kDiscrepancyFreshS = 10.0;
/// SAFETY CONTOUR AHEAD and DANGER AHEAD are raised at once, unconfirmed, from this probability on.
inline constexpr double kGroundingImmediateProbability = 0.5;
/// Throws std::invalid_argument naming the field (the CPA limits', or dr_limit_m or
/// position_discrepancy_m not finite and >= 0).
void validate(const AlertFeedSettings& s);

/// The settings a scenario implies: its tracker's CPA/TCPA limits and whether it acquires in zones.
AlertFeedSettings alertFeedSettingsFor(const Scenario& scenario);

class AlertFeed {
 public:
  explicit AlertFeed(AlertFeedSettings settings = {});

  /// Reports every condition of `f` to `m`, then advances m's timers to f.timeUs. The manager's clock
  /// is the frame's time plus clockOffsetUs (a live run's manager keeps its own zero: sim/live_watch.h).
  void feed(const SimFrame& f, alerts::AlertManager& m, TimeUs clockOffsetUs = 0);
  /// New limits from the next frame on (throws as validate does).
  void setSettings(const AlertFeedSettings& s);
  [[nodiscard]] const AlertFeedSettings& settings() const { return settings_; }

 private:
  void feedTracks(const SimFrame& f, alerts::AlertManager& m);
  void feedOwnShip(const SimFrame& f, alerts::AlertManager& m) const;
  void feedDiscrepancy(const SimFrame& f, alerts::AlertManager& m);
  void feedVoyage(const SimFrame& f, alerts::AlertManager& m);

  struct Fix {
    TimeUs timeUs = 0;
    geo::GridPoint position;
  };

  AlertFeedSettings settings_;
  TimeUs offsetUs_ = 0;  ///< of the feed() in progress
  alerts::CpaAlertCondition cpa_;
  std::set<int> tracks_;                ///< the tracks of the previous frame
  std::optional<Fix> gps_, loran_;      ///< the latest fix of each position source
  bool discrepant_ = false;             ///< POSITION DISCREPANCY holds (with its hysteresis)
  std::optional<TimeUs> closeSinceUs_;  ///< since when, while it holds, the fixes are close again
  bool contourAhead_ = false, dangerAhead_ = false;       ///< the alerts' conditions
  std::optional<TimeUs> contourSinceUs_, dangerSinceUs_;  ///< since when the probability is above
  std::string contourText_, dangerText_, groundedText_;
  std::set<int> routeEvents_;  ///< WAYPOINT APPROACH sources (and ARRIVAL as -1) raised last frame
  std::set<int> resetTracks_;  ///< TRACK FILTER RESET sources raised last frame
  alerts::AisDistressFeed distress_;
};

}  // namespace reckoner::sim
