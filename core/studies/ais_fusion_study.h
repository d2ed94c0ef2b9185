#pragma once
// The AIS-radar evaluation (docs/fusion.md, `reckoner-cli fusion`): on a scenario whose targets carry
// simulated AIS transponders, over Monte Carlo runs,
//  - association: at every cycle, each AIS station that has been heard for associateWindowS and whose
//    vessel has had a confirmed radar track for as long is "eligible"; it is correct when associated
//    with a track of its own vessel, missed when associated with none, false when associated with a
//    track of another vessel (or of clutter). A swap is an association that turns false; it is "far"
//    when the two vessels are more than 500 m apart at that time;
//  - accuracy of three estimates of every AIS-carrying vessel at 1 and 3 minutes after its radar track
//    was acquired, as the IMO table scores them (imo_errors.h): the fused track (the run as
//    configured), the radar-only track (the same seed with fusion off: the radar picture and the AIS
//    messages are drawn from their own streams, so they are the same) and the AIS-only estimate (the
//    station's latest report, reference-corrected and carried to that time, against own ship's DRKF);
//    with the mean NEES of each estimate's target position and velocity (4 dof) at 3 minutes.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "sensors/ais_transmitter.h"
#include "sim/scenario.h"
#include "studies/imo_errors.h"

namespace reckoner::studies {

enum class FusionSource : std::uint8_t { Fused, RadarOnly, AisOnly };
inline constexpr int kFusionSourceCount = 3;
const char* fusionSourceName(FusionSource s);

struct FusionStudyOptions {
  int runs = 10;
  int threads = 1;
  std::uint64_t seed = 1;
  double associateWindowS = 180.0;  ///< heard and tracked this long before a station is scored
  double swapDistanceM = 500.0;
};

struct FusionAccuracy {
  std::array<double, kImoErrorCount> p95At1{}, p95At3{};
  int samplesAt1 = 0, samplesAt3 = 0;
  double meanNeesAt3 = 0.0;  ///< target position and velocity, 4 dof
};

struct FusionStudyResult {
  std::string scenario;
  int runs = 0;
  int aisVessels = 0;                                                 ///< per run
  long eligible = 0, correct = 0, missed = 0, falseAssociations = 0;  ///< station-cycles
  long swapsNear = 0, swapsFar = 0;
  long associationEvents = 0, dissociationEvents = 0;
  long fusedReports = 0, rejectedReports = 0;
  std::array<FusionAccuracy, kFusionSourceCount> accuracy{};
  [[nodiscard]] double correctFraction() const {
    return eligible > 0 ? static_cast<double>(correct) / static_cast<double>(eligible) : 0.0;
  }
};

/// Throws std::invalid_argument when no target carries AIS, there is no radar, or the options are
/// not positive.
FusionStudyResult evaluateFusion(const sim::Scenario& scenario, const FusionStudyOptions& options);

/// The scenario with a transponder of class cls on every target that has none (MMSI 200000000 + id,
/// a 120 m ship with its antenna 30 m from the stern for class A, a 12 m boat for class B): the IMO
/// scenarios evaluated with AIS.
sim::Scenario withAis(sim::Scenario s, sensors::AisStationClass cls);

}  // namespace reckoner::studies
