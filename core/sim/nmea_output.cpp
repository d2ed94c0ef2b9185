#include "sim/nmea_output.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "common/angles.h"
#include "common/units.h"
#include "io/nmea_out.h"

namespace reckoner::sim {
namespace {

namespace nm = io::nmea;

/// Grid velocity, position covariance and heading turned into true north/east at a grid point.
struct TrueOf {
  double gammaRad = 0.0, scale = 1.0;

  /// True bearing (deg, [0, 360)) of a grid vector.
  [[nodiscard]] double bearingDeg(double east, double north) const {
    return radToDeg(wrapTwoPi(bearingOf(east, north) + gammaRad));
  }
  /// The covariance of a grid position, in true north/east metres.
  void covariance(double cxx, double cyy, double cxy, OwnShipFix& f) const {
    // A grid vector (e_g, n_g) is (e, n) = (e_g cos g + n_g sin g, -e_g sin g + n_g cos g) / scale.
    const double c = std::cos(gammaRad), s = std::sin(gammaRad), k = 1.0 / (scale * scale);
    f.varEastM2 = k * (c * c * cxx + 2 * c * s * cxy + s * s * cyy);
    f.varNorthM2 = k * (s * s * cxx - 2 * c * s * cxy + c * c * cyy);
    f.covNorthEastM2 = k * (-s * c * cxx + (c * c - s * s) * cxy + s * c * cyy);
  }
};

TrueOf trueOf(const geo::LocalFrame& frame, double xM, double yM) {
  const geo::GridInfo g = frame.gridInfo({xM, yM});
  TrueOf t;
  if (std::isfinite(g.convergenceRad)) t.gammaRad = g.convergenceRad;
  if (std::isfinite(g.scale) && g.scale > 0) t.scale = g.scale;
  return t;
}

void motion(const TrueOf& t, double vx, double vy, OwnShipFix& f) {
  f.sogKn = mpsToKnots(std::hypot(vx, vy) / t.scale);
  f.cogTrueDeg = t.bearingDeg(vx, vy);
}

void current(const TrueOf& t, double cx, double cy, OwnShipFix& f) {
  if (!std::isfinite(cx) || !std::isfinite(cy)) return;
  f.setTrueDeg = t.bearingDeg(cx, cy);  // the direction the current sets toward
  f.driftKn = mpsToKnots(std::hypot(cx, cy) / t.scale);
}

char statusLetter(track::TrackStatus s) {
  switch (s) {
    case track::TrackStatus::Tentative:
      return 'Q';
    case track::TrackStatus::Confirmed:
      return 'T';
    case track::TrackStatus::Lost:
      return 'L';
  }
  return 'Q';
}

char priorityLetter(alerts::Priority p) {
  switch (p) {
    case alerts::Priority::Alarm:
      return 'A';
    case alerts::Priority::Warning:
      return 'W';
    case alerts::Priority::Caution:
      return 'C';
  }
  return 'W';
}

char stateLetter(alerts::AlertState s) {
  switch (s) {
    case alerts::AlertState::Unacknowledged:
      return 'V';
    case alerts::AlertState::Silenced:
      return 'S';
    case alerts::AlertState::Acknowledged:
      return 'A';
    case alerts::AlertState::Rectified:
      return 'U';
  }
  return 'V';
}

/// Category A: the alerts whose decision needs the task station's picture (targets); B the others.
char categoryLetter(alerts::AlertKind k) {
  switch (k) {
    case alerts::AlertKind::CpaTcpa:
    case alerts::AlertKind::GuardZone:
    case alerts::AlertKind::LostTarget:
    case alerts::AlertKind::LostAisTarget:
    case alerts::AlertKind::TrackFilterReset:
    case alerts::AlertKind::AisDistress:
      return 'A';
    default:
      return 'B';
  }
}

int kindIndex(alerts::AlertKind k) {
  return static_cast<int>(k);
}

/// ALF's alert identifier of a kind: in the range IEC 61924-2 leaves to manufacturers (10000 and up);
/// Reckoner's kinds are not the standard's alerts.
int alertIdentifier(alerts::AlertKind k) {
  return 10001 + kindIndex(k);
}

int positiveMod(long long v, int m) {
  return static_cast<int>(((v % m) + m) % m);
}

/// `preferred` if not taken, else the next number in [lo, hi] that is not (wrapping to lo); `preferred`
/// when every one is.
int firstFree(const std::set<int>& taken, int preferred, int lo, int hi) {
  for (int i = 0, n = hi - lo + 1; i < n; ++i) {
    const int c = lo + positiveMod(static_cast<long long>(preferred) - lo + i, n);
    if (!taken.contains(c)) return c;
  }
  return preferred;
}

}  // namespace

OwnShipFix ownShipFixOf(const OwnShipRow& row, UtcUs utc, const geo::LocalFrame& frame) {
  const TrueOf t = trueOf(frame, row.estXM, row.estYM);
  OwnShipFix f;
  f.utcUs = utc;
  f.latDeg = row.estLatDeg;
  f.lonDeg = row.estLonDeg;
  motion(t, row.estVxMps, row.estVyMps, f);
  if (std::isfinite(row.estHeadingRad))
    f.headingTrueDeg = radToDeg(wrapTwoPi(row.estHeadingRad + t.gammaRad));
  t.covariance(row.sdXM * row.sdXM, row.sdYM * row.sdYM, row.covXYM2, f);
  current(t, row.estCurrentXMps, row.estCurrentYMps, f);
  f.deadReckoning = row.deadReckoning;
  return f;
}

OwnShipFix ownShipFixOf(const ReplayOwnRow& row, const geo::LocalFrame& frame) {
  const GroundEstimate& e = row.estimate;
  const TrueOf t = trueOf(frame, e.xM, e.yM);
  OwnShipFix f;
  f.utcUs = row.utcUs;
  f.latDeg = e.latDeg;
  f.lonDeg = e.lonDeg;
  motion(t, e.vxMps, e.vyMps, f);
  if (std::isfinite(e.headingRad)) f.headingTrueDeg = radToDeg(wrapTwoPi(e.headingRad + t.gammaRad));
  t.covariance(e.sdXM * e.sdXM, e.sdYM * e.sdYM, e.covXYM2, f);
  current(t, row.calibration.currentXMps, row.calibration.currentYMps, f);
  f.deadReckoning = row.deadReckoning;
  return f;
}

NmeaOutput::NmeaOutput(NmeaOutputOptions options) : options_(std::move(options)) {}

std::vector<std::string> NmeaOutput::route(UtcUs utc, const nav::RouteStatus& status, const geo::Route& route,
                                           bool deadReckoning) {
  std::vector<std::string> out;
  if (!options_.route) return out;
  if (lastRouteUtc_ && utc >= *lastRouteUtc_ &&
      toSeconds(utc - *lastRouteUtc_) < options_.ownShipPeriodS - 1e-6)
    return out;
  lastRouteUtc_ = utc;
  const char mode = deadReckoning ? 'E' : 'A';
  const std::string& talker = options_.routeTalker;
  out.push_back(io::nmea::xte(talker, nav::xteOf(status, mode)));
  out.push_back(io::nmea::rmb(talker, nav::rmbOf(status, route, mode)));
  out.push_back(io::nmea::apb(talker, nav::apbOf(status, route, mode)));
  counters_.sentences += 3;
  return out;
}

std::vector<std::string> NmeaOutput::ownShip(const OwnShipFix& fix) {
  std::vector<std::string> out;
  if (!options_.ownShip && !options_.tracks) return out;
  if (!std::isfinite(fix.latDeg) || !std::isfinite(fix.lonDeg)) return out;
  if (lastOwnUtc_ && fix.utcUs >= *lastOwnUtc_ &&
      toSeconds(fix.utcUs - *lastOwnUtc_) < options_.ownShipPeriodS - 1e-6) {
    ++counters_.ownShipSkipped;
    return out;
  }
  lastOwnUtc_ = fix.utcUs;
  const char mode = fix.deadReckoning ? 'E' : 'A';
  const std::string& talker = options_.ownShipTalker;
  if (options_.ownShip) {
    // GGA before RMC: a reader that takes GGA's empty satellite count for no fix (gpsd 3.22) has the
    // RMC's fix last in each cycle.
    nm::GgaOut g;
    g.utc = fix.utcUs;
    g.latDeg = fix.latDeg;
    g.lonDeg = fix.lonDeg;
    g.quality = fix.deadReckoning ? 6 : 1;
    out.push_back(nm::gga(talker, g));
    out.push_back(nm::rmc(talker, {fix.utcUs, fix.latDeg, fix.lonDeg, fix.sogKn, fix.cogTrueDeg, mode}));
    out.push_back(nm::vtg(talker, {fix.cogTrueDeg, fix.sogKn, mode}));
    if (std::isfinite(fix.headingTrueDeg)) out.push_back(nm::hdt(talker, fix.headingTrueDeg));
    const nm::ErrorEllipse e = nm::errorEllipse(fix.varNorthM2, fix.varEastM2, fix.covNorthEastM2);
    nm::GstOut s;
    s.utc = fix.utcUs;
    s.majorSdM = e.majorSdM;
    s.minorSdM = e.minorSdM;
    s.majorOrientationDeg = e.orientationDeg;
    s.latSdM = std::sqrt(std::max(0.0, fix.varNorthM2));
    s.lonSdM = std::sqrt(std::max(0.0, fix.varEastM2));
    out.push_back(nm::gst(talker, s));
  }
  if (options_.tracks) {
    nm::OsdOut o;
    if (std::isfinite(fix.headingTrueDeg)) o.headingTrueDeg = fix.headingTrueDeg;
    o.courseTrueDeg = fix.cogTrueDeg;
    o.speedKn = fix.sogKn;
    const bool current = std::isfinite(fix.setTrueDeg) && std::isfinite(fix.driftKn);
    if (current) {
      o.setTrueDeg = fix.setTrueDeg;
      o.driftKn = fix.driftKn;
    }
    // Over ground from the positioning system while fixes come (`P`). Dead reckoning: the motion through
    // the water (`W`: the estimate over ground less the estimated current, which set and drift give), so
    // that a reader adding set and drift to it gets the ground track once, not the current twice.
    o.courseRef = o.speedRef = fix.deadReckoning ? 'W' : 'P';
    if (fix.deadReckoning && current && std::isfinite(fix.cogTrueDeg) && std::isfinite(fix.sogKn)) {
      const double cog = degToRad(fix.cogTrueDeg), set = degToRad(fix.setTrueDeg);
      const double east = fix.sogKn * std::sin(cog) - fix.driftKn * std::sin(set);
      const double north = fix.sogKn * std::cos(cog) - fix.driftKn * std::cos(set);
      o.speedKn = std::hypot(east, north);
      o.courseTrueDeg = radToDeg(wrapTwoPi(std::atan2(east, north)));
    }
    out.push_back(nm::osd(options_.radarTalker, o));
  }
  return counted(out);
}

std::vector<std::string> NmeaOutput::sweep(UtcUs utc, std::span<const TrackRow> tracks) {
  std::vector<std::string> out;
  if (!options_.tracks) return out;
  if (lastSweepUtc_ && utc == *lastSweepUtc_) {
    ++counters_.sweepsSkipped;
    return out;
  }
  lastSweepUtc_ = utc;
  // Numbers of the tracks that are gone are free again.
  for (auto it = numbers_.begin(); it != numbers_.end();) {
    const bool present =
        std::any_of(tracks.begin(), tracks.end(), [&](const TrackRow& t) { return t.trackId == it->first; });
    it = present ? std::next(it) : numbers_.erase(it);
  }
  for (const TrackRow& t : tracks) {
    auto it = numbers_.find(t.trackId);
    if (it == numbers_.end()) {
      std::optional<int> free;
      for (int k = 0; k < 100 && !free; ++k) {
        const int n = (nextNumber_ + k) % 100;
        if (std::none_of(numbers_.begin(), numbers_.end(), [n](const auto& p) { return p.second == n; }))
          free = n;
      }
      if (!free) {
        ++counters_.tracksUnnumbered;
        continue;
      }
      nextNumber_ = (*free + 1) % 100;
      it = numbers_.emplace(t.trackId, *free).first;
    }
    const std::string name = "TRK" + std::to_string(t.trackId);
    nm::TtmOut m;
    m.number = it->second;
    m.distanceNm = t.rangeNm;
    m.bearingDeg = t.bearingDeg;
    m.speedKn = t.speedKn;
    m.courseDeg = t.courseDeg;
    if (std::isfinite(t.cpaNm) && std::isfinite(t.tcpaMin)) {
      m.cpaNm = t.cpaNm;
      m.tcpaMin = t.tcpaMin;
    }
    m.name = name;
    m.status = statusLetter(t.status);
    m.utc = utc;
    m.acquisition = t.manual ? 'M' : 'A';
    out.push_back(nm::ttm(options_.radarTalker, m));
    nm::TllOut l;
    l.number = it->second;
    l.latDeg = t.estLatDeg;
    l.lonDeg = t.estLonDeg;
    l.name = name;
    l.utc = utc;
    l.status = m.status;
    out.push_back(nm::tll(options_.radarTalker, l));
  }
  return counted(out);
}

std::optional<int> NmeaOutput::targetNumber(int trackId) const {
  const auto it = numbers_.find(trackId);
  if (it == numbers_.end()) return std::nullopt;
  return it->second;
}

void NmeaOutput::number(const alerts::AlertId& id, Sent& s) const {
  std::set<int> numbers, instances;
  for (const auto& [other, o] : sent_) {
    if (other == id) continue;
    numbers.insert(o.alrNumber);
    if (other.kind == id.kind) instances.insert(o.instance);
  }
  // ALR: 50 numbers a kind (kind 0 from 001, kind 1 from 051, ...), the source's among them; ALF: the
  // source (track id, MMSI, ...) + 1 when it fits in six digits. The next free number when taken, so that
  // a receiver that keys on the number never mixes two alerts up.
  s.alrNumber = firstFree(numbers, kindIndex(id.kind) * 50 + 1 + positiveMod(id.source, 50), 1, 999);
  const long long own = static_cast<long long>(id.source) + 1;
  s.instance = firstFree(
      instances, own >= 1 && own <= 999999 ? static_cast<int>(own) : positiveMod(id.source, 999999) + 1, 1,
      999999);
}

void NmeaOutput::emitAlert(std::vector<std::string>& out, const alerts::Alert& a, const Sent& s,
                           UtcUs changedUtc, bool cleared) {
  const std::string title = alerts::traitsOf(a.id.kind).name;
  if (options_.alertSentences != AlertSentences::AlfAlc) {
    nm::AlrOut r;
    r.utc = changedUtc;
    r.number = s.alrNumber;
    r.active = !cleared && a.state != alerts::AlertState::Rectified;
    r.acknowledged = a.state == alerts::AlertState::Acknowledged;
    r.text = a.text.empty() ? title : title + ": " + a.text;
    out.push_back(nm::alr(options_.alertTalker, r));
  }
  if (options_.alertSentences != AlertSentences::Alr) {
    nm::AlfOut f;
    f.sequence = nextSequence();
    f.utc = changedUtc;
    f.category = categoryLetter(a.id.kind);
    f.priority = priorityLetter(a.priority);
    f.state = cleared ? 'N' : stateLetter(a.state);
    f.manufacturer = "RKN";
    f.identifier = alertIdentifier(a.id.kind);
    f.instance = s.instance;
    f.revision = s.revision;
    f.escalation = a.escalated ? 1 : 0;
    f.title = title;
    f.description = a.text;
    for (auto& l : nm::alf(options_.alertTalker, f)) out.push_back(std::move(l));
  }
}

std::vector<std::string> NmeaOutput::alerts(TimeUs now, UtcUs utc, const std::vector<alerts::Alert>& shown) {
  std::vector<std::string> out;
  if (!options_.alerts) return out;
  const TimeUs repeatUs = fromSeconds(options_.alertRepeatS);
  const auto utcOf = [&](TimeUs t) { return utc - (now - t); };
  // Gone: rectified and acknowledged, or ended (kinds that do not hold until acknowledged).
  for (auto it = sent_.begin(); it != sent_.end();) {
    const bool present =
        std::any_of(shown.begin(), shown.end(), [&](const alerts::Alert& a) { return a.id == it->first; });
    if (present) {
      ++it;
      continue;
    }
    Sent& s = it->second;
    s.revision = s.revision % 99 + 1;
    emitAlert(out, s.last, s, utc, true);
    it = sent_.erase(it);
  }
  for (const alerts::Alert& a : shown) {
    auto it = sent_.find(a.id);
    if (it == sent_.end()) {
      Sent s;
      s.state = a.state;
      s.priority = a.priority;
      s.escalated = a.escalated;
      s.sentUs = now;
      s.last = a;
      number(a.id, s);
      emitAlert(out, a, s, utcOf(a.changedUs), false);
      sent_.emplace(a.id, s);
      continue;
    }
    Sent& s = it->second;
    const bool changed = s.state != a.state || s.priority != a.priority || s.escalated != a.escalated;
    if (changed) s.revision = s.revision % 99 + 1;
    if (changed || now - s.sentUs >= repeatUs) {
      s.state = a.state;
      s.priority = a.priority;
      s.escalated = a.escalated;
      s.sentUs = now;
      s.last = a;
      emitAlert(out, a, s, utcOf(a.changedUs), false);
    }
  }
  if (options_.alertSentences != AlertSentences::Alr && (!lastListUs_ || now - *lastListUs_ >= repeatUs)) {
    lastListUs_ = now;
    std::vector<nm::AlcEntry> entries;
    for (const auto& [id, s] : sent_)
      entries.push_back({"RKN", alertIdentifier(id.kind), s.instance, s.revision});
    for (auto& l : nm::alc(options_.alertTalker, nextSequence(), entries)) out.push_back(std::move(l));
  }
  return counted(out);
}

std::vector<std::string> NmeaOutput::ais(std::string_view line) {
  std::vector<std::string> out;
  if (!options_.ais) return out;
  while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.remove_suffix(1);
  if (line.size() < 7 || line[0] != '!' || (line.substr(3, 3) != "VDM" && line.substr(3, 3) != "VDO"))
    return out;
  out.emplace_back(line);
  ++counters_.aisPassed;
  return counted(out);
}

RunNmeaOutput::RunNmeaOutput(const Scenario& scenario, UtcUs utc0, NmeaOutputOptions options)
    : geo_(scenario.origin.latDeg, scenario.origin.lonDeg),
      utc0_(utc0),
      out_(std::move(options)),
      feed_(alertFeedSettingsFor(scenario)),
      route_(scenario.voyage.route) {}

std::vector<std::string> RunNmeaOutput::frame(const SimFrame& f, const OwnShipRow& row,
                                              std::span<const TrackRow> tracks) {
  std::vector<std::string> lines = out_.ownShip(ownShipFixOf(row, utc0_ + row.timeUs, geo_));
  std::size_t i = 0;
  while (i < tracks.size()) {  // one sweep per time
    std::size_t j = i;
    while (j < tracks.size() && tracks[j].timeUs == tracks[i].timeUs) ++j;
    for (auto& l : out_.sweep(utc0_ + tracks[i].timeUs, tracks.subspan(i, j - i)))
      lines.push_back(std::move(l));
    i = j;
  }
  if (f.route && route_) {
    for (auto& l : out_.route(utc0_ + f.timeUs, *f.route, *route_, f.deadReckoning.active))
      lines.push_back(std::move(l));
  }
  feed_.feed(f, manager_);
  for (auto& l : out_.alerts(f.timeUs, utc0_ + f.timeUs, manager_.alerts())) lines.push_back(std::move(l));
  return lines;
}

std::vector<std::string> rowsNmea(NmeaOutput& out, std::span<const ReplayOwnRow> own,
                                  std::span<const TrackRow> tracks, std::span<const UtcUs> trackUtc,
                                  const geo::LocalFrame& frame) {
  std::vector<std::string> lines;
  const std::size_t n = std::min(tracks.size(), trackUtc.size());
  std::size_t t = 0;
  const auto sweepsUntil = [&](std::optional<UtcUs> until) {
    while (t < n && (!until || trackUtc[t] <= *until)) {
      std::size_t j = t;
      while (j < n && trackUtc[j] == trackUtc[t]) ++j;
      for (auto& l : out.sweep(trackUtc[t], tracks.subspan(t, j - t))) lines.push_back(std::move(l));
      t = j;
    }
  };
  for (const ReplayOwnRow& row : own) {
    sweepsUntil(row.utcUs);
    for (auto& l : out.ownShip(ownShipFixOf(row, frame))) lines.push_back(std::move(l));
  }
  sweepsUntil(std::nullopt);
  return lines;
}

std::vector<std::string> replayNmea(const ReplayResult& r, NmeaOutputOptions options) {
  NmeaOutput out(std::move(options));
  return rowsNmea(out, r.own, r.tracks, r.trackRowUtc, geo::LocalFrame(r.origin.latDeg, r.origin.lonDeg));
}

}  // namespace reckoner::sim
