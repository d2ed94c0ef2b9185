// The NMEA reader's second half (replay_nmea_detail.h): what each sentence offers its epoch, and the
// epochs with the active source of each quantity (sim/replay_sources.h).
#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "common/angles.h"
#include "common/units.h"
#include "sim/replay_nmea_detail.h"
#include "sim/stream_time.h"

namespace reckoner::sim::replay_input::detail {
namespace {
namespace nm = io::nmea;
using sources::Kind;
using sources::Quantity;

bool plausibleSpeedKn(double kn) {
  return std::isfinite(kn) && std::abs(kn) <= kMaxPlausibleSpeedKn;
}

/// A value one sentence offers its epoch; several sources may offer one quantity.
struct Candidate {
  sources::Offer offer;  ///< offer.index: the sentence (index into the parsed sentences)
  geo::GeoPoint position;
  std::optional<double> hdop;
  double aMps = 0.0, bRad = 0.0;  ///< velocity: sog, cog; heading: -, heading
  bool magnetic = false;
  sensors::SpeedlogMode mode = sensors::SpeedlogMode::BottomLock;
};

enum class Use { Valid, Unusable, NotGnss, Implausible, NoVariation };

/// The latest magnetic variation known while reading (HDG's or RMC's, else the configured one).
struct Variation {
  std::optional<double> deg;
};

/// What one sentence offers its epoch (into `out`), and whether it was valid: one call per sentence
/// type (std::visit on the sentence's body).
class SentenceOffers {
 public:
  SentenceOffers(const Parsed& p, std::size_t index, Variation& var, std::vector<Candidate>& out)
      : p_(p), index_(index), var_(var), out_(out) {}

