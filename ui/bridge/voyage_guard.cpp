#include "ui/bridge/voyage_guard.h"

namespace reckoner::ui {
namespace {
bool same(const charts::AntiGroundingSettings& a, const charts::AntiGroundingSettings& b) {
  return a.safety.safetyContourM == b.safety.safetyContourM &&
         a.safety.safetyDepthM == b.safety.safetyDepthM && a.draughtM == b.draughtM &&
         a.dangerClearanceM == b.dangerClearanceM && a.halfBeamM == b.halfBeamM;
}
}  // namespace

void VoyageGuard::setCells(std::vector<charts::CellPtr> cells) {
  cells_ = std::move(cells);
  guard_.reset();
}

void VoyageGuard::setSafety(const charts::SafetySettings& safety) {
  safety_ = safety;
}

std::shared_ptr<const charts::ChartSafety> VoyageGuard::guardFor(const sim::VoyageSpec& v) {
  if (cells_.empty()) return nullptr;
  charts::AntiGroundingSettings g = charts::antiGroundingSettingsOf(v);
  if (safety_) g.safety = *safety_;
  if (!guard_ || !same(guard_->settings(), g)) {
    guard_.reset();
    guard_ = std::make_shared<const charts::ChartSafety>(cells_, g);
  }
  return guard_;
}

}  // namespace reckoner::ui
