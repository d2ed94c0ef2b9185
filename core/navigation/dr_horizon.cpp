#include "navigation/dr_horizon.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <vector>

#include "common/angles.h"
#include "estimation/chi_square.h"
#include "estimation/models/drkf_gyro.h"
#include "estimation/models/drkf_speedlog.h"

namespace reckoner::nav {

double positionError95M(const drkf::Belief& b) {
  static const double k95 = est::chiSquareQuantile(0.95, 2.0);
  est::Mat<2> P;
  P << b.P(drkf::kPosX, drkf::kPosX), b.P(drkf::kPosX, drkf::kPosY), b.P(drkf::kPosY, drkf::kPosX),
      b.P(drkf::kPosY, drkf::kPosY);
  const Eigen::SelfAdjointEigenSolver<est::Mat<2>> eig(P, Eigen::EigenvaluesOnly);
  return std::sqrt(k95 * std::max(0.0, eig.eigenvalues()[1]));
}

std::optional<double> timeToPositionLimitS(const Drkf& filter, const DeadReckoningAids& aids, double limitM,
                                           double maxS) {
  if (!(limitM > 0.0) || !(maxS > 0.0)) return std::nullopt;
  if (positionError95M(filter.belief()) >= limitM) return 0.0;
  Drkf f = filter;
  const double stepS = std::max(5.0, aids.periodS);
  const TimeUs t0 = f.timeUs();
  std::vector<sensors::OwnShipSample> samples;
  for (double elapsed = stepS; elapsed <= maxS + 1e-9; elapsed += stepS) {
    const TimeUs t = t0 + fromSeconds(elapsed);
    if (!f.predictTo(t)) return std::nullopt;
    const drkf::State& x = f.belief().x;
    const geo::GridInfo g = f.frame().gridInfo({x[drkf::kPosX], x[drkf::kPosY]});
    samples.clear();
    if (aids.speedlog) {
      const auto mode = aids.speedlogMode == sensors::SpeedlogMode::GroundLock
                            ? est::drkf::SpeedlogModel::Mode::GroundLock
                            : est::drkf::SpeedlogModel::Mode::BottomLock;
      const double gridSpeed = est::drkf::SpeedlogModel(mode, 0.0).h(x)[0];
      samples.emplace_back(
          sensors::SpeedlogSample{t, gridSpeed / g.scale, aids.speedlogMode, aids.speedlogVarM2PerS2});
    }
    if (aids.gyro) {
      const double gridHeading = est::drkf::GyroHeadingModel(0.0).h(x)[0];
      samples.emplace_back(
          sensors::GyroSample{t, wrapTwoPi(gridHeading + g.convergenceRad), aids.gyroVarRad2});
    }
    if (!samples.empty()) f.update(t, samples);
    if (positionError95M(f.belief()) >= limitM) return elapsed;
  }
  return std::nullopt;
}

}  // namespace reckoner::nav
