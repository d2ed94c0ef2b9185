#pragma once
// ARPA track management (IMO MSC.192(79) 5.25) around a bank of TTKFs fed by one DRKF (seed 000
// figure 3). Plots arrive without identity, in time order, as the beam sweeps; they are associated in
// batches (everything received since the last own-ship input) by global nearest neighbour with an
// optimal assignment inside a chi-square gate. New tracks start from unassociated plots inside the
// acquisition zones (or by hand), are confirmed when seen in M of their first N sweeps, are kept
// while seen in 5 of the last 10 sweeps and are then declared lost (last position kept for a while).
// The paper's own mode, where every plot's target is known, is kept for its consistency tests.
// docs/ttkf.md has the rules and their reasons.
//
// The tracker is built of the tracking literature's components, one file each: the predictor
// (track_predictor.h) and the hypothesiser with its gate (hypothesiser.h) say which plots may belong to
// which track; the data associator (data_associator.h) chooses among them; the updater
// (track_updater.h) applies a plot to its track; the initiator (initiator.h) starts tracks on the
// plots left over and confirms them M of N; the deleter (deleter.h) declares them lost. TrackManager
// is the loop around them, with the bank's bookkeeping: capacity, manual acquisition, danger, events.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/committed_allocator.h"
#include "radar/land_mask.h"
#include "tracking/cpa.h"
#include "tracking/deleter.h"
#include "tracking/hypothesiser.h"
#include "tracking/initiator.h"
#include "tracking/track.h"
#include "tracking/track_filter.h"
#include "tracking/track_updater.h"

namespace reckoner::track {

enum class Association : std::uint8_t {
  Nearest,  ///< global nearest neighbour: plots carry no identity (a real radar)
  Known,    ///< each plot's tag is its target (seed 000's assumption); tag < 0 plots are ignored
};

struct TrackManagerConfig {
  TtkfConfig filter;
  Association association = Association::Nearest;
  std::size_t capacity = 1000;
  double capacityWarningFraction = 0.95;  ///< warn when this share of the capacity is in use
  int confirmHits = 3;                    ///< M
  int confirmSweeps = 5;                  ///< N
  int keepHits = 5;                       ///< seen in keepHits ...
  int keepSweeps = 10;                    ///< ... of the last keepSweeps sweeps, else lost
  double lostHoldS = 60.0;                ///< a lost track stays shown this long
  bool autoAcquire = true;
  std::vector<AcquisitionZone> zones;  ///< empty with autoAcquire: the whole picture
  double manualAcquireRadiusM = 300.0;
  double sweepPeriodS = 2.0;
  double dangerCpaM = 1852.0;  ///< 1 NM
  double dangerTcpaS = 720.0;  ///< 12 min
  /// The target model of a track fused with AIS: reports every 2 to 30 s measure its velocity, so a
  /// straight-running ship's small random acceleration suffices (turns are caught by the AIS
  /// innovation, Ttkf::updateTargetState's adaptNis).
  est::GaussMarkov fusedTargetAcceleration{0.005, 0.02};
  /// The filter of new tracks (track_filter.h); each kind's parameters below.
  TrackerKind kind = TrackerKind::Ekf;
  /// ekf-ie: seed 001's input estimation around the TTKF (docs/manoeuvres.md), the window in radar
  /// updates and the false-alarm probability per window.
  int inputEstimationWindow = 15;
  double inputEstimationPfa = 1e-4;
  AbgConfig abg{0.1, true};
  ImmConfig imm;
  /// Every track's divergence guard (estimation/divergence_guard.h, docs/consistency.md "Divergence
  /// guards"): a filter whose covariance loses positive definiteness, or whose NIS stays far above its
  /// band, restarts on an associated plot, keeping its track number.
  est::DivergenceGuardConfig guard;
  /// Empty if valid, else the first problem.
  [[nodiscard]] std::string check() const;
};

struct TrackEvent {
  enum class Kind : std::uint8_t {
    Acquired,         ///< a new (tentative) track
    Confirmed,        ///< M of N reached
    Lost,             ///< fewer than keepHits in keepSweeps: lost-target alarm
    Dropped,          ///< a tentative track that could not be confirmed
    Removed,          ///< a lost track's hold time is over
    Cancelled,        ///< by the user
    Dangerous,        ///< CPA and TCPA both under the limits (rising edge)
    Manoeuvre,        ///< a manoeuvre was declared (rising edge of the flag: ekf-ie and imm)
    CapacityWarning,  ///< the number of tracks reached the warning level (rising edge)
    CapacityFull,     ///< a plot was not acquired because the bank is full (once per sweep)
    FilterReset,      ///< the divergence guard restarted the track's filter on a plot (reason says why)
  };
  Kind kind;
  TimeUs timeUs = 0;
  int trackId = 0;
  est::DivergenceReason reason = est::DivergenceReason::None;  ///< FilterReset: what tripped the guard
};
const char* trackEventName(TrackEvent::Kind k);

struct TrackCounters {
  long plots = 0;
  long plotsAssociated = 0;
  long plotsStale = 0;        ///< older than the last own-ship input: not usable
  long plotsRefusedFull = 0;  ///< would have started a track, bank full
  long plotsOnLand = 0;       ///< unassociated plots on charted land: not acquired (chart-aided ARPA)
  long tracksStarted = 0;
  long tracksConfirmed = 0;
  long tracksLost = 0;
  long tracksDropped = 0;
  std::size_t largestCluster = 0;      ///< largest association cluster solved (tracks + plots)
  est::DivergenceCounts filterResets;  ///< track filters restarted by their divergence guard
};

class TrackManager {
 public:
  /// Throws std::invalid_argument for an invalid configuration.
  explicit TrackManager(const TrackManagerConfig& config);

