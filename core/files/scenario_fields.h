#pragma once
// Internal to files/: what the scenario reader's parts share (scenario_json.h is the interface). The
// Fields reader of one JSON object (unknown fields are errors), the checked helpers, and the one name
// table per enumeration that both the reader and the writer use.
#include <array>
#include <functional>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "common/step_schedule.h"
#include "common/time.h"
#include "estimation/gauss_markov.h"
#include "io/input_error.h"
#include "io/json.h"
#include "sim/scenario.h"

namespace reckoner::files::scenario_detail {

using sensors::SpeedlogMode;

inline std::string formatNumber(double v) {
  std::ostringstream o;
  o << v;
  return o.str();
}

/// Reads one JSON object's fields, tracking which were used so that unknown ones are reported.
class Fields {
 public:
  Fields(const std::string& file, const io::JsonValue& v, std::string path)
      : file_(file), v_(v), path_(std::move(path)) {
    if (!v.isObject()) fail(v, path_, std::string("must be an object, got ") + typeName(v.type));
    used_.assign(v.object.size(), false);
  }

  [[noreturn]] void fail(const io::JsonValue& at, const std::string& path, const std::string& msg) const {
    throw io::InputError(file_, at.line, path, msg);
  }
  [[nodiscard]] std::string pathOf(std::string_view key) const {
    return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
  }
  [[nodiscard]] const std::string& file() const { return file_; }

  const io::JsonValue* get(std::string_view key) {
    for (std::size_t i = 0; i < v_.object.size(); ++i) {
      if (v_.object[i].first == key) {
        used_[i] = true;
        return &v_.object[i].second;
      }
    }
    return nullptr;
  }
  const io::JsonValue& require(std::string_view key) {
    const io::JsonValue* v = get(key);
    if (!v) fail(v_, pathOf(key), "required field is missing");
    return *v;
  }

  enum class Check { Any, Positive, NonNegative };

