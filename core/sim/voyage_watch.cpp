#include "sim/voyage_watch.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/angles.h"
#include "common/units.h"
#include "sim/simulation_engine.h"

namespace reckoner::sim {
namespace {

constexpr double kReorderHeadingRad = 0.2 * kPi / 180.0;  // the autopilot's dead band
constexpr double kReorderSpeedMps = 0.01;
constexpr double kMaxDriftSine = 0.9;  // a current stronger than this share of the speed is not stemmed

}  // namespace

std::vector<std::string> VoyageSpec::problems() const {
  std::vector<std::string> out;
  if (route) {
    for (const std::string& p : route->problems()) out.push_back("voyage.route: " + p);
  }
  if (followRoute && !route) out.emplace_back("voyage.follow_route: there is no route to follow");
  if (!(draughtM > 0.0 && draughtM < 100.0)) out.emplace_back("voyage.draught_m must be in (0, 100)");
  if (!std::isfinite(safetyContourM)) out.emplace_back("voyage.safety_contour_m must be finite");
  if (safetyDepthM && !std::isfinite(*safetyDepthM)) out.emplace_back("voyage.safety_depth_m must be finite");
  if (!(dangerClearanceM >= 0.0 && dangerClearanceM < 10000.0))
    out.emplace_back("voyage.danger_clearance_m must be in [0, 10000)");
  if (!(halfBeamM >= 0.0 && halfBeamM < 100.0)) out.emplace_back("voyage.half_beam_m must be in [0, 100)");
  for (const std::string& p : lookAhead.problems()) out.push_back("voyage: " + p);
  if (!(lookAheadPeriodS > 0.0 && lookAheadPeriodS <= 600.0))
    out.emplace_back("voyage.look_ahead_period_s must be in (0, 600]");
  if (!(alertProbability > 0.0 && alertProbability < 1.0))
    out.emplace_back("voyage.alert_probability must be in (0, 1)");
  if (!(alertConfirmationS >= 0.0 && alertConfirmationS <= 120.0))
    out.emplace_back("voyage.alert_confirmation_s must be in [0, 120]");
  if (!(steeringLookaheadM > 0.0 && steeringLookaheadM < 1e5))
    out.emplace_back("voyage.steering_lookahead_m must be in (0, 100000)");
  return out;
}

nav::OwnShipFix ownShipFixOf(const nav::Drkf& filter) {
  const est::Vec<4> g = nav::groundStateOf(filter.belief());
  const est::Mat<4> c = nav::groundCovarianceOf(filter.belief());
  const geo::GridPoint gp{g[0], g[1]};
  nav::OwnShipFix fix;
  fix.position = filter.frame().toGeodetic(gp);
  const geo::GridInfo gi = filter.frame().gridInfo(gp);
  if (!std::isfinite(gi.scale) || !g.allFinite()) {
    fix.position = {std::nan(""), std::nan("")};
    return fix;
  }
  fix.sogMps = std::hypot(g[2], g[3]) / gi.scale;
  fix.cogRad = wrapTwoPi(bearingOf(g[2], g[3]) + gi.convergenceRad);
  // grid (east, north) to true (east, north): a clockwise turn by the convergence, and the scale
  const double cs = std::cos(gi.convergenceRad), sn = std::sin(gi.convergenceRad);
  est::Mat<2> r;
  r << cs, sn, -sn, cs;
  r /= gi.scale;
  const est::Mat<2> p = r * c.topLeftCorner<2, 2>() * r.transpose();
  fix.positionCovariance = nav::PositionCovariance{p(1, 1), p(0, 0), p(0, 1)};
  fix.velocitySdMps =
      std::sqrt(std::max(0.0, est::largestEigenvalue(est::Mat<2>(c.bottomRightCorner<2, 2>())))) / gi.scale;
  return fix;
}

VoyageWatch::VoyageWatch(const VoyageSpec& spec) : spec_(spec) {
  if (const auto p = spec.problems(); !p.empty()) throw std::invalid_argument(p.front());
  if (spec_.route) monitor_.emplace(*spec_.route, spec_.monitor);
}

void VoyageWatch::setRoute(const std::optional<geo::Route>& route, bool follow) {
  VoyageSpec next = spec_;
  next.route = route;
  next.followRoute = follow && route.has_value();
  if (const auto p = next.problems(); !p.empty()) throw std::invalid_argument(p.front());
  spec_ = next;
  monitor_.reset();
  if (spec_.route) monitor_.emplace(*spec_.route, spec_.monitor);
  lastOrder_.reset();
}

void VoyageWatch::observe(TimeUs t, const nav::Drkf& filter, SimFrame& out) {
  if (monitor_) out.route = monitor_->update(t, ownShipFixOf(filter));
  const TimeUs period = fromSeconds(spec_.lookAheadPeriodS);
  if (guard_ && (!lastLookAheadUs_ || t - *lastLookAheadUs_ >= period)) {
    lastLookAheadUs_ = t;
    nav::LookAheadSettings settings = spec_.lookAhead;
    settings.horizonS += spec_.alertConfirmationS;  // the alert waits this long before it is raised
    out.lookAhead = guard_->outlook(nav::predictLookAhead(filter, settings), filter.frame());
  }
  out.aground = aground_.has_value();
}

void VoyageWatch::step(TimeUs t, const nav::Drkf& filter, VesselMotionModel& truth,
                       const geo::LocalFrame& frame, SimFrame& out) {
  observe(t, filter, out);
  if (guard_ && !aground_) {
    if (std::optional<Grounding> g = guard_->grounding(frame.toGeodetic(truth.state().position))) {
      aground_ = g;
      truth.runAground();
      out.grounded = std::move(g);
      out.aground = true;
    }
  }
  if (!aground_ && monitor_ && spec_.followRoute && out.route && out.route->valid) {
    steer(t, filter, truth, frame, *out.route);
  }
}

void VoyageWatch::steer(TimeUs t, const nav::Drkf& filter, VesselMotionModel& truth,
                        const geo::LocalFrame& frame, const nav::RouteStatus& status) {
  nav::CrossTrackSteering law;
  law.lookaheadM = spec_.steeringLookaheadM;
  const double courseTrue = nav::headingToSteerRad(status, law);
  const est::drkf::State& x = filter.belief().x;
  const geo::GridInfo gi = frame.gridInfo({x[est::drkf::kPosX], x[est::drkf::kPosY]});
  const double course = wrapTwoPi(courseTrue - gi.convergenceRad);
  const std::optional<double>& planned = spec_.route->waypoints[status.to].leg.plannedSpeedKn;
  const VesselTruth& now = truth.state();
  double speed = planned
                     ? knotsToMps(*planned)
                     : (truth.order() ? truth.order()->speedMps : std::hypot(now.waterVxMps, now.waterVyMps));
  speed = std::max(speed, 0.0);
  // the heading through the water that makes the course good against the estimated current
  const double cross = x[est::drkf::kCurX] * std::cos(course) - x[est::drkf::kCurY] * std::sin(course);
  const double drift =
      speed > 0.1 ? std::asin(std::clamp(cross / speed, -kMaxDriftSine, kMaxDriftSine)) : 0.0;
  HelmOrder order{wrapTwoPi(course - drift), speed, 0.0, 0.0};
  if (lastOrder_ && std::abs(angleDiff(order.headingRad, lastOrder_->headingRad)) < kReorderHeadingRad &&
      std::abs(order.speedMps - lastOrder_->speedMps) < kReorderSpeedMps) {
    return;
  }
  KinematicEvent e;
  e.timeUs = t + 1;
  e.order = order;
  if (truth.overrideFrom(e)) lastOrder_ = order;
}

}  // namespace reckoner::sim