  Use operator()(const nm::Rmc& b) {
    if (b.variationDeg) var_.deg = b.variationDeg;
    if (!b.valid) return Use::Unusable;
    if (!nm::gnssFix(b.mode)) return Use::NotGnss;
    if (b.sogKn && !plausibleSpeedKn(*b.sogKn)) return Use::Implausible;
    Candidate c = offer(Quantity::Position, 2);
    c.position = {b.latDeg, b.lonDeg};
    out_.push_back(c);
    if (b.sogKn && b.cogTrueDeg) {
      Candidate v = offer(Quantity::Velocity, 0);
      v.aMps = knotsToMps(*b.sogKn);
      v.bRad = degToRad(*b.cogTrueDeg);
      out_.push_back(v);
    }
    return Use::Valid;
  }
  Use operator()(const nm::Gga& b) {
    if (b.quality == 0) return Use::Unusable;
    return gnssPosition(nm::gnssFix(b.quality), {b.latDeg, b.lonDeg}, b.hdop);
  }
  Use operator()(const nm::Gns& b) {
    if (!b.hasPosition) return Use::Unusable;
    return gnssPosition(nm::gnssFix(std::string_view(b.modes)), {b.latDeg, b.lonDeg}, b.hdop);
  }
  Use operator()(const nm::Vtg& b) {
    if (!b.cogTrueDeg || b.mode == 'N') return Use::Unusable;
    if (!nm::gnssFix(b.mode)) return Use::NotGnss;
    if (!plausibleSpeedKn(b.sogKn)) return Use::Implausible;
    Candidate v = offer(Quantity::Velocity, 1);
    v.aMps = knotsToMps(b.sogKn);
    v.bRad = degToRad(*b.cogTrueDeg);
    out_.push_back(v);
    return Use::Valid;
  }
  Use operator()(const nm::Gll& b) {
    if (!b.valid) return Use::Unusable;
    if (!nm::gnssFix(b.mode)) return Use::NotGnss;
    Candidate c = offer(p_.kind.quantity, p_.kind.rank);  // a GNSS or (talker LC) a Loran-C position
    c.position = {b.latDeg, b.lonDeg};
    out_.push_back(c);
    return Use::Valid;
  }
  Use operator()(const nm::Ths& b) {
    if (b.mode != 'A') return b.mode == 'V' ? Use::Unusable : Use::NotGnss;
    return heading(b.headingDeg, false, 0);
  }
  Use operator()(const nm::Hdt& b) { return heading(b.headingDeg, false, 1); }
  Use operator()(const nm::Hdg& b) {
    if (b.variationDeg) var_.deg = b.variationDeg;
    if (!var_.deg) return Use::NoVariation;
    return heading(b.sensorDeg + b.deviationDeg.value_or(0.0) + *var_.deg, true, 2);
  }
  Use operator()(const nm::Hdm& b) {
    if (!var_.deg) return Use::NoVariation;
    return heading(b.headingDeg + *var_.deg, true, 3);
  }
  Use operator()(const nm::Vhw& b) {
    if (!plausibleSpeedKn(b.speedKn)) return Use::Implausible;
    Candidate l = offer(Quantity::SpeedLog, 1);
    l.aMps = knotsToMps(b.speedKn);
    l.mode = sensors::SpeedlogMode::BottomLock;
    out_.push_back(l);
    // Its heading fields, after every compass sentence (a plotter's copy of them).
    if (b.headingTrueDeg)
      heading(*b.headingTrueDeg, false, 4);
    else if (b.headingMagneticDeg && var_.deg)
      heading(*b.headingMagneticDeg + *var_.deg, true, 5);
    return Use::Valid;
  }
  Use operator()(const nm::Vbw& b) {
    Candidate l = offer(Quantity::SpeedLog, 0);
    if (b.longGroundKn) {
      const double kn = std::hypot(*b.longGroundKn, *b.transGroundKn);
      if (!plausibleSpeedKn(kn)) return Use::Implausible;
      l.aMps = knotsToMps(kn);
      l.mode = sensors::SpeedlogMode::GroundLock;
    } else if (b.longWaterKn) {
      const double kn = std::hypot(*b.longWaterKn, *b.transWaterKn);
      if (!plausibleSpeedKn(kn)) return Use::Implausible;
      l.aMps = knotsToMps(kn);
    } else {
      return Use::Unusable;
    }
    out_.push_back(l);
    return Use::Valid;
  }
  /// ZDA (time), GST (accuracy, taken with its fix), ROT and DTM: nothing to offer here.
  template <typename Other>
  Use operator()(const Other&) {
    return Use::Valid;
  }

 private:
  [[nodiscard]] Candidate offer(Quantity q, int rank) const {
    Candidate c;
    c.offer = {p_.source, Kind{q, rank}, index_};
    return c;
  }
  Use heading(double trueDeg, bool magnetic, int rank) {
    Candidate c = offer(Quantity::Heading, rank);
    c.bRad = wrapTwoPi(degToRad(trueDeg));
    c.magnetic = magnetic;
    out_.push_back(c);
    return Use::Valid;
  }
  /// GGA's or GNS's position, when it is a GNSS fix.
  Use gnssPosition(bool fix, geo::GeoPoint position, std::optional<double> hdop) {
    if (!fix) return Use::NotGnss;
    Candidate c = offer(Quantity::Position, p_.kind.rank);
    c.position = position;
    c.hdop = hdop;
    out_.push_back(c);
    return Use::Valid;
  }

  const Parsed& p_;
  std::size_t index_;
  Variation& var_;
  std::vector<Candidate>& out_;
};

/// A time-only epoch at most this often (Epoch::empty()).
constexpr UtcUs kHeartbeatUs = 900'000;

/// The sentences of one epoch's time: their offers, and each talker's GST (the sentence index).
struct EpochOffers {
  std::vector<Candidate> candidates;
  std::map<std::string, std::size_t> gstOf;
};

/// The epochs, each with the value of the active source of each quantity; counts what each sentence
/// became (used, standby, skipped by reason) into its source's and the file's counts.
class Assembler {
 public:
  Assembler(const NmeaOptions& o, ReplayStats& st, std::map<sources::SourceId, SourceStats>& stats)
      : st_(st),
        stats_(stats),
        var_{o.variationDeg},
        selector_(static_cast<std::int64_t>(std::llround(o.holdS * 1e6))) {}