  /// The DRKF output (seed 000 figure 3): associates the plots received so far, then feeds every
  /// active track.
  void feedOwnShip(const OwnShipInput& own);
  /// A plot in the grid frame, in time order; tag: its true target in simulation (-1: unknown),
  /// used only for scoring, or for association in Known mode.
  void addPlot(const GridPlot& plot, int tag = -1);
  /// Closes the sweep at time t: associates the remaining plots, counts hits and misses, confirms,
  /// drops, loses and removes tracks.
  void endSweep(TimeUs t);

  /// Manual acquisition: starts a track on the unassociated plot nearest to grid point (x, y) among
  /// those of the current and the previous sweep, within manualAcquireRadiusM. Returns its id.
  std::optional<int> acquire(double xGridM, double yGridM);
  /// The filter of tracks started from now on (the operator's choice; tracks keep theirs).
  void setTrackerKind(TrackerKind kind) { config_.kind = kind; }
  /// Chart-aided acquisition: unassociated plots on this land are not acquired automatically (they are
  /// echoes of the shore, not targets). Null: no chart. Manual acquisition is the operator's call.
  void setLandMask(std::shared_ptr<const radar::LandMask> land) { land_ = std::move(land); }
  /// The operator's cancellation: the track is gone, and automatic acquisition keeps away from its
  /// vessel for CancelledTracks::kHoldS (initiator.h).
  bool cancel(int trackId);
  void cancelAll();
  /// Automatic acquisition on or off from now (the operator's switch; manual acquisition always works).
  void setAutoAcquire(bool on) { config_.autoAcquire = on; }
  /// The acquisition (guard) zones from now on; false, changing nothing, when one is not a ring sector
  /// (TrackManagerConfig::check's rule).
  bool setZones(const std::vector<AcquisitionZone>& zones);
  [[nodiscard]] const std::vector<AcquisitionZone>& zones() const { return config_.zones; }
  /// The operator's CPA and TCPA limits of the dangerous-target flag from now on (ignored unless both
  /// are finite and >= 0, as TrackManagerConfig::check demands).
  void setDangerLimits(double cpaM, double tcpaS);

