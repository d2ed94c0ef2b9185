#pragma once
// The filter behind an ARPA track, chosen per track (issue 6, docs/manoeuvres.md "Choosing the
// tracker"):
//   ekf     the 12-state TTKF of seed 000 (own ship and target, Gauss-Markov accelerations)
//   ekf-ie  the same with seed 001's input estimation (manoeuvre flag and correction)
//   abg     seed 003's alpha-beta-gamma filter on the plots made absolute with own ship's position
//   imm     the constant-velocity / coordinated-turn IMM (tracking/imm.h)
// Whatever the filter, a track shows the rest of the system the same 12-state belief (own ship and
// target position, velocity and acceleration), so association, CPA, the chart and the plots need not
// know which one runs. For abg and imm the own-ship block is the DRKF output carried forward by the
// TTKF's own-vessel model, and the target block is the filter's; the two blocks are taken as
// uncorrelated. The abg has no covariance of its own: it carries the one its gains give (Joseph form
// holds for any gain) when the target moves as the tracker's target model says (the Gauss-Markov
// acceleration of tracker.target_acceleration, as the EKF assumes), for the gate and the ellipse.
#include <cstdint>
#include <optional>
#include <string_view>
#include <variant>

#include "tracking/alpha_beta_gamma.h"
#include "tracking/imm.h"
#include "tracking/ttkf.h"

namespace reckoner::track {

enum class TrackerKind : std::uint8_t { Ekf, EkfInputEstimation, AlphaBetaGamma, Imm };
inline constexpr int kTrackerKindCount = 4;
/// "ekf", "ekf-ie", "abg", "imm".
const char* trackerKindName(TrackerKind k);
/// Human-readable: "EKF", "EKF + input estimation", "alpha-beta-gamma", "IMM (CV/CT)".
const char* trackerKindLabel(TrackerKind k);
std::optional<TrackerKind> trackerKindFromName(std::string_view name);

/// Own ship's part of a 12-state belief (position, velocity and acceleration, indices 0 to 5) at
/// t >= own.timeUs, from a DRKF output and the TTKF's own-vessel model.
est::Gaussian<6> ownShipAt(const TtkfContext& ctx, const OwnShipInput& own, TimeUs t);

/// Seed 003's filter as a track filter. Plots become absolute grid positions with own ship's estimate
/// at the plot time, measurement covariance the converted plot's plus own ship's position covariance.
class AbgTrackFilter {
 public:
  /// Starts on a plot (the filter's first point). Throws std::invalid_argument for a degenerate plot.
  AbgTrackFilter(std::shared_ptr<const TtkfContext> ctx, const AbgConfig& config, const OwnShipInput& own,
                 const GridPlot& plot);
  void feedOwnShip(const OwnShipInput& own);
  /// Gated with the context's radar gate on range and bearing.
  est::UpdateReport<2> updateRadar(const GridPlot& plot);
  [[nodiscard]] tk::Belief predicted(TimeUs t) const;
  [[nodiscard]] TimeUs timeUs() const { return std::max(own_.timeUs, targetUs_); }
  [[nodiscard]] const AlphaBetaGammaFilter& filter() const { return abg_; }

 private:
  /// Target [x y vx vy ax ay] predicted to t >= targetUs_ (mean by the filter's constant
  /// acceleration, covariance with the target model's noise).
  [[nodiscard]] est::Gaussian<6> targetAt(TimeUs t) const;
  std::shared_ptr<const TtkfContext> ctx_;
  AlphaBetaGammaFilter abg_;
  est::Mat<6> P_;  ///< target covariance at targetUs_
  OwnShipInput own_;
  TimeUs targetUs_;
};

/// The IMM as a track filter: plots with their own noise plus own ship's position uncertainty.
class ImmTrackFilter {
 public:
  ImmTrackFilter(std::shared_ptr<const TtkfContext> ctx, const ImmConfig& config, const OwnShipInput& own,
                 const GridPlot& plot);
  void feedOwnShip(const OwnShipInput& own);
  est::UpdateReport<2> updateRadar(const GridPlot& plot);
  [[nodiscard]] tk::Belief predicted(TimeUs t) const;
  [[nodiscard]] TimeUs timeUs() const { return std::max(own_.timeUs, imm_.timeUs()); }
  [[nodiscard]] const ImmTracker& filter() const { return imm_; }

 private:
  std::shared_ptr<const TtkfContext> ctx_;
  ImmTracker imm_;
  OwnShipInput own_;
};

/// One of the four, behind one interface.
class TrackFilter {
 public:
  TrackFilter(TrackerKind kind, Ttkf f) : kind_(kind), f_(std::move(f)) {}
  explicit TrackFilter(AbgTrackFilter f) : kind_(TrackerKind::AlphaBetaGamma), f_(std::move(f)) {}
  explicit TrackFilter(ImmTrackFilter f) : kind_(TrackerKind::Imm), f_(std::move(f)) {}

  [[nodiscard]] TrackerKind kind() const { return kind_; }
  /// The TTKF (ekf and ekf-ie), else null.
  [[nodiscard]] const Ttkf* ttkf() const { return std::get_if<Ttkf>(&f_); }
  [[nodiscard]] Ttkf* ttkf() { return std::get_if<Ttkf>(&f_); }
  [[nodiscard]] const ImmTrackFilter* imm() const { return std::get_if<ImmTrackFilter>(&f_); }
  [[nodiscard]] const AbgTrackFilter* abg() const { return std::get_if<AbgTrackFilter>(&f_); }

  void feedOwnShip(const OwnShipInput& own);
  /// detail: filled by the TTKF only (input estimation).
  est::UpdateReport<2> updateRadar(const GridPlot& plot, Ttkf::RadarDetail* detail = nullptr);
  /// A direct measurement of the target's position and velocity (Ttkf::updateTargetState); the
  /// alpha-beta-gamma and IMM filters do not take one (an Empty report).
  est::UpdateReport<4> updateTargetState(TimeUs t, const est::Vec<4>& z, const est::Mat<4>& R, double gate,
                                         double adaptNis = 0.0);
  /// The 12-state belief at timeUs().
  [[nodiscard]] tk::Belief belief() const;
  /// The 12-state belief predicted to t (t before timeUs(): the current one).
  [[nodiscard]] tk::Belief predicted(TimeUs t) const;
  [[nodiscard]] TimeUs timeUs() const;
  /// The filter's own manoeuvre indication where it has one (IMM: turn mode most likely).
  [[nodiscard]] bool modelManoeuvring() const;

 private:
  TrackerKind kind_;
  std::variant<Ttkf, AbgTrackFilter, ImmTrackFilter> f_;
};

}  // namespace reckoner::track
