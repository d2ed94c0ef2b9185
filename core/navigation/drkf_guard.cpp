// The DRKF's divergence guard (estimation/divergence_guard.h; docs/consistency.md, "Divergence guards"):
// after every epoch the guard judges the blocks' NIS and the covariance; a filter it marks diverged goes
// on as it is until the first epoch with a usable GNSS fix, where it restarts from that fix with the
// covariance it started with.
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <variant>
#include <vector>

#include "navigation/drkf.h"

namespace reckoner::nav {
namespace {
using namespace est::drkf;
/// Without a GNSS velocity the restart knows nothing of the velocity: 0 with this sd (about 16 kn),
/// as a replay starts (sim/replay_runner.cpp).
constexpr double kUnknownVelocitySdMps = 8.0;

bool usableVelocity(const sensors::GpsSample& fix) {
  return fix.hasVelocity && std::isfinite(fix.velEastMps) && std::isfinite(fix.velNorthMps) &&
         std::isfinite(fix.velocityVarM2PerS2) && fix.velocityVarM2PerS2 > 0.0;
}
}  // namespace

const sensors::GpsSample* Drkf::usableFix(TimeUs t, std::span<const sensors::OwnShipSample> samples) {
  for (const auto& sample : samples) {
    const auto* g = std::get_if<sensors::GpsSample>(&sample);
    if (g && g->timeUs == t && std::isfinite(g->position.xM) && std::isfinite(g->position.yM) &&
        std::isfinite(g->positionVarM2) && g->positionVarM2 > 0.0)
      return g;
  }
  return nullptr;
}

Belief Drkf::beliefAtFix(const sensors::GpsSample& fix) const {
  Belief b;
  b.x.setZero();  // every Gauss-Markov state at its prior mean
  b.P = initialP_;
  for (const int i : {kPosX, kPosY, kVelX, kVelY}) {
    b.P.row(i).setZero();
    b.P.col(i).setZero();
  }
  b.x[kPosX] = fix.position.xM;
  b.x[kPosY] = fix.position.yM;
  b.P(kPosX, kPosX) = std::max(initialP_(kPosX, kPosX), fix.positionVarM2);
  b.P(kPosY, kPosY) = std::max(initialP_(kPosY, kPosY), fix.positionVarM2);
  const geo::GridInfo g = frame_.gridInfo(fix.position);
  if (!usableVelocity(fix)) {
    const double v = kUnknownVelocitySdMps * kUnknownVelocitySdMps;
    b.P(kVelX, kVelX) = std::max(initialP_(kVelX, kVelX), v);
    b.P(kVelY, kVelY) = std::max(initialP_(kVelY, kVelY), v);
    return b;
  }
  // The fix measures the velocity over ground x3 + x2 (x7 + x6): the velocity through the water is it
  // minus the current, which restarts at its prior (mean 0): var(x3) = var(fix) + var(x2), cov(x3, x2)
  // = -var(x2). True east/north to grid as addGpsFix converts it.
  const double cg = std::cos(g.convergenceRad), sg = std::sin(g.convergenceRad);
  b.x[kVelX] = g.scale * (fix.velEastMps * cg - fix.velNorthMps * sg);
  b.x[kVelY] = g.scale * (fix.velEastMps * sg + fix.velNorthMps * cg);
  const double vv = g.scale * g.scale * fix.velocityVarM2PerS2;
  for (const auto& [vel, cur] : {std::pair{kVelX, kCurX}, std::pair{kVelY, kCurY}}) {
    b.P(vel, vel) = std::max(initialP_(vel, vel), vv) + b.P(cur, cur);
    b.P(vel, cur) = b.P(cur, vel) = -b.P(cur, cur);
  }
  return b;
}

DrkfUpdateReport Drkf::restartAt(TimeUs t, const sensors::GpsSample& fix,
                                 std::span<const sensors::OwnShipSample> samples) {
  const est::DivergenceReason why = guard_.reason();
  belief_ = beliefAtFix(fix);
  timeUs_ = t;
  rejectedSinceUs_.fill(-1);
  gnssScale_ = GnssNoiseScale{};
  guard_.reset();
  counters_.resets = guard_.resets();
  // The epoch's other samples, applied to the new state as usual.
  std::vector<sensors::OwnShipSample> rest;
  rest.reserve(samples.size());
  for (const auto& s : samples)
    if (std::get_if<sensors::GpsSample>(&s) != &fix) rest.push_back(s);
  DrkfUpdateReport report = updateEpoch(t, rest);
  report.reset = why;
  // The fix made the state: its blocks read applied without a gate and without a NIS.
  const auto consumed = [&](DrkfBlock b) {
    ++counters_.byStatus[b][static_cast<std::size_t>(est::UpdateStatus::AcceptedForced)];
    if (report.blockCount >= kMaxBlocksPerEpoch) return;
    est::BlockReport& r = report.blocks[static_cast<std::size_t>(report.blockCount++)];
    r = est::BlockReport{b,    2,  std::numeric_limits<double>::quiet_NaN(), 0.0,
                         true, -1, est::UpdateStatus::AcceptedForced};
    report.dim += 2;
  };
  consumed(kGpsPosition);
  if (usableVelocity(fix)) consumed(kGpsVelocity);
  watch(report);
  return report;
}

void Drkf::watch(DrkfUpdateReport& report) {
  for (int i = 0; i < report.blockCount; ++i) {
    const est::BlockReport& b = report.blocks[static_cast<std::size_t>(i)];
    if (est::isApplied(b.status) || b.status == est::UpdateStatus::RejectedGate) guard_.addNis(b.nis, b.dim);
  }
  guard_.checkCovariance<kStateDim>(belief_.P, &modelled_);
  report.diverged = guard_.reason();
}

}  // namespace reckoner::nav
