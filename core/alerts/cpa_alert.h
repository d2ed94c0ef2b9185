#pragma once
// The CPA/TCPA alert condition with hysteresis, so that a target hovering at a limit raises one alert
// and not one per sweep. It begins as the tracker's danger rule does (CPA <= cpaM and 0 <= TCPA <=
// tcpaS) and ends only when the target has been clearly outside for clearAfterS: CPA above cpaM +
// cpaMarginM, TCPA above tcpaS + tcpaMarginS, or the closest approach more than tcpaMarginS past. The
// margin keeps a CPA swinging about its limit from chattering; the time keeps a noisy TCPA (a target
// with little relative motion, whose TCPA jumps by minutes from sweep to sweep) from doing so.
#include <map>
#include <string>

#include "common/time.h"
#include "tracking/cpa.h"

namespace reckoner::alerts {

struct CpaAlertLimits {
  double cpaM = 1852.0;       ///< 1 NM
  double tcpaS = 720.0;       ///< 12 min
  double cpaMarginM = 185.2;  ///< 0.1 NM
  double tcpaMarginS = 30.0;
  double clearAfterS = 20.0;  ///< outside this long before the condition ends
};
/// Throws std::invalid_argument naming the field unless every limit is finite, cpaM and tcpaS above 0 and
/// the margins at least 0.
void validate(const CpaAlertLimits& l);

class CpaAlertCondition {
 public:
  explicit CpaAlertCondition(CpaAlertLimits limits = {});
  /// Whether the condition holds at `now` for track `trackId` given its latest CPA; remembers it per
  /// track. Times must not decrease.
  bool update(int trackId, TimeUs now, const track::Cpa& cpa);
  /// A track that no longer exists.
  void forget(int trackId) { tracks_.erase(trackId); }
  [[nodiscard]] const CpaAlertLimits& limits() const { return limits_; }

 private:
  CpaAlertLimits limits_;
  struct State {
    bool holding = false;
    bool outside = false;  ///< clearly outside at the latest update, since outsideSinceUs
    TimeUs outsideSinceUs = 0;
  };
  std::map<int, State> tracks_;
};

/// "CPA 0.42 NM in 6.5 min" for the alert text.
std::string cpaAlertText(int trackId, const track::Cpa& cpa);

}  // namespace reckoner::alerts