  /// The epoch at t of these sentences (file order within it): offered, chosen and counted.
  void epoch(UtcUs t, const std::vector<const Parsed*>& sentences, std::vector<Epoch>& out) {
    ps_ = &sentences;
    used_.assign(sentences.size(), 0);
    valid_.assign(sentences.size(), 0);
    repeated_.assign(sentences.size(), 0);
    EpochOffers offers;
    for (std::size_t i = 0; i < sentences.size(); ++i) offer(i, offers);
    addEpoch(t, offers, out);
    countOutcomes();
    ps_ = nullptr;
  }

 private:
  [[nodiscard]] const Parsed& at(std::size_t i) const { return *(*ps_)[i]; }

  /// Sentence i's offers into e, counted by what it was.
  void offer(std::size_t i, EpochOffers& e) {
    SourceStats& s = stats_[at(i).source];
    switch (std::visit(SentenceOffers(at(i), i, var_, e.candidates), at(i).sentence.body)) {
      case Use::Valid:
        valid_[i] = 1;
        if (std::holds_alternative<nm::Gst>(at(i).sentence.body)) e.gstOf[at(i).sentence.talker] = i;
        break;
      case Use::Unusable:
        ++st_.unusable, ++s.unusable;
        break;
      case Use::NotGnss:
        ++st_.notGnss, ++s.notMeasured;
        break;
      case Use::Implausible:
        ++st_.implausible, ++s.implausible;
        break;
      case Use::NoVariation:
        ++st_.noVariation, ++s.unusable;
        break;
    }
  }

  /// The epoch at t: each quantity's value from its active source; kept unless it is a time-only
  /// epoch too soon after the last.
  void addEpoch(UtcUs t, const EpochOffers& offers, std::vector<Epoch>& out) {
    credit(t);
    Epoch e;
    e.utc = t;
    for (int qi = 0; qi < sources::kQuantityCount; ++qi) choose(static_cast<Quantity>(qi), t, offers, e);
    lastT_ = t;
    any_ = true;
    // A second with sentences but no own-ship data (ZDA alone while the GNSS is out, say): the recorder
    // is running, so dead reckoning goes on. Kept as a time-only epoch when no epoch was in the last
    // 0.9 s (a ZDA stamped just after its second's fixes adds nothing).
    if (!e.empty() || out.empty() || t - out.back().utc >= kHeartbeatUs) out.push_back(e);
  }

  /// Each valid sentence of the epoch: used (what it offered went in, or it is time or accuracy), or
  /// standby.
  void countOutcomes() {
    for (std::size_t i = 0; i < ps_->size(); ++i) {
      if (!valid_[i]) continue;
      SourceStats& s = stats_[at(i).source];
      const Quantity q = at(i).kind.quantity;
      if (used_[i] || q == Quantity::Time) {
        ++st_.sentencesUsed, ++s.used;
      } else if (q == Quantity::Other || q == Quantity::Accuracy) {
        ++st_.notUsed;  // ROT, DTM of WGS-84, a GST whose fix was not taken
      } else if (repeated_[i]) {
        ++st_.repeated, ++s.repeated;  // its source gave the epoch's value in an earlier sentence
      } else {
        ++st_.standby, ++s.standby;
      }
    }
  }

  /// Active time of each quantity's source up to t.
  void credit(UtcUs t) {
    if (!any_) return;
    for (int q = 0; q < sources::kQuantityCount; ++q)
      if (!previous_[static_cast<std::size_t>(q)].empty())
        stats_[previous_[static_cast<std::size_t>(q)]].activeS += 1e-6 * static_cast<double>(t - lastT_);
  }

