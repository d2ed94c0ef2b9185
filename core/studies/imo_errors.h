#pragma once
// The quantities of IMO MSC.192(79)'s accuracy table from the truth and from an estimate, and their
// absolute errors: relative course and speed, CPA, TCPA, true course and speed (imo_accuracy.h and the
// AIS fusion evaluation, ais_fusion_study.h, score with these).
#include <array>

#include "sim/vessel_motion.h"
#include "tracking/cpa.h"

namespace reckoner::studies {

inline constexpr int kImoErrorCount = 6;
/// Absolute errors, in the table's order and units: deg, kn, NM, min, deg, kn.
using ImoErrors = std::array<double, kImoErrorCount>;

struct ImoTruth {
  double relCourseDeg = 0, relSpeedKn = 0, cpaNm = 0, tcpaMin = 0, courseDeg = 0, speedKn = 0;
};

/// From own ship's and the target's truth; convergence: grid to true at own ship.
ImoTruth imoTruthOf(const sim::VesselTruth& own, const sim::VesselTruth& target, double convergenceRad);
/// The errors of what a track (or an AIS-only estimate) shows; TCPA infinite when undefined.
ImoErrors imoErrorsOf(const track::TrackKinematics& k, const ImoTruth& t);

}  // namespace reckoner::studies