  double number(std::string_view key, Check check = Check::Any) {
    return checkedNumber(require(key), pathOf(key), check);
  }
  double numberOr(std::string_view key, double fallback, Check check = Check::Any) {
    const io::JsonValue* v = get(key);
    return v ? checkedNumber(*v, pathOf(key), check) : fallback;
  }
  /// An optional integer in [lo, hi].
  int integerOr(std::string_view key, int lo, int hi, int fallback) {
    const io::JsonValue* c = get(key);
    if (!c) return fallback;
    if (!c->isNumber() || c->number < lo || c->number > hi || std::floor(c->number) != c->number)
      fail(*c, pathOf(key), "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return static_cast<int>(c->number);
  }
  double checkedNumber(const io::JsonValue& v, const std::string& path, Check check) const {
    if (!v.isNumber()) fail(v, path, std::string("must be a number, got ") + typeName(v.type));
    if (check == Check::Positive && !(v.number > 0.0))
      fail(v, path, "must be positive, got " + formatNumber(v.number));
    if (check == Check::NonNegative && !(v.number >= 0.0))
      fail(v, path, "must not be negative, got " + formatNumber(v.number));
    return v.number;
  }
  std::string stringOr(std::string_view key, std::string fallback) {
    const io::JsonValue* v = get(key);
    if (!v) return fallback;
    if (!v->isString()) fail(*v, pathOf(key), std::string("must be a string, got ") + typeName(v->type));
    return v->string;
  }
  bool boolean(const io::JsonValue& v, const std::string& path) const {
    if (!v.isBool()) fail(v, path, std::string("must be true or false, got ") + typeName(v.type));
    return v.boolean;
  }
  std::array<double, 2> pair(std::string_view key, std::array<double, 2> fallback) {
    const io::JsonValue* v = get(key);
    if (!v) return fallback;
    if (!v->isArray() || v->array.size() != 2)
      fail(*v, pathOf(key), "must be an array of two numbers [x, y]");
    return {checkedNumber(v->array[0], pathOf(key) + "[0]", Check::Any),
            checkedNumber(v->array[1], pathOf(key) + "[1]", Check::Any)};
  }

  /// Reports the first field nobody asked for.
  void finish() const {
    for (std::size_t i = 0; i < v_.object.size(); ++i)
      if (!used_[i]) fail(v_.object[i].second, pathOf(v_.object[i].first), "unknown field");
  }

  [[nodiscard]] const io::JsonValue& json() const { return v_; }

 private:
  const std::string& file_;
  const io::JsonValue& v_;
  std::string path_;
  std::vector<bool> used_;
};

/// One enumeration's spellings in scenario files, with what each means (for the error message).
template <typename E>
struct NamedValue {
  E value;
  std::string_view name, meaning;
};

template <typename E, std::size_t N>
std::string_view nameOf(const std::array<NamedValue<E>, N>& table, E value) {
  for (const auto& t : table)
    if (t.value == value) return t.name;
  return table.front().name;  // unreachable for a complete table
}

/// The value spelled `v`, or a failure listing the spellings: must be "a" (meaning) or "b" (meaning).
template <typename E, std::size_t N>
E valueOf(const std::array<NamedValue<E>, N>& table, const Fields& f, const io::JsonValue& v,
          const std::string& path) {
  if (v.isString())
    for (const auto& t : table)
      if (v.string == t.name) return t.value;
  std::string msg = "must be ";
  for (std::size_t i = 0; i < N; ++i) {
    if (i > 0) msg += i + 1 == N ? " or " : ", ";
    msg.append(1, '"').append(table[i].name).append("\" (").append(table[i].meaning).append(")");
  }
  f.fail(v, path, msg);
}

inline constexpr std::array<NamedValue<SpeedlogMode>, 2> kSpeedlogModes{{
    {SpeedlogMode::GroundLock, "ground_lock", "speed over ground"},
    {SpeedlogMode::BottomLock, "bottom_lock", "speed through water"},
}};
inline constexpr std::array<NamedValue<track::OwnShipFeed>, 2> kOwnShipFeeds{{
    {track::OwnShipFeed::Marginal, "marginal", "consistent"},
    {track::OwnShipFeed::Measurement, "measurement", "seed 000"},
}};
inline constexpr std::array<NamedValue<track::Association>, 2> kAssociations{{
    {track::Association::Nearest, "nearest", "global nearest neighbour"},
    {track::Association::Known, "known", "seed 000: plots carry their target"},
}};

/// A time of the run, in seconds in [0, duration_s] (compared in seconds: 1e13 s does not fit the
/// microsecond clock).
TimeUs timeField(Fields& f, std::string_view key, TimeUs durationUs);
int lineOfPath(const io::JsonValue& root, std::string_view path);
est::GaussMarkov gaussMarkov(Fields& f, std::string_view varianceKey, std::string_view sigmaKey);
void readPowerSchedule(Fields& sensor, StepSchedule<bool>& power, TimeUs durationUs,
                       const std::function<void(Fields&, TimeUs)>& onMode = {});
SpeedlogMode speedlogMode(const Fields& f, const io::JsonValue& v, const std::string& path);

// The sections of a scenario file (scenario_read.cpp, scenario_read_tracking.cpp).
void readSensors(Fields& top, sim::Scenario& s);
void readOwnShip(Fields& top, sim::Scenario& s);
void readTargets(Fields& top, sim::Scenario& s);
void readRadarMatching(Fields& top, sim::Scenario& s);
void readTracker(Fields& top, sim::Scenario& s);
void readFilter(Fields& top, sim::Scenario& s);
// The AIS parts (scenario_ais.cpp).
void readTargetAis(Fields& target, sim::TargetSpec& t);
void readAisAssociation(Fields& tracker, sim::TrackerSpec& tr);
void writeTargetAis(io::JsonWriter& w, const sensors::AisTransmitterSpec& a);
void writeAisAssociation(io::JsonWriter& w, const track::AisAssociationConfig& a);
/// The "voyage" block (scenario_voyage.cpp).
void readVoyage(Fields& top, sim::Scenario& s);
void writeVoyage(io::JsonWriter& w, const sim::VoyageSpec& v);

}  // namespace reckoner::files::scenario_detail
