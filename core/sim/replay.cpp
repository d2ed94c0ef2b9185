#include "sim/replay.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <map>

#include "common/angles.h"
#include "common/units.h"
#include "io/input_error.h"
#include "io/nmea.h"
#include "tracking/cpa.h"

namespace reckoner::sim {
namespace {
namespace nm = io::nmea;
constexpr std::int64_t kUsPerDay = 86400LL * 1000000LL;

std::vector<std::string_view> lines(const std::string& text) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string_view l(text.data() + start, end - start);
    if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
    out.push_back(l);
    start = end + 1;
  }
  return out;
}

/// One own-ship epoch being assembled from the sentences that share a timestamp.
struct Epoch {
  UtcUs utc = 0;
  std::optional<geo::GeoPoint> gps;
  std::optional<std::pair<double, double>> gpsVelocity;  ///< sog m/s, cog true rad
  std::optional<geo::GeoPoint> loran;
  std::optional<double> headingRad;
  std::optional<std::pair<double, sensors::SpeedlogMode>> log;  ///< m/s
};

struct Plot {
  UtcUs utc;
  double rangeM, bearingRad;
  int tag;
};

std::optional<double> toNumber(std::string_view f) {
  while (!f.empty() && f.front() == ' ') f.remove_prefix(1);
  while (!f.empty() && f.back() == ' ') f.remove_suffix(1);
  if (f.empty()) return std::nullopt;
  double v = 0.0;
  const auto [p, ec] = std::from_chars(f.data(), f.data() + f.size(), v);
  if (ec != std::errc() || p != f.data() + f.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

std::vector<Plot> readRadar(const std::string& text, const std::string& name, ReplayStats& st) {
  const auto ls = lines(text);
  if (ls.empty())
    throw io::InputError(name, 1, "header", "empty file; expected 'utc,range_m,bearing_deg[,target_id]'");
  std::string header(ls[0]);
  header.erase(std::remove(header.begin(), header.end(), ' '), header.end());
  const bool withId = header == "utc,range_m,bearing_deg,target_id";
  if (!withId && header != "utc,range_m,bearing_deg")
    throw io::InputError(name, 1, "header",
                         "expected 'utc,range_m,bearing_deg[,target_id]', got '" + header + "'");
  std::vector<Plot> out;
  for (std::size_t i = 1; i < ls.size(); ++i) {
    if (ls[i].empty()) continue;
    ++st.radarLines;
    std::vector<std::string_view> f;
    std::size_t s = 0;
    while (true) {
      const std::size_t c = ls[i].find(',', s);
      f.push_back(ls[i].substr(s, c == std::string_view::npos ? std::string_view::npos : c - s));
      if (c == std::string_view::npos) break;
      s = c + 1;
    }
    if (f.size() != (withId ? 4u : 3u)) {
      ++st.radarBad;
      continue;
    }
    const auto utc = parseIso8601(f[0]);
    const auto r = toNumber(f[1]), b = toNumber(f[2]);
    int tag = -1;
    bool ok = utc && r && b && *r >= 0.0 && *b >= 0.0 && *b <= 360.0;
    if (ok && withId && !f[3].empty()) {
      const auto id = toNumber(f[3]);
      ok = id && *id >= 0 && *id == std::floor(*id) && *id < 1e9;
      if (ok) tag = static_cast<int>(*id);
    }
    if (!ok) {
      ++st.radarBad;
      continue;
    }
    if (!out.empty() && *utc < out.back().utc) {
      ++st.radarOutOfOrder;
      continue;
    }
    out.push_back({*utc, *r, degToRad(*b), tag});
  }
  st.radarPlots = static_cast<long>(out.size());
  return out;
}

std::vector<Epoch> readNmea(const std::string& text, const std::string& name, ReplayStats& st) {
  const auto ls = lines(text);
  // The date: the first RMC or ZDA that carries one (earlier sentences share its day).
  std::optional<nm::Date> date;
  std::optional<double> firstTod;
  for (const auto l : ls) {
    const auto r = nm::parse(l);
    if (!r.sentence) continue;
    if (const auto* rmc = std::get_if<nm::Rmc>(&r.sentence->body); rmc && rmc->date) {
      date = rmc->date;
      firstTod = rmc->timeOfDayS;
      break;
    }
    if (const auto* zda = std::get_if<nm::Zda>(&r.sentence->body)) {
      date = zda->date;
      firstTod = zda->timeOfDayS;
      break;
    }
  }
  if (!date)
    throw io::InputError(name, 0, "", "no RMC or ZDA sentence with a date: the replay needs UTC dates");
  UtcUs dayStart = daysFromCivil(date->year, date->month, date->day) * kUsPerDay;
  std::optional<double> lastTod;
  std::optional<UtcUs> current;
  std::vector<Epoch> out;
  for (std::size_t i = 0; i < ls.size(); ++i) {
    const auto r = nm::parse(ls[i]);
    if (r.error == nm::Error::Empty) continue;
    ++st.nmeaLines;
    switch (r.error) {
      case nm::Error::BadChecksum:
        ++st.badChecksum;
        continue;
      case nm::Error::Unknown:
        ++st.unknownSentences;
        continue;
      case nm::Error::Malformed:
        ++st.malformed;
        continue;
      default:
        break;
    }
    const nm::Sentence& s = *r.sentence;
    std::optional<double> tod;
    std::visit(
        [&](const auto& b) {
          using T = std::decay_t<decltype(b)>;
          if constexpr (std::is_same_v<T, nm::Rmc> || std::is_same_v<T, nm::Gga> ||
                        std::is_same_v<T, nm::Zda>)
            tod = b.timeOfDayS;
          else if constexpr (std::is_same_v<T, nm::Gll>)
            tod = b.timeOfDayS;
        },
        s.body);
    if (tod) {
      // Before the dated sentence: same day, unless the clock wrapped past midnight.
      if (!lastTod && firstTod && *tod > *firstTod + 43200.0) dayStart -= kUsPerDay;
      if (lastTod && *tod < *lastTod - 43200.0) dayStart += kUsPerDay;
      lastTod = tod;
      const UtcUs t = dayStart + static_cast<UtcUs>(std::llround(*tod * 1e6));
      if (current && t < *current) {
        ++st.outOfOrder;
        continue;
      }
      current = t;
    }
    if (!current) {
      ++st.untimed;
      continue;
    }
    if (out.empty() || out.back().utc != *current) out.push_back(Epoch{*current, {}, {}, {}, {}, {}});
    Epoch& e = out.back();
    bool used = true;
    std::visit(
        [&](const auto& b) {
          using T = std::decay_t<decltype(b)>;
          if constexpr (std::is_same_v<T, nm::Rmc>) {
            if (!b.valid) {
              used = false;
              return;
            }
            if (!e.gps) e.gps = geo::GeoPoint{b.latDeg, b.lonDeg};
            if (b.sogKn && b.cogTrueDeg && !e.gpsVelocity)
              e.gpsVelocity = std::pair{knotsToMps(*b.sogKn), degToRad(*b.cogTrueDeg)};
          } else if constexpr (std::is_same_v<T, nm::Gga>) {
            if (b.quality <= 0) {
              used = false;
              return;
            }
            if (!e.gps) e.gps = geo::GeoPoint{b.latDeg, b.lonDeg};
          } else if constexpr (std::is_same_v<T, nm::Vtg>) {
            if (!b.cogTrueDeg) {
              used = false;
              return;
            }
            e.gpsVelocity = std::pair{knotsToMps(b.sogKn), degToRad(*b.cogTrueDeg)};
          } else if constexpr (std::is_same_v<T, nm::Gll>) {
            if (!b.valid) {
              used = false;
              return;
            }
            if (s.talker == "LC")
              e.loran = geo::GeoPoint{b.latDeg, b.lonDeg};
            else if (!e.gps)
              e.gps = geo::GeoPoint{b.latDeg, b.lonDeg};
          } else if constexpr (std::is_same_v<T, nm::Hdt>) {
            e.headingRad = degToRad(b.headingDeg);
          } else if constexpr (std::is_same_v<T, nm::Vhw>) {
            if (!e.log) e.log = std::pair{knotsToMps(b.speedKn), sensors::SpeedlogMode::BottomLock};
          } else if constexpr (std::is_same_v<T, nm::Vbw>) {
            if (b.longGroundKn)
              e.log = std::pair{knotsToMps(std::hypot(*b.longGroundKn, *b.transGroundKn)),
                                sensors::SpeedlogMode::GroundLock};
            else if (b.longWaterKn && !e.log)
              e.log = std::pair{knotsToMps(std::hypot(*b.longWaterKn, *b.transWaterKn)),
                                sensors::SpeedlogMode::BottomLock};
            else
              used = false;
          } else {
            // ZDA: time only.
          }
        },
        s.body);
    if (used)
      ++st.sentencesUsed;
    else
      ++st.unusable;
  }
  return out;
}

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
}  // namespace

std::int64_t daysFromCivil(int y, int m, int d) {
  // Count of days from 1970-01-01 (proleptic Gregorian), by years shifted to start in March.
  y -= m <= 2 ? 1 : 0;
  const std::int64_t era = (y >= 0 ? y : y - 399) / 400;
  const std::int64_t yoe = y - era * 400;
  const std::int64_t doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1;
  const std::int64_t doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  return era * 146097 + doe - 719468;
}

std::optional<UtcUs> parseIso8601(std::string_view s) {
  while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
  while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
  if (s.size() < 20 || s[4] != '-' || s[7] != '-' || s[10] != 'T' || s[13] != ':' || s[16] != ':' ||
      s.back() != 'Z')
    return std::nullopt;
  const auto num = [&](std::size_t at, std::size_t n) -> std::optional<int> {
    int v = 0;
    const auto [p, ec] = std::from_chars(s.data() + at, s.data() + at + n, v);
    if (ec != std::errc() || p != s.data() + at + n) return std::nullopt;
    return v;
  };
  const auto y = num(0, 4), mo = num(5, 2), d = num(8, 2), h = num(11, 2), mi = num(14, 2);
  const auto sec = toNumber(s.substr(17, s.size() - 18));
  if (!y || !mo || !d || !h || !mi || !sec || *mo < 1 || *mo > 12 || *d < 1 || *d > 31 || *h > 23 ||
      *mi > 59 || *sec < 0.0 || *sec >= 61.0)
    return std::nullopt;
  return daysFromCivil(*y, *mo, *d) * kUsPerDay +
         (static_cast<std::int64_t>(*h) * 3600 + *mi * 60) * 1000000LL +
         static_cast<std::int64_t>(std::llround(*sec * 1e6));
}

std::string formatIso8601(UtcUs t) {
  std::int64_t days = t >= 0 ? t / kUsPerDay : (t - kUsPerDay + 1) / kUsPerDay;
  std::int64_t us = t - days * kUsPerDay;
  // Civil from days (inverse of daysFromCivil).
  days += 719468;
  const std::int64_t era = (days >= 0 ? days : days - 146096) / 146097;
  const std::int64_t doe = days - era * 146097;
  const std::int64_t yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
  std::int64_t y = yoe + era * 400;
  const std::int64_t doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
  const std::int64_t mp = (5 * doy + 2) / 153;
  const std::int64_t d = doy - (153 * mp + 2) / 5 + 1;
  const std::int64_t m = mp < 10 ? mp + 3 : mp - 9;
  y += m <= 2 ? 1 : 0;
  const std::int64_t h = us / 3600000000LL;
  us -= h * 3600000000LL;
  const std::int64_t mi = us / 60000000LL;
  us -= mi * 60000000LL;
  char buf[96];
  std::snprintf(buf, sizeof buf, "%04lld-%02lld-%02lldT%02lld:%02lld:%02lld.%06lldZ",
                static_cast<long long>(y), static_cast<long long>(m), static_cast<long long>(d),
                static_cast<long long>(h), static_cast<long long>(mi), static_cast<long long>(us / 1000000),
                static_cast<long long>(us % 1000000));
  return buf;
}

ReplayResult replay(const std::string& nmeaText, const std::string& nmeaName, const std::string* radarCsv,
                    const std::string& radarName, const ReplayOptions& o) {
  ReplayResult res;
  const std::vector<Epoch> epochs = readNmea(nmeaText, nmeaName, res.stats);
  const std::vector<Plot> plots = radarCsv ? readRadar(*radarCsv, radarName, res.stats) : std::vector<Plot>{};
  if (epochs.empty()) throw io::InputError(nmeaName, 0, "", "no usable timed sentence");
  res.utc0 = epochs.front().utc;
  const auto firstFix =
      std::find_if(epochs.begin(), epochs.end(), [](const Epoch& e) { return e.gps || e.loran; });
  if (firstFix == epochs.end())
    throw io::InputError(nmeaName, 0, "", "no position fix (RMC, GGA or GLL) to start from");
  res.origin = o.originFromSettings ? o.settings.origin : (firstFix->gps ? *firstFix->gps : *firstFix->loran);
  const geo::LocalFrame frame(res.origin.latDeg, res.origin.lonDeg);
  const Scenario& st = o.settings;
  const auto rel = [&](UtcUs u) -> TimeUs { return u - res.utc0; };

  // Start the DRKF at the first fix, with the velocity of that epoch when GPS gave one.
  const nav::DrkfConfig config = drkfConfigFor(st);
  est::drkf::Belief initial;
  const geo::GridPoint p0 = frame.toLocal(firstFix->gps ? *firstFix->gps : *firstFix->loran);
  const bool hasVel = firstFix->gpsVelocity.has_value();
  initial.P = nav::initialCovariance(
      config.process, firstFix->gps ? std::sqrt(st.gps.positionVarM2) * 2.0 : 100.0, hasVel ? 1.0 : 8.0);
  initial.x.setZero();
  initial.x[est::drkf::kPosX] = p0.xM;
  initial.x[est::drkf::kPosY] = p0.yM;
  if (hasVel) {
    const geo::GridInfo g = frame.gridInfo(p0);
    const double courseGrid = firstFix->gpsVelocity->second - g.convergenceRad;
    initial.x[est::drkf::kVelX] = firstFix->gpsVelocity->first * std::sin(courseGrid);
    initial.x[est::drkf::kVelY] = firstFix->gpsVelocity->first * std::cos(courseGrid);
  }
  nav::Drkf drkf(config, frame, initial, rel(firstFix->utc));
  track::TrackManagerConfig tmc = trackManagerConfigFor(st.tracker, st.radar.sweepPeriodS);
  tmc.association = o.assumeAssociation ? track::Association::Known : track::Association::Nearest;
  track::TrackManager bank(tmc);

  const auto ownInput = [&]() {
    track::OwnShipInput in{drkf.timeUs(), nav::groundStateOf(drkf.belief()),
                           nav::groundCovarianceOf(drkf.belief()), 0.0};
    in.convergenceRad = frame.gridInfo({in.x[0], in.x[1]}).convergenceRad;
    return in;
  };
  const TimeUs sweepUs = fromSeconds(st.radar.sweepPeriodS);
  std::optional<TimeUs> nextSweepEnd;
  const auto closeSweepsUntil = [&](TimeUs t) {
    while (nextSweepEnd && *nextSweepEnd <= t) {
      bank.endSweep(*nextSweepEnd);
      const double gamma = ownInput().convergenceRad;
      for (const auto& tr : bank.tracks()) {
        const auto b = bank.beliefAt(tr, *nextSweepEnd);
        const TrackRow r = trackEstimateRow(*nextSweepEnd, tr.id, tr.tag(), tr.status, tr.dangerous, b,
                                            track::kinematicsOf(b, gamma), tr.lastRadar.nis, frame);
        res.tracks.push_back(r);
        res.trackRowUtc.push_back(res.utc0 + *nextSweepEnd);
      }
      *nextSweepEnd += sweepUs;
    }
  };

  const auto processPlot = [&](const Plot& p) {
    const TimeUs tp = rel(p.utc);
    if (tp < drkf.timeUs()) {
      ++res.stats.radarBeforeFix;
      return;
    }
    if (!nextSweepEnd) nextSweepEnd = tp + sweepUs;
    closeSweepsUntil(tp);
    const auto own = ownInput();
    const sensors::RadarPlot rp{tp, p.rangeM, p.bearingRad, st.radar.plotRangeVarM2(),
                                st.radar.plotBearingVarRad2()};
    bank.addPlot(track::toGrid(rp, frame.gridInfo({own.x[0], own.x[1]})), p.tag);
  };

  std::size_t pi = 0;
  for (const Epoch& e : epochs) {
    ++res.stats.epochs;
    const TimeUs t = rel(e.utc);
    // Plots up to (not including) this epoch.
    for (; pi < plots.size() && rel(plots[pi].utc) < t; ++pi) processPlot(plots[pi]);
    if (t < drkf.timeUs()) {
      ++res.stats.epochsBeforeFix;
      continue;
    }
    closeSweepsUntil(t);
    std::vector<sensors::OwnShipSample> samples;
    if (e.gps) {
      sensors::GpsSample g{t, frame.toLocal(*e.gps), st.gps.positionVarM2, false, 0.0, 0.0, 0.0};
      if (e.gpsVelocity) {
        g.hasVelocity = true;
        g.velEastMps = e.gpsVelocity->first * std::sin(e.gpsVelocity->second);
        g.velNorthMps = e.gpsVelocity->first * std::cos(e.gpsVelocity->second);
        g.velocityVarM2PerS2 = st.gps.velocityVarM2PerS2;
      }
      samples.emplace_back(g);
    }
    if (e.loran) samples.emplace_back(sensors::LoranSample{t, frame.toLocal(*e.loran), st.loran.whiteVarM2});
    if (e.log)
      samples.emplace_back(
          sensors::SpeedlogSample{t, e.log->first, e.log->second, st.speedlog.whiteVarM2PerS2});
    if (e.headingRad)
      samples.emplace_back(sensors::GyroSample{t, *e.headingRad, st.gyro.sdRad * st.gyro.sdRad});
    const nav::DrkfUpdateReport rep = drkf.update(t, samples);
    bank.feedOwnShip(ownInput());
    ReplayOwnRow r;
    r.timeUs = t;
    r.utcUs = e.utc;
    r.estimate = groundEstimateOf(drkf.belief(), frame);
    r.sensors = labelOf(samples);
    r.rowsApplied = rep.dim;
    res.own.push_back(r);
  }
  // Plots after the last epoch are processed against the last own-ship estimate.
  for (; pi < plots.size(); ++pi) processPlot(plots[pi]);
  if (nextSweepEnd) closeSweepsUntil(*nextSweepEnd);  // the last sweep ends with the data
  res.drkf = drkf.counters();
  res.tracking = bank.counters();
  return res;
}

}  // namespace reckoner::sim
