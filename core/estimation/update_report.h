#pragma once
// The record every measurement update returns; gating, plots, track status and tests read it.
#include <cstdint>
#include <limits>
#include <string_view>

#include "estimation/gaussian.h"

namespace reckoner::est {

enum class UpdateStatus : std::uint8_t {
  Accepted,            ///< applied, innovation inside the gate
  AcceptedForced,      ///< applied without gating (gate re-opened after persistent rejection)
  RejectedGate,        ///< NIS above the chi-square gate; state unchanged
  RejectedNonFinite,   ///< NaN or infinity in z, R or the model output; state unchanged
  RejectedNumerical,   ///< innovation covariance not positive definite, or non-finite result
  RejectedDegenerate,  ///< the model cannot be linearised here (e.g. heading at zero speed)
  RejectedStale,       ///< measurement older than the filter time
  Empty,               ///< no measurement rows
};

constexpr bool isApplied(UpdateStatus s) {
  return s == UpdateStatus::Accepted || s == UpdateStatus::AcceptedForced;
}

constexpr std::string_view statusName(UpdateStatus s) {
  switch (s) {
    case UpdateStatus::Accepted:
      return "accepted";
    case UpdateStatus::AcceptedForced:
      return "accepted_forced";
    case UpdateStatus::RejectedGate:
      return "rejected_gate";
    case UpdateStatus::RejectedNonFinite:
      return "rejected_non_finite";
    case UpdateStatus::RejectedNumerical:
      return "rejected_numerical";
    case UpdateStatus::RejectedDegenerate:
      return "rejected_degenerate";
    case UpdateStatus::RejectedStale:
      return "rejected_stale";
    case UpdateStatus::Empty:
      return "empty";
  }
  return "unknown";
}

/// Result of one (possibly stacked) update. innovation and S have dim rows; gate <= 0 means ungated.
template <int MaxM>
struct UpdateReport {
  int dim = 0;
  BVec<MaxM> innovation;
  BMat<MaxM> S;
  double nis = std::numeric_limits<double>::quiet_NaN();
  double gate = 0.0;
  UpdateStatus status = UpdateStatus::Empty;

  [[nodiscard]] bool applied() const { return isApplied(status); }
};

}  // namespace reckoner::est