  /// Fuses a direct measurement of a track's target state (an associated AIS report, ais_fusion.h) at
  /// t >= the track's filter time; an Empty report for an unknown or lost track or a filter that does
  /// not take one.
  est::UpdateReport<4> fuseTargetState(int trackId, TimeUs t, const est::Vec<4>& z, const est::Mat<4>& R,
                                       double gate, double adaptNis = 0.0);
  /// A track fused with AIS (true) runs the quieter target model of fusedTargetAcceleration; false
  /// returns it to the bank's. Ignored for an unknown track or a filter without a TTKF.
  void setFused(int trackId, bool fused);
  /// The track's belief predicted to t (not changing the track); lost tracks keep their last one.
  [[nodiscard]] est::ttkf::Belief beliefAt(const Track& t, TimeUs time) const;
  using TrackTable = std::vector<Track, CommittedAllocator<Track>>;
  [[nodiscard]] const TrackTable& tracks() const { return tracks_; }
  [[nodiscard]] const Track* find(int trackId) const;
  [[nodiscard]] std::size_t activeCount() const;
  [[nodiscard]] bool capacityWarning() const { return capacityWarning_; }
  [[nodiscard]] const TrackCounters& counters() const { return counters_; }
  [[nodiscard]] const TrackManagerConfig& config() const { return config_; }
  [[nodiscard]] const std::shared_ptr<const TtkfContext>& context() const { return ctx_; }
  [[nodiscard]] const std::optional<OwnShipInput>& lastOwnShip() const { return lastOwn_; }
  /// Events since the last call.
  std::vector<TrackEvent> takeEvents();

 private:
  struct Pending {
    GridPlot plot;
    int tag;
  };
  struct FreePlot {
    GridPlot plot;
    int tag;
    OwnShipInput own;  ///< own ship when the plot was left unassociated
    int sweep;
  };
  /// Associates the plots received since the last own-ship input, then starts tracks on the rest.
  void associatePending();
  /// One GNN round between the tracks of one status and the plots not yet taken (taken[j]).
  void associateRound(TrackStatus status, const PlotBatch& batch, std::vector<char>& taken);
  /// The tracks of one status that may take a plot of the batch, predicted and gated.
  [[nodiscard]] std::vector<GatedTrack> predictAndAdmit(TrackStatus status, const PlotBatch& batch) const;
  void initiateFromUnassociated(const std::vector<char>& taken);
  void associateKnown(const GridPlot& plot, int tag);
  void applyPlot(Track& t, const GridPlot& plot, int tag);
  /// The guard's verdict on the radar update just made with `plot`; a diverged filter restarts on it.
  void guardAfterPlot(Track& t, const GridPlot& plot, int tag);
  /// A new filter of the track's kind started on the plot (same track number); false when the plot
  /// cannot start one (the guard stays tripped: the next associated plot is tried).
  bool restartFilter(Track& t, const GridPlot& plot, int tag);
  std::optional<int> startTrack(const OwnShipInput& own, const GridPlot& plot, int tag, bool manual);
  void judgeTentative(Track& t, TimeUs now);
  void loseTrack(Track& t, TimeUs now);
  void removeDroppedAndExpired(TimeUs now);
  void updateDanger(Track& t, TimeUs now);
  void updateCapacityWarning();
  void event(TrackEvent::Kind k, TimeUs t, int id) { events_.push_back({k, t, id}); }

  TrackManagerConfig config_;
  std::shared_ptr<const TtkfContext> ctx_;
  std::shared_ptr<const TtkfContext> fusedCtx_;
  Hypothesiser hypothesiser_;
  TrackFilterFactory filters_;
  MofNConfirmation confirmation_;
  CancelledTracks cancelled_;
  HitsInWindowDeleter deleter_;
  TrackUpdater updater_;
  TrackTable tracks_;  ///< reserved for the capacity (up to 4096) and committed at construction
  std::vector<Pending> pending_;
  std::vector<FreePlot> free_;
  std::optional<OwnShipInput> lastOwn_;
  std::vector<TrackEvent> events_;
  TrackCounters counters_;
  int nextId_ = 1;
  std::size_t active_ = 0;
  int sweep_ = 0;
  bool capacityWarning_ = false;
  bool fullThisSweep_ = false;
  std::shared_ptr<const radar::LandMask> land_;
};

}  // namespace reckoner::track
