#include "sim/replay_runner.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/angles.h"
#include "io/error_line.h"
#include "tracking/cpa.h"

namespace reckoner::sim::replay_runner {
namespace {

/// Positions farther than this from the replay's origin lie outside its grid frame (the UTM zone's
/// scale error passes 1% about there; GeographicLib's series stop being valid not far beyond).
constexpr double kMaxFrameDistanceM = 1000e3;
/// Epochs in a row whose update failed numerically before the DRKF is restarted at the next fix.
constexpr int kFailedEpochsBeforeRestart = 3;
/// Sweeps closed one by one after the bank has emptied, before a gap in the plots is skipped whole.
constexpr int kIdleSweeps = 3;
/// A live frame shows a sensor on while its latest sample is at most this old.
constexpr TimeUs kSensorHeardUs = 10 * kMicrosPerSecond;
/// Plots a live frame carries at most (a flood of plots between two epochs is thinned for display).
constexpr std::size_t kMaxFramePlots = 4096;

std::string labelOf(const std::vector<sensors::OwnShipSample>& samples) {
  std::string s;
  for (const auto& m : samples) {
    if (!s.empty()) s += '+';
    switch (sensors::sensorOf(m)) {
      case sensors::SensorId::Gps:
        s += "gps";
        break;
      case sensors::SensorId::LoranC:
        s += "loran_c";
        break;
      case sensors::SensorId::Speedlog:
        s += std::get<sensors::SpeedlogSample>(m).mode == sensors::SpeedlogMode::GroundLock ? "speedlog_gl"
                                                                                            : "speedlog_bl";
        break;
      case sensors::SensorId::Gyro:
        s += "gyro";
        break;
    }
  }
  return s.empty() ? "none" : s;
}

CalibrationEstimate calibrationOf(const est::drkf::Belief& b, const est::drkf::ProcessParams& p) {
  namespace dk = est::drkf;
  const auto sd = [&](int i) { return std::sqrt(std::max(0.0, b.P(i, i))); };
  CalibrationEstimate c;
  c.currentXMps = b.x[dk::kCurX];
  c.currentYMps = b.x[dk::kCurY];
  c.sdCurrentXMps = sd(dk::kCurX);
  c.sdCurrentYMps = sd(dk::kCurY);
  if (p.headingBias.sigma > 0.0) {
    c.headingBiasRad = b.x[dk::kHeadingBias];
    c.sdHeadingBiasRad = sd(dk::kHeadingBias);
  }
  if (p.logScale.sigma > 0.0) {
    c.logScale = b.x[dk::kLogScale];
    c.sdLogScale = sd(dk::kLogScale);
  }
  if (p.speedlogError.sigma > 0.0) {
    c.logOffsetMps = b.x[dk::kLogBias];
    c.sdLogOffsetMps = sd(dk::kLogBias);
  }
  return c;
}

}  // namespace

geo::GeoPoint chooseOrigin(const ReplayOptions& o, const Epoch& first, const std::string& nmeaName,
                           std::vector<std::string>& warnings) {
  const geo::GeoPoint fix = first.gps ? *first.gps : *first.loran;
  if (!o.originFromSettings) return fix;
  const geo::LocalFrame frame(o.settings.origin.latDeg, o.settings.origin.lonDeg);
  const geo::GridPoint p = frame.toLocal(fix);
  const double d = std::hypot(p.xM, p.yM);
  if (std::isfinite(d) && d <= kMaxFrameDistanceM) return o.settings.origin;
  char buf[200];
  std::snprintf(
      buf, sizeof buf,
      "origin: %.4f, %.4f lies %s from the first fix of %s (%.4f, %.4f); the replay's grid "
      "frame starts at that fix instead",
      o.settings.origin.latDeg, o.settings.origin.lonDeg,
      std::isfinite(d) ? (std::to_string(static_cast<long>(d / 1000.0)) + " km").c_str() : "too far",
      nmeaName.c_str(), fix.latDeg, fix.lonDeg);
  warnings.push_back(
      io::oneLine((o.settingsName.empty() ? std::string("settings") : o.settingsName) + ": " + buf));
  return fix;
}

track::TrackManagerConfig trackerConfigOf(const ReplayOptions& o) {
  track::TrackManagerConfig c = trackManagerConfigFor(o.settings.tracker, o.settings.radar.sweepPeriodS);
  c.association = o.assumeAssociation ? track::Association::Known : track::Association::Nearest;
  return c;
}

std::optional<geo::GridPoint> Runner::inFrame(const std::optional<geo::GeoPoint>& p) {
  if (!p) return std::nullopt;
  const geo::GridPoint g = frame_.toLocal(*p);
  if (std::isfinite(g.xM) && std::isfinite(g.yM) && std::hypot(g.xM, g.yM) <= kMaxFrameDistanceM) return g;
  ++res_.stats.outsideFrame;
  return std::nullopt;
}

void Runner::start(const Epoch& e, TimeUs t, const std::optional<geo::GridPoint>& gps,
                   const std::optional<geo::GridPoint>& loran) {
  // At the fix, with the velocity of that epoch when GPS gave one.
  const bool hasVel = gps && e.gpsVelocity;
  est::drkf::Belief initial;
  initial.P = nav::initialCovariance(config_.process, gps ? std::sqrt(gpsVarianceOf(e)) * 2.0 : 100.0,
                                     hasVel ? 1.0 : 8.0);
  initial.x.setZero();
  const geo::GridPoint p0 = gps ? *gps : *loran;
  initial.x[est::drkf::kPosX] = p0.xM;
  initial.x[est::drkf::kPosY] = p0.yM;
  if (hasVel) {
    const double courseGrid = e.gpsVelocity->second - frame_.gridInfo(p0).convergenceRad;
    initial.x[est::drkf::kVelX] = e.gpsVelocity->first * std::sin(courseGrid);
    initial.x[est::drkf::kVelY] = e.gpsVelocity->first * std::cos(courseGrid);
  }
  drkf_.emplace(config_, frame_, initial, t);
}

track::OwnShipInput Runner::ownInput() const {
  track::OwnShipInput in{drkf_->timeUs(), nav::groundStateOf(drkf_->belief()),
                         nav::groundCovarianceOf(drkf_->belief()), 0.0};
  in.convergenceRad = frame_.gridInfo({in.x[0], in.x[1]}).convergenceRad;
  return in;
}

void Runner::count(const nav::DrkfUpdateReport& rep, const std::vector<sensors::OwnShipSample>& samples) {
  if (rep.blockCount == 0 && rep.joint.status != est::UpdateStatus::Empty) {
    // The prediction itself failed: nothing was tried, every sample failed.
    for (const auto& m : samples) {
      switch (sensors::sensorOf(m)) {
        case sensors::SensorId::Gps:
          ++res_.updates[nav::kGpsPosition].failed;
          if (std::get<sensors::GpsSample>(m).hasVelocity) ++res_.updates[nav::kGpsVelocity].failed;
          break;
        case sensors::SensorId::LoranC:
          ++res_.updates[nav::kLoranPosition].failed;
          break;
        case sensors::SensorId::Speedlog:
          ++res_.updates[nav::kSpeedlog].failed;
          break;
        case sensors::SensorId::Gyro:
          ++res_.updates[nav::kGyro].failed;
          break;
      }
    }
    return;
  }
  for (int i = 0; i < rep.blockCount; ++i) {
    const est::BlockReport& b = rep.blocks[static_cast<std::size_t>(i)];
    SensorUpdateCounts& c = res_.updates[static_cast<std::size_t>(b.tag)];
    const bool gated = b.status == est::UpdateStatus::RejectedGate;
    if (est::isApplied(b.status))
      ++c.accepted;
    else if (gated)
      ++c.gated;
    else if (b.status != est::UpdateStatus::Empty)
      ++c.failed;
  }
  nav::addToNisWindows(rep, nis_);
}

void Runner::ownShip(const Epoch& e) {
  ReplayStats& stats = res_.stats;
  ++stats.epochs;
  if (e.empty()) ++stats.epochsTimeOnly;
  const TimeUs t = rel(e.utc);
  if (drkf_ && lastEpochUs_ && t - *lastEpochUs_ > maxGapUs_) {
    // Nothing recorded for longer than the max gap: the ship may be anywhere, heading and speed anything.
    stop();
    ++stats.restartsAfterGap;
    restarted_ = true;
  }
  lastEpochUs_ = t;
  const auto gps = inFrame(e.gps), loran = inFrame(e.loran);
  if (!drkf_) {
    if (!gps && !loran) {
      ++(restarted_ ? stats.epochsAwaitingFix : stats.epochsBeforeFix);
      return;
    }
    start(e, t, gps, loran);
  }
  closeSweepsUntil(t);
  const Scenario& st = o_.settings;
  std::vector<sensors::OwnShipSample> samples;
  if (gps) {
    sensors::GpsSample g{t, *gps, gpsVarianceOf(e), false, 0.0, 0.0, 0.0};
    if (e.gpsVelocity) {
      g.hasVelocity = true;
      g.velEastMps = e.gpsVelocity->first * std::sin(e.gpsVelocity->second);
      g.velNorthMps = e.gpsVelocity->first * std::cos(e.gpsVelocity->second);
      g.velocityVarM2PerS2 = st.gps.velocityVarM2PerS2;
    }
    samples.emplace_back(g);
  }
  if (loran) samples.emplace_back(sensors::LoranSample{t, *loran, st.loran.whiteVarM2});
  if (e.log)
    samples.emplace_back(
        sensors::SpeedlogSample{t, e.log->first, e.log->second, st.speedlog.whiteVarM2PerS2});
  if (e.headingRad) {
    const double sd = e.headingMagnetic ? degToRad(o_.magneticHeadingSdDeg) : st.gyro.sdRad;
    samples.emplace_back(sensors::GyroSample{t, *e.headingRad, sd * sd});
  }
  const nav::DrkfUpdateReport rep = drkf_->update(t, samples);
  count(rep, samples);
  if (config_.adaptiveGnssNoise)
    res_.gnssNoiseScale = {drkf_->gnssNoiseScale().scale(0), drkf_->gnssNoiseScale().scale(1)};
  const bool failed = rep.joint.status == est::UpdateStatus::RejectedNumerical ||
                      rep.joint.status == est::UpdateStatus::RejectedNonFinite;
  failedEpochs_ = failed ? failedEpochs_ + 1 : 0;
  if (bank_) bank_->feedOwnShip(ownInput());
  ReplayOwnRow r;
  r.timeUs = t;
  r.utcUs = e.utc;
  r.estimate = groundEstimateOf(drkf_->belief(), frame_);
  r.calibration = calibrationOf(drkf_->belief(), config_.process);
  r.sensors = samples.empty() ? "none" : labelOf(samples);
  r.rowsApplied = rep.dim;
  deadReckoning_.addEpoch(rep);
  const nav::DeadReckoningStatus dr = deadReckoning_.evaluate(t);
  r.deadReckoning = dr.active;
  res_.own.push_back(r);
  if (sink_) {
    emitFrame(t, std::move(samples), rep, dr);
  } else if (bank_) {
    (void)bank_->takeEvents();  // no one reads them: keep the bank's event list bounded
  }
  if (failedEpochs_ >= kFailedEpochsBeforeRestart) {
    stop();
    ++stats.restartsAfterFailure;
    restarted_ = true;
  }
}

void Runner::stop() {
  if (!drkf_) return;
  const nav::DrkfCounters& c = drkf_->counters();
  nav::DrkfCounters& sum = res_.drkf;
  for (std::size_t b = 0; b < c.byStatus.size(); ++b)
    for (std::size_t k = 0; k < c.byStatus[b].size(); ++k) sum.byStatus[b][k] += c.byStatus[b][k];
  sum.predictFailures += c.predictFailures;
  sum.staleSamples += c.staleSamples;
  sum.overflowSamples += c.overflowSamples;
  sum.resets += c.resets;
  drkf_.reset();
  failedEpochs_ = 0;
}

void Runner::closeSweepsUntil(TimeUs t) {
  int idle = 0;
  while (nextSweepEnd_ && *nextSweepEnd_ <= t) {
    if (bank_->tracks().empty() && ++idle > kIdleSweeps) {
      // Nothing left to close: skip the rest of a gap in the plots whole (a gap of years costs nothing).
      *nextSweepEnd_ += (t - *nextSweepEnd_) / sweepUs_ * sweepUs_;
      if (*nextSweepEnd_ <= t) *nextSweepEnd_ += sweepUs_;
      break;
    }
    bank_->endSweep(*nextSweepEnd_);
    const double gamma = drkf_ ? ownInput().convergenceRad : 0.0;
    for (const auto& tr : bank_->tracks()) {
      const auto b = bank_->beliefAt(tr, *nextSweepEnd_);
      res_.tracks.push_back(trackEstimateRow(*nextSweepEnd_, tr.id, tr.tag(), tr.status, tr.dangerous, b,
                                             track::kinematicsOf(b, gamma), tr.lastRadar.nis, frame_));
      res_.tracks.back().manoeuvring = tr.manoeuvring;
      res_.tracks.back().manual = tr.manual;
      res_.trackRowUtc.push_back(res_.utc0 + *nextSweepEnd_);
    }
    if (sink_) {
      SweepSnapshot snap;
      snap.timeUs = *nextSweepEnd_;
      for (const auto& tr : bank_->tracks())
        snap.tracks.push_back(trackSnapshotOf(*bank_, tr, snap.timeUs, gamma));
      sweeps_.push_back(std::move(snap));
    }
    *nextSweepEnd_ += sweepUs_;
  }
}

void Runner::emitFrame(TimeUs t, std::vector<sensors::OwnShipSample>&& samples,
                       const nav::DrkfUpdateReport& rep, const nav::DeadReckoningStatus& dr) {
  SimFrame f;
  f.timeUs = t;
  f.hasTruth = false;
  f.estimate = drkf_->belief();
  // No truth: the estimate stands in its place for geometry only (SimFrame::hasTruth).
  f.trueState = f.estimate.x;
  f.truth.timeUs = t;
  f.truth.position = {f.estimate.x[est::drkf::kPosX], f.estimate.x[est::drkf::kPosY]};
  f.truth.waterVxMps = f.estimate.x[est::drkf::kVelX] - f.estimate.x[est::drkf::kCurX];
  f.truth.waterVyMps = f.estimate.x[est::drkf::kVelY] - f.estimate.x[est::drkf::kCurY];
  f.truth.currentXMps = f.estimate.x[est::drkf::kCurX];
  f.truth.currentYMps = f.estimate.x[est::drkf::kCurY];
  const double heading = headingOf(f.estimate);
  f.truth.headingRad = std::isfinite(heading) ? heading : 0.0;
  for (std::size_t b = 0; b < nis_.size(); ++b) f.noisierThanConfigured[b] = nis_[b].lastAbove();
  for (const auto& m : samples) {
    lastSampleUs_[static_cast<std::size_t>(sensors::sensorOf(m))] = t;
    if (const auto* log = std::get_if<sensors::SpeedlogSample>(&m)) logMode_ = log->mode;
  }
  for (std::size_t i = 0; i < lastSampleUs_.size(); ++i)
    f.sensors.on[i] = lastSampleUs_[i] && t - *lastSampleUs_[i] <= kSensorHeardUs;
  f.sensors.speedlogMode = logMode_;
  f.measurements = std::move(samples);
  f.updates.push_back(rep);
  f.deadReckoning = dr;
  if (bank_) {
    const double gamma = ownInput().convergenceRad;
    for (const auto& tr : bank_->tracks()) f.tracks.push_back(trackSnapshotOf(*bank_, tr, t, gamma));
    f.trackEvents = bank_->takeEvents();
    f.capacityWarning = bank_->capacityWarning();
    f.zones = bank_->zones();
  }
  f.sweeps.swap(sweeps_);
  f.plots.swap(plots_);
  f.plotSources.assign(f.plots.size(), -1);
  sink_(std::move(f));
}

void Runner::plot(const Plot& p) {
  const TimeUs tp = rel(p.utc);
  if (!drkf_ || tp < drkf_->timeUs()) {
    ++res_.stats.radarBeforeFix;
    return;
  }
  if (!nextSweepEnd_) nextSweepEnd_ = tp + sweepUs_;
  closeSweepsUntil(tp);
  const auto own = ownInput();
  const sensors::RadarPlot rp{tp, p.rangeM, p.bearingRad, o_.settings.radar.plotRangeVarM2(),
                              o_.settings.radar.plotBearingVarRad2()};
  bank_->addPlot(track::toGrid(rp, frame_.gridInfo({own.x[0], own.x[1]})), p.tag);
  if (sink_ && plots_.size() < kMaxFramePlots) plots_.push_back(rp);
}

void Runner::finish() {
  if (nextSweepEnd_) closeSweepsUntil(*nextSweepEnd_);  // the last sweep ends with the data
  stop();
  if (bank_) res_.tracking = bank_->counters();
  for (std::size_t b = 0; b < nis_.size(); ++b) {
    const est::NisWindowCounts& n = res_.updates[b].nis = nis_[b].counts();
    // A fifth of the windows or more above the band: the sensor is noisier than the settings say (the gate
    // will reject good data, the sd is too small).
    if (n.windows >= 3 && 5 * n.above >= n.windows) {
      char buf[240];
      std::snprintf(buf, sizeof buf,
                    "%s: innovations larger than its configured noise in %ld of %ld windows of 60 updates "
                    "(mean NIS per degree of freedom %.2f): the sensor's noise is larger than configured",
                    nav::blockName(static_cast<nav::DrkfBlock>(b)), n.above, n.windows, n.meanPerDof());
      res_.warnings.push_back(buf);
    }
  }
}

}  // namespace reckoner::sim::replay_runner
