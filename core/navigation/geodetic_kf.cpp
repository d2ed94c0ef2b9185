#include "navigation/geodetic_kf.h"

#include <GeographicLib/Ellipsoid.hpp>
#include <cmath>
#include <stdexcept>

#include "common/angles.h"
#include "estimation/chi_square.h"
#include "estimation/ekf.h"
#include "estimation/model_concepts.h"

namespace reckoner::nav {
namespace geod {
namespace {
const GeographicLib::Ellipsoid& wgs84() {
  return GeographicLib::Ellipsoid::WGS84();
}
double e2() {
  return wgs84().EccentricitySq();
}

/// d(COG, SOG) / d(vE, vN); zero rows below the speed limit (COG held, SOG then from the state).
est::Mat<2> courseSpeedJacobian(double vE, double vN, double minSpeedMps) {
  const double s2 = vE * vE + vN * vN, s = std::sqrt(s2);
  est::Mat<2> J = est::Mat<2>::Zero();
  if (s < minSpeedMps || s == 0.0) return J;
  J << vN / s2, -vE / s2, vE / s, vN / s;
  return J;
}
}  // namespace

double meridianRadius(double latRad) {
  return wgs84().MeridionalCurvatureRadius(radToDeg(latRad));
}
double primeVerticalRadius(double latRad) {
  return wgs84().TransverseCurvatureRadius(radToDeg(latRad));
}

State transition(const State& x, double T, double minSpeedMps) {
  State o = x;
  const double lat = x[kLat];
  o[kLat] = lat + T * x[kVn] / meridianRadius(lat);
  o[kLon] = x[kLon] + T * x[kVe] / (primeVerticalRadius(lat) * std::cos(lat));
  const double s = std::hypot(x[kVe], x[kVn]);
  if (s >= minSpeedMps && s > 0.0) {
    o[kCog] = wrapTwoPi(std::atan2(x[kVe], x[kVn]));
    o[kSog] = s;
  }
  return o;
}

Covariance transitionJacobian(const State& x, double T, double minSpeedMps) {
  const double lat = x[kLat], sn = std::sin(lat), cs = std::cos(lat);
  const double M = meridianRadius(lat), N = primeVerticalRadius(lat), D = N * cs;
  const double w = 1.0 - e2() * sn * sn;
  const double dM = M * 3.0 * e2() * sn * cs / w;         // dM/dlat
  const double dD = N * sn * (e2() * cs * cs / w - 1.0);  // d(N cos lat)/dlat
  Covariance F = Covariance::Identity();
  F(kLat, kLat) = 1.0 - T * x[kVn] * dM / (M * M);
  F(kLat, kVn) = T / M;
  F(kLon, kLat) = -T * x[kVe] * dD / (D * D);
  F(kLon, kVe) = T / D;
  const est::Mat<2> J = courseSpeedJacobian(x[kVe], x[kVn], minSpeedMps);
  if (!J.isZero()) {
    F(kCog, kCog) = F(kSog, kSog) = 0.0;
    F.block<2, 2>(kCog, kVe) = J;
  }
  return F;
}
}  // namespace geod

namespace {
using namespace geod;

/// Two state components measured directly; `wrapFirst`: the first is an angle in [0, 2 pi).
template <int A, int B, bool WrapFirst, bool WrapSecond>
struct DirectPair {
  static constexpr int kDim = 2;
  [[nodiscard]] est::Vec<2> h(const State& x) const { return {x[A], x[B]}; }
  [[nodiscard]] est::MatRC<2, kStateDim> jacobian(const State&) const {
    est::MatRC<2, kStateDim> H = est::MatRC<2, kStateDim>::Zero();
    H(0, A) = H(1, B) = 1.0;
    return H;
  }
  [[nodiscard]] est::Vec<2> residual(const est::Vec<2>& z, const est::Vec<2>& zh) const {
    return {WrapFirst ? angleDiff(z[0], zh[0]) : z[0] - zh[0],
            WrapSecond ? angleDiff(z[1], zh[1]) : z[1] - zh[1]};
  }
};
using PositionModel = DirectPair<kLat, kLon, false, true>;
using VelocityModel = DirectPair<kVe, kVn, false, false>;
using CourseSpeedModel = DirectPair<kCog, kSog, true, false>;
static_assert(est::MeasurementModel<PositionModel, kStateDim>);
static_assert(est::MeasurementModel<VelocityModel, kStateDim>);
static_assert(est::MeasurementModel<CourseSpeedModel, kStateDim>);

/// Maps a covariance of (lat, lon, vE, vN) into the full state (COG and SOG follow the velocity).
Covariance spread(const est::Mat<4>& P4, const est::Mat<2>& Jcs) {
  Eigen::Matrix<double, kStateDim, 4> B = Eigen::Matrix<double, kStateDim, 4>::Zero();
  B.topRows<4>().setIdentity();
  B.block<2, 2>(kCog, 2) = Jcs;
  return B * P4 * B.transpose();
}
}  // namespace

int GeodeticUpdate::rowsApplied() const {
  return (position.applied() ? 2 : 0) + (deadReckoning.applied() ? 2 : 0) + (courseSpeed.applied() ? 2 : 0);
}

std::string GeodeticKfConfig::check() const {
  if (!(accelerationQ > 0.0) || !std::isfinite(accelerationQ)) return "acceleration noise must be positive";
  if (!(cogQ >= 0.0) || !(sogQ >= 0.0) || !std::isfinite(cogQ) || !std::isfinite(sogQ))
    return "COG and SOG noise must be >= 0";
  if (!(minSpeedMps > 0.0)) return "minimum speed must be positive";
  if (!(gateProbability >= 0.0 && gateProbability < 1.0)) return "gate probability must lie in [0, 1)";
  if (!(gateReopenS > 0.0)) return "gate re-open time must be positive";
  return {};
}

GeodeticKf::GeodeticKf(const GeodeticKfConfig& config, const Belief& initial, TimeUs t0)
    : config_(config), gate_(0.0), belief_(initial), timeUs_(t0) {
  if (const std::string p = config.check(); !p.empty()) throw std::invalid_argument("geodetic KF: " + p);
  if (!initial.x.allFinite() || !est::isPositiveDefinite(initial.P))
    throw std::invalid_argument(
        "geodetic KF: initial state must be finite with a positive definite covariance");
  gate_ = config.gateProbability > 0.0 ? est::chiSquareQuantile(config.gateProbability, 2.0) : 0.0;
}

Belief GeodeticKf::initialBelief(const geo::LocalFrame& frame, const geo::GridPoint& p, double sdPosM,
                                 double vEast, double vNorth, double sdVelMps) {
  const geo::GeoPoint g = frame.toGeodetic(p);
  const double lat = degToRad(g.latDeg);
  Belief b;
  const double s = std::hypot(vEast, vNorth);
  b.x << lat, degToRad(g.lonDeg), vEast, vNorth, wrapTwoPi(std::atan2(vEast, vNorth)), s;
  est::Mat<4> P4 = est::Mat<4>::Zero();
  P4(0, 0) = std::pow(sdPosM / meridianRadius(lat), 2);
  P4(1, 1) = std::pow(sdPosM / (primeVerticalRadius(lat) * std::cos(lat)), 2);
  P4(2, 2) = P4(3, 3) = sdVelMps * sdVelMps;
  b.P = spread(P4, courseSpeedJacobian(vEast, vNorth, 0.5));
  // COG and SOG keep a floor of their own (a slow start has no defined course).
  b.P(kCog, kCog) += s > 0.5 ? 1e-6 : kPi * kPi / 3.0;
  b.P(kSog, kSog) += 1e-6;
  return b;
}

bool GeodeticKf::predictTo(TimeUs t) {
  if (t < timeUs_) return false;
  if (t == timeUs_) return true;
  const double T = toSeconds(t - timeUs_);
  const State& x = belief_.x;
  const Covariance F = transitionJacobian(x, T, config_.minSpeedMps);
  // White acceleration q per axis: the (position, velocity) pairs lat-vN and lon-vE, positions in
  // angle; COG and SOG take the velocity's noise through their Jacobian, plus their own.
  const double lat = x[kLat], M = meridianRadius(lat), D = primeVerticalRadius(lat) * std::cos(lat);
  const double q = config_.accelerationQ;
  est::Mat<4> Q4 = est::Mat<4>::Zero();  // lat, lon, vE, vN
  Q4(0, 0) = q * T * T * T / 3.0 / (M * M);
  Q4(0, 3) = Q4(3, 0) = q * T * T / 2.0 / M;
  Q4(1, 1) = q * T * T * T / 3.0 / (D * D);
  Q4(1, 2) = Q4(2, 1) = q * T * T / 2.0 / D;
  Q4(2, 2) = Q4(3, 3) = q * T;
  Covariance Q = spread(Q4, courseSpeedJacobian(x[kVe], x[kVn], config_.minSpeedMps));
  Q(kCog, kCog) += config_.cogQ * T;
  Q(kSog, kSog) += config_.sogQ * T;
  Belief next;
  next.x = transition(x, T, config_.minSpeedMps);
  next.P = F * belief_.P * F.transpose() + Q;
  est::symmetrise(next.P);
  if (!next.x.allFinite() || !next.P.allFinite()) return false;
  belief_ = next;
  timeUs_ = t;
  return true;
}

GeodeticUpdate GeodeticKf::update(TimeUs t, std::span<const sensors::OwnShipSample> samples,
                                  const geo::LocalFrame& frame) {
  GeodeticUpdate out;
  if (!predictTo(t)) return out;
  const auto [gps, gyro, log] = sensors::epochSamples(samples);
  if (gps) {
    const geo::GeoPoint g = frame.toGeodetic(gps->position);
    const double scale = frame.gridInfo(gps->position).scale;
    const double lat = degToRad(g.latDeg);
    const double var = gps->positionVarM2 / (scale * scale);  // true metres
    const double M = meridianRadius(lat), D = primeVerticalRadius(lat) * std::cos(lat);
    const est::Mat<2> R = est::Vec<2>(var / (M * M), var / (D * D)).asDiagonal();
    // A fix refused for gateReopenS is applied ungated once: a filter that has drifted beyond its
    // own covariance must not lock the GPS out for good.
    const bool reopen =
        positionRejectedSinceUs_ >= 0 && toSeconds(t - positionRejectedSinceUs_) >= config_.gateReopenS;
    out.position =
        est::update(belief_, PositionModel{}, est::Vec<2>(lat, degToRad(g.lonDeg)), R, reopen ? 0.0 : gate_);
    if (out.position.status == est::UpdateStatus::RejectedGate && positionRejectedSinceUs_ < 0)
      positionRejectedSinceUs_ = t;
    if (out.position.applied()) {
      if (reopen) out.position.status = est::UpdateStatus::AcceptedForced;
      positionRejectedSinceUs_ = -1;
    }
    const double sp = std::hypot(gps->velEastMps, gps->velNorthMps);
    if (gps->hasVelocity && sp >= config_.minSpeedMps) {
      // COG and SOG of the GPS velocity; their covariance through the Jacobian (eq. 27's band).
      const est::Mat<2> J = courseSpeedJacobian(gps->velEastMps, gps->velNorthMps, config_.minSpeedMps);
      const est::Mat<2> Rcs = J * (gps->velocityVarM2PerS2 * est::Mat<2>::Identity()) * J.transpose();
      out.courseSpeed =
          est::update(belief_, CourseSpeedModel{},
                      est::Vec<2>(wrapTwoPi(std::atan2(gps->velEastMps, gps->velNorthMps)), sp), Rcs, gate_);
    }
  }
  if (gyro && log && log->speedMps >= config_.minSpeedMps) {
    // Dead reckoning's velocity projections from heading and log speed, their covariance by the
    // Jacobian of (speed, heading) -> (vE, vN) (seed 002's Jacobi matrix).
    const double h = gyro->headingRad, v = log->speedMps, sh = std::sin(h), ch = std::cos(h);
    est::Mat<2> J;
    J << sh, v * ch, ch, -v * sh;
    const est::Mat<2> R = J * est::Vec<2>(log->varM2PerS2, gyro->varRad2).asDiagonal() * J.transpose();
    out.deadReckoning = est::update(belief_, VelocityModel{}, est::Vec<2>(v * sh, v * ch), R, gate_);
  }
  return out;
}

est::Gaussian<4> GeodeticKf::groundInGrid(const geo::LocalFrame& frame) const {
  const State& x = belief_.x;
  const geo::GridPoint p = frame.toLocal({radToDeg(x[kLat]), radToDeg(x[kLon])});
  // The projection's Jacobian by central differences (1e-7 rad is about 0.6 m).
  constexpr double d = 1e-7;
  const auto at = [&](double dLat, double dLon) {
    const geo::GridPoint q = frame.toLocal({radToDeg(x[kLat] + dLat), radToDeg(x[kLon] + dLon)});
    return est::Vec<2>(q.xM, q.yM);
  };
  est::Mat<2> Jp;
  Jp.col(0) = (at(d, 0) - at(-d, 0)) / (2 * d);
  Jp.col(1) = (at(0, d) - at(0, -d)) / (2 * d);
  const geo::GridInfo gi = frame.gridInfo(p);
  const double c = std::cos(gi.convergenceRad), s = std::sin(gi.convergenceRad);
  est::Mat<2> Jv;  // true (vE, vN) -> grid (vx, vy): rotate by -convergence, scale
  Jv << c, -s, s, c;
  Jv *= gi.scale;
  est::Mat<4> J = est::Mat<4>::Zero();
  J.topLeftCorner<2, 2>() = Jp;
  J.bottomRightCorner<2, 2>() = Jv;
  est::Gaussian<4> g;
  g.x << p.xM, p.yM, Jv * x.segment<2>(kVe);
  g.P = J * belief_.P.topLeftCorner<4, 4>() * J.transpose();
  est::symmetrise(g.P);
  return g;
}

}  // namespace reckoner::nav
