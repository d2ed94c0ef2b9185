#include "alerts/cpa_alert.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "common/units.h"

namespace reckoner::alerts {

void validate(const CpaAlertLimits& l) {
  const auto check = [](double v, bool zeroAllowed, const char* field) {
    if (!std::isfinite(v) || v < 0.0 || (!zeroAllowed && v == 0.0))
      throw std::invalid_argument(std::string("alerts: ") + field + " must be a finite number " +
                                  (zeroAllowed ? "of at least 0" : "above 0"));
  };
  check(l.cpaM, false, "cpa_limit_m");
  check(l.tcpaS, false, "tcpa_limit_s");
  check(l.cpaMarginM, true, "cpa_margin_m");
  check(l.tcpaMarginS, true, "tcpa_margin_s");
  check(l.clearAfterS, true, "clear_after_s");
}

CpaAlertCondition::CpaAlertCondition(CpaAlertLimits limits) : limits_(limits) {
  validate(limits_);
}

bool CpaAlertCondition::update(int trackId, TimeUs now, const track::Cpa& cpa) {
  State& s = tracks_[trackId];
  if (!std::isfinite(cpa.cpaM) || !std::isfinite(cpa.tcpaS)) return s.holding;  // keep the last decision
  if (!s.holding) {
    s.holding = track::withinDangerLimits(cpa, limits_.cpaM, limits_.tcpaS);  // the tracker's rule
    s.outside = false;
    return s.holding;
  }
  const bool outside = cpa.cpaM > limits_.cpaM + limits_.cpaMarginM ||
                       cpa.tcpaS > limits_.tcpaS + limits_.tcpaMarginS || cpa.tcpaS < -limits_.tcpaMarginS;
  if (!outside) {
    s.outside = false;
  } else if (!s.outside) {
    s.outside = true;
    s.outsideSinceUs = now;
  }
  if (s.outside && now - s.outsideSinceUs >= fromSeconds(limits_.clearAfterS)) {
    s.holding = false;
    s.outside = false;
  }
  return s.holding;
}

std::string cpaAlertText(int trackId, const track::Cpa& cpa) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "track %d: CPA %.2f NM in %.1f min", trackId,
                cpa.cpaM / kMetresPerNauticalMile, cpa.tcpaS / 60.0);
  return buf;
}

}  // namespace reckoner::alerts
