#pragma once
// The AIS side of a simulation (docs/fusion.md): the targets' transponders (sensors/ais_transmitter.h),
// own ship's AIS target table (tracking/ais_targets.h) and the association and fusion of the stations
// with the radar tracks (tracking/ais_fusion.h). SimulationEngine runs it at the end of every cycle,
// after the radar and own ship: messages heard in the cycle go to the table and the fusion in time
// order, then the fusion checks associations and fuses reports into the track bank.
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "sensors/ais_transmitter.h"
#include "sim/scenario.h"
#include "sim/vessel_motion.h"
#include "tracking/ais_fusion.h"
#include "tracking/ais_targets.h"
#include "tracking/track_manager.h"

namespace reckoner::sim {

/// What a cycle's AIS gave: messages heard, the table, the associations and their events.
struct AisCycle {
  std::vector<sensors::AisReception> received;  ///< in time order
  std::shared_ptr<const std::vector<track::AisTarget>> targets;
  std::vector<track::AisAssociation> associations;
  std::vector<track::AisAssociationEvent> events;
};

class AisTraffic {
 public:
  /// Throws std::invalid_argument for an invalid association configuration or transponder.
  AisTraffic(const Scenario& scenario, std::uint64_t seed);

  /// A transponder for target `index` (scenario order) appearing at startUs, when its spec has one.
  void addTarget(std::size_t index, const TargetSpec& target, TimeUs startUs);
  /// No transponder anywhere: nothing to do.
  [[nodiscard]] bool idle() const { return !any_; }
  /// Transponders held: one per AIS vessel that has not left yet (a vessel's leave_s is final, so its
  /// transponder and the hull history it keeps are released when it leaves, and a run of thousands of
  /// passing vessels holds only those still to come or present).
  [[nodiscard]] std::size_t transponders() const;

  /// The end of a cycle at `end`: the transponders' messages up to then (targets: their truths, in
  /// scenario order; present: appeared), the table advanced with own ship, association and fusion.
  AisCycle step(TimeUs end, const std::vector<VesselMotionModel>& targets,
                const std::vector<std::uint8_t>& present, const geo::LocalFrame& frame,
                track::TrackManager& bank, const track::OwnShipInput& own);

  [[nodiscard]] const track::AisTargetTable& table() const { return table_; }
  [[nodiscard]] const track::AisRadarFusion& fusion() const { return fusion_; }

 private:
  std::uint64_t seed_;
  std::vector<std::optional<sensors::AisTransmitter>> transmitters_;  ///< per target index
  std::vector<std::optional<TimeUs>> leaveUs_;                        ///< per target index
  track::AisTargetTable table_;
  track::AisRadarFusion fusion_;
  bool any_ = false;
};

/// The hull of a vessel truth as a transponder sees it (centre, ground velocity, heading, turn rate).
sensors::AisHullState hullOf(const VesselTruth& v);

}  // namespace reckoner::sim
