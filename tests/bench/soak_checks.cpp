#include "soak_checks.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "navigation/drkf.h"
#include "sim/run_rows.h"

namespace reckoner::soak {

void NeesSeries::add(double nees, double hourIndex, double q99) {
  const auto h = static_cast<std::size_t>(std::max(0.0, hourIndex));
  if (hours.size() <= h) hours.resize(h + 1);
  hours[h].sum += nees;
  ++hours[h].count;
  if (nees > q99) ++hours[h].aboveQ99;
}

NeesHour NeesSeries::total() const {
  NeesHour t;
  for (const NeesHour& h : hours) {
    t.sum += h.sum;
    t.count += h.count;
    t.aboveQ99 += h.aboveQ99;
  }
  return t;
}

FrameChecker::FrameChecker(const sim::Scenario& scenario, const est::drkf::ProcessParams& process)
    : scenario_(scenario), process_(process) {
  for (std::size_t i = 0; i < scenario_.targets.size(); ++i) index_[scenario_.targets[i].id] = i;
  r_.own.dof = nav::neesDof(process);
  r_.tracks.dof = 4;
  ownQ99_ = est::chiSquareQuantile(0.99, r_.own.dof);
  trackQ99_ = est::chiSquareQuantile(0.99, r_.tracks.dof);
}

void FrameChecker::problem(const sim::SimFrame& f, const std::string& what) {
  if (r_.problems.size() >= 20) return;
  char buf[64];
  std::snprintf(buf, sizeof buf, "t = %.1f s: ", toSeconds(f.timeUs));
  r_.problems.push_back(buf + what);
}

template <int N>
void FrameChecker::covariance(const est::Mat<N>& P, const est::Vec<N>& x, const sim::SimFrame& f,
                              int trackId) {
  // (the label is made only for a problem: this runs for every track of every frame)
  const auto what = [trackId] {
    return trackId < 0 ? std::string("own ship") : "track " + std::to_string(trackId);
  };
  ++r_.covariancesChecked;
  if (!P.allFinite() || !x.allFinite()) {
    ++r_.nonFinite;
    problem(f, what() + ": a NaN or infinity");
    return;
  }
  const double scale = std::max(1.0, P.cwiseAbs().maxCoeff());
  if ((P - P.transpose()).cwiseAbs().maxCoeff() > 1e-9 * scale) {
    ++r_.asymmetric;
    problem(f, what() + ": covariance not symmetric");
  }
  const Eigen::LLT<est::Mat<N>> llt(P);
  if (llt.info() != Eigen::Success) {
    ++r_.notPositiveDefinite;
    problem(f, what() + ": covariance not positive definite");
  }
}

void FrameChecker::sweeps(const sim::SimFrame& f) {
  for (const sim::SweepSnapshot& sw : f.sweeps) {
    for (const sim::TrackSnapshot& t : sw.tracks) {
      if (t.status != track::TrackStatus::Confirmed || t.targetId < 0) continue;
      const auto it = index_.find(t.targetId);
      if (it == index_.end() || it->second >= sw.targets.size() ||
          !scenario_.targets[it->second].presentAt(sw.timeUs))
        continue;
      const double nees = sim::positionVelocityNees4(t.estimate, sw.targets[it->second]);
      if (std::isfinite(nees)) r_.tracks.add(nees, toSeconds(sw.timeUs) / 3600.0, trackQ99_);
    }
  }
}

void FrameChecker::check(const sim::SimFrame& f) {
  ++r_.frames;
  covariance<est::drkf::kStateDim>(f.estimate.P, f.estimate.x, f, -1);
  for (const sim::TrackSnapshot& t : f.tracks)
    covariance<est::ttkf::kStateDim>(t.estimate.P, t.estimate.x, f, t.trackId);
  if (f.hasTruth) {
    const double nees = nav::drkfNees(f.trueState - f.estimate.x, f.estimate.P, process_);
    if (std::isfinite(nees)) r_.own.add(nees, toSeconds(f.timeUs) / 3600.0, ownQ99_);
  }
  sweeps(f);
  if (f.aisTargets) {
    for (const track::AisTarget& a : *f.aisTargets)
      if ((a.latDeg && !std::isfinite(*a.latDeg)) || (a.lonDeg && !std::isfinite(*a.lonDeg)) ||
          (a.sogKn && !std::isfinite(*a.sogKn))) {
        ++r_.nonFinite;
        problem(f, "AIS target " + std::to_string(a.mmsi) + ": a NaN or infinity");
      }
    r_.maxAisTargets =
        std::max<std::int64_t>(r_.maxAisTargets, static_cast<std::int64_t>(f.aisTargets->size()));
  }
  r_.maxTracks = std::max<std::int64_t>(r_.maxTracks, static_cast<std::int64_t>(f.tracks.size()));
  r_.maxTargetsPresent = std::max<std::int64_t>(
      r_.maxTargetsPresent, std::count(f.targetPresent.begin(), f.targetPresent.end(), std::uint8_t{1}));
}

}  // namespace reckoner::soak