  /// Quantity q of epoch e (at t): the active source's offer, if any.
  void choose(Quantity q, UtcUs t, const EpochOffers& eo, Epoch& e) {
    std::vector<const sources::Offer*> offers;
    for (const Candidate& c : eo.candidates)
      if (c.offer.kind.quantity == q) offers.push_back(&c.offer);
    const sources::Offer* pick = offers.empty() ? nullptr : selector_.choose(q, t, offers);
    previous_[static_cast<std::size_t>(q)] = selector_.active(q);
    if (!pick) return;
    const Candidate& c = *std::find_if(eo.candidates.begin(), eo.candidates.end(),
                                       [&](const Candidate& k) { return &k.offer == pick; });
    used_[c.offer.index] = 1;
    for (const sources::Offer* other : offers)
      if (other != pick && other->source == pick->source) repeated_[other->index] = 1;
    switch (q) {
      case Quantity::Position:
        e.gps = c.position;
        e.gpsHdop = c.hdop.value_or(1.0);
        takeGst(c, eo, e);
        break;
      case Quantity::Loran:
        e.loran = c.position;
        break;
      case Quantity::Velocity:
        e.gpsVelocity = std::pair{c.aMps, c.bRad};
        break;
      case Quantity::Heading:
        e.headingRad = c.bRad;
        e.headingMagnetic = c.magnetic;
        break;
      case Quantity::SpeedLog:
        e.log = std::pair{c.aMps, c.mode};
        break;
      default:
        break;
    }
  }

  /// The receiver's own error statistics, when it sent them for this fix: the larger axis.
  void takeGst(const Candidate& fix, const EpochOffers& eo, Epoch& e) {
    const auto it = eo.gstOf.find(at(fix.offer.index).sentence.talker);
    if (it == eo.gstOf.end()) return;
    const auto& gst = std::get<nm::Gst>(at(it->second).sentence.body);
    if (gst.latSdM && gst.lonSdM) {
      e.gpsVarM2 = std::max(*gst.latSdM * *gst.latSdM, *gst.lonSdM * *gst.lonSdM);
      used_[it->second] = 1;
    }
  }

  const std::vector<const Parsed*>* ps_ = nullptr;
  ReplayStats& st_;
  std::map<sources::SourceId, SourceStats>& stats_;
  Variation var_;
  sources::Selector selector_;
  std::vector<char> used_, valid_, repeated_;
  UtcUs lastT_ = 0;
  bool any_ = false;
  std::array<sources::SourceId, sources::kQuantityCount> previous_{};
};

}  // namespace

struct EpochAssembler::Impl : Assembler {
  using Assembler::Assembler;
};

EpochAssembler::EpochAssembler(const NmeaOptions& o, ReplayStats& st,
                               std::map<sources::SourceId, SourceStats>& stats)
    : impl_(std::make_unique<Impl>(o, st, stats)) {}
EpochAssembler::~EpochAssembler() = default;

void EpochAssembler::addEpoch(UtcUs t, const std::vector<const Parsed*>& sentences, std::vector<Epoch>& out) {
  impl_->epoch(t, sentences, out);
}

std::vector<Epoch> assembleEpochs(const std::vector<Parsed>& ps, const TimedGroups& groups,
                                  const NmeaOptions& o, ReplayStats& st,
                                  std::map<sources::SourceId, SourceStats>& stats) {
  const std::vector<std::size_t> order = replayOrder(groups.utc, {}, st.reordered);
  EpochAssembler assembler(o, st, stats);
  std::vector<Epoch> out;
  std::vector<const Parsed*> sentences;
  for (std::size_t g = 0; g < order.size();) {
    const UtcUs t = groups.utc[order[g]];
    sentences.clear();
    for (; g < order.size() && groups.utc[order[g]] == t; ++g)
      for (const std::size_t i : groups.sentences[order[g]]) sentences.push_back(&ps[i]);
    assembler.addEpoch(t, sentences, out);
  }
  return out;
}

}  // namespace reckoner::sim::replay_input::detail
