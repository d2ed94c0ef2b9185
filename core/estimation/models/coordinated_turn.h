#pragma once
// Target motion models for the IMM (issue 6), in the grid frame, state [x, y, vx, vy, w]: position (m),
// velocity over ground (m/s) and turn rate w (rad/s, clockwise positive, as bearings).
//   Constant velocity (CV): x' = x + T v, v' = v, w' = 0.
//   Coordinated turn (CT): the velocity rotates clockwise by wT (seed 000 Table II's footnote form)
//     vx' = vx cos wT + vy sin wT,   vy' = -vx sin wT + vy cos wT
//     x'  = x + (vx sin wT + vy (1 - cos wT)) / w,   y' = y + (-vx (1 - cos wT) + vy sin wT) / w
//   and w' = w; for small wT the factors are taken from their series (no cancellation near w = 0).
// Both have white acceleration noise q (m^2/s^3) on each axis; CT also a random-walk turn rate (qw,
// rad^2/s^3).
#include <cmath>

#include "estimation/gaussian.h"

namespace reckoner::est::ct {

enum Index : int { kX = 0, kY, kVx, kVy, kW, kStateDim };
using State = Vec<kStateDim>;
using Covariance = Mat<kStateDim>;

inline State cvPredict(const State& s, double T) {
  State o = s;
  o[kX] += T * s[kVx];
  o[kY] += T * s[kVy];
  o[kW] = 0.0;
  return o;
}

inline Covariance cvTransition(double T) {
  Covariance F = Covariance::Identity();
  F(kX, kVx) = F(kY, kVy) = T;
  F(kW, kW) = 0.0;
  return F;
}

/// sin(wT)/w and (1 - cos(wT))/w, by their series when |wT| is small (no cancellation).
inline void turnFactors(double w, double T, double& sinOverW, double& oneMinusCosOverW) {
  const double th = w * T;
  if (std::abs(th) < 1e-3) {
    sinOverW = T * (1.0 - th * th / 6.0);
    oneMinusCosOverW = T * (th / 2.0 - th * th * th / 24.0);
  } else {
    sinOverW = std::sin(th) / w;
    oneMinusCosOverW = (1.0 - std::cos(th)) / w;
  }
}

inline State ctPredict(const State& s, double T) {
  const double w = s[kW], vx = s[kVx], vy = s[kVy];
  double a = 0.0, b = 0.0;
  turnFactors(w, T, a, b);
  State o = s;
  o[kX] += vx * a + vy * b;
  o[kY] += -vx * b + vy * a;
  o[kVx] = vx * std::cos(w * T) + vy * std::sin(w * T);
  o[kVy] = -vx * std::sin(w * T) + vy * std::cos(w * T);
  return o;
}

/// d ctPredict / d state (analytic; tested against the numeric Jacobian).
inline Covariance ctTransition(const State& s, double T) {
  const double w = s[kW], vx = s[kVx], vy = s[kVy];
  const double th = w * T, sn = std::sin(th), cs = std::cos(th);
  double a = 0.0, b = 0.0;
  turnFactors(w, T, a, b);
  // d a / dw and d b / dw.
  double da = 0.0, db = 0.0;
  if (std::abs(th) < 1e-3) {
    da = -T * T * th / 3.0;
    db = T * T * (0.5 - th * th / 8.0);
  } else {
    da = T * cs / w - sn / (w * w);
    db = T * sn / w - (1.0 - cs) / (w * w);
  }
  Covariance F = Covariance::Identity();
  F(kX, kVx) = a;
  F(kX, kVy) = b;
  F(kY, kVx) = -b;
  F(kY, kVy) = a;
  F(kX, kW) = vx * da + vy * db;
  F(kY, kW) = -vx * db + vy * da;
  F(kVx, kVx) = cs;
  F(kVx, kVy) = sn;
  F(kVy, kVx) = -sn;
  F(kVy, kVy) = cs;
  F(kVx, kW) = T * (-vx * sn + vy * cs);
  F(kVy, kW) = T * (-vx * cs - vy * sn);
  return F;
}

/// White acceleration q on each axis; turn-rate random walk qw (0 for CV, whose w is reset to 0).
inline Covariance noise(double q, double qw, double T) {
  Covariance Q = Covariance::Zero();
  for (int a = 0; a < 2; ++a) {
    const int p = kX + a, v = kVx + a;
    Q(p, p) = q * T * T * T / 3.0;
    Q(p, v) = Q(v, p) = q * T * T / 2.0;
    Q(v, v) = q * T;
  }
  Q(kW, kW) = qw * T;
  return Q;
}

}  // namespace reckoner::est::ct
