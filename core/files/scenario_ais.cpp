// The scenario format's AIS parts (docs/scenarios.md): a target's "ais" transponder and the tracker's
// "ais_association".
#include "files/scenario_fields.h"
#include "files/scenario_json.h"

namespace reckoner::files::scenario_detail {

using io::JsonValue;
using io::JsonWriter;

namespace {
inline constexpr std::array<NamedValue<sensors::AisStationClass>, 3> kAisClasses{{
    {sensors::AisStationClass::A, "A", "SOTDMA, 2-10 s"},
    {sensors::AisStationClass::B, "B", "CS, 30 s"},
    {sensors::AisStationClass::Sart, "SART", "AIS-SART, MOB or EPIRB-AIS: 8 reports a minute"},
}};

void readAisErrors(Fields& f, track::AisErrorModel& e) {
  const JsonValue* v = f.get("errors");
  if (!v) return;
  Fields g(f.file(), *v, f.pathOf("errors"));
  using C = Fields::Check;
  e.positionSdAccurateM = g.numberOr("position_sd_accurate_m", e.positionSdAccurateM, C::Positive);
  e.positionSdM = g.numberOr("position_sd_m", e.positionSdM, C::Positive);
  e.positionCorrelationS = g.numberOr("position_correlation_s", e.positionCorrelationS, C::Positive);
  e.velocitySdClassAMps = g.numberOr("velocity_sd_class_a_mps", e.velocitySdClassAMps, C::Positive);
  e.velocitySdClassBMps = g.numberOr("velocity_sd_class_b_mps", e.velocitySdClassBMps, C::Positive);
  e.velocityCorrelationS = g.numberOr("velocity_correlation_s", e.velocityCorrelationS, C::Positive);
  e.headingSdDeg = g.numberOr("heading_sd_deg", e.headingSdDeg, C::Positive);
  e.cogOffsetSdDeg = g.numberOr("cog_offset_sd_deg", e.cogOffsetSdDeg, C::Positive);
  e.unknownOffsetSdM = g.numberOr("unknown_offset_sd_m", e.unknownOffsetSdM, C::Positive);
  e.unknownLatencyS = g.numberOr("unknown_latency_s", e.unknownLatencyS, C::NonNegative);
  e.unknownLatencySdS = g.numberOr("unknown_latency_sd_s", e.unknownLatencySdS, C::Positive);
  e.accelerationSdMps2 = g.numberOr("acceleration_sd_mps2", e.accelerationSdMps2, C::Positive);
  g.finish();
}
}  // namespace

void readTargetAis(Fields& f, sim::TargetSpec& t) {
  const JsonValue* v = f.get("ais");
  if (!v) return;
  Fields g(f.file(), *v, f.pathOf("ais"));
  const JsonValue& cls = g.require("class");
  auto a = sensors::AisTransmitterSpec::defaults(valueOf(kAisClasses, g, cls, g.pathOf("class")));
  const JsonValue& mmsi = g.require("mmsi");
  if (!mmsi.isNumber() || mmsi.number < 1 || mmsi.number > 999999999 ||
      std::floor(mmsi.number) != mmsi.number)
    g.fail(mmsi, g.pathOf("mmsi"), "must be an integer in [1, 999999999]");
  a.mmsi = static_cast<std::uint32_t>(mmsi.number);
  a.shipName = g.stringOr("ship_name", t.name);
  a.shipType = g.integerOr("ship_type", 1, 99, a.shipType);
  if (const JsonValue* d = g.get("antenna_m")) {
    if (!d->isArray() || d->array.size() != 4)
      g.fail(*d, g.pathOf("antenna_m"), "must be [to_bow, to_stern, to_port, to_starboard] in metres");
    std::array<int, 4> m{};
    const std::array<int, 4> hi{511, 511, 63, 63};
    for (std::size_t i = 0; i < 4; ++i) {
      const JsonValue& x = d->array[i];
      if (!x.isNumber() || x.number < 0 || x.number > hi[i] || std::floor(x.number) != x.number)
        g.fail(x, g.pathOf("antenna_m") + "[" + std::to_string(i) + "]",
               "must be an integer in [0, " + std::to_string(hi[i]) + "]");
      m[i] = static_cast<int>(x.number);
    }
    a.toBowM = m[0];
    a.toSternM = m[1];
    a.toPortM = m[2];
    a.toStarboardM = m[3];
  }
  using C = Fields::Check;
  a.positionSdM = g.numberOr("position_sd_m", a.positionSdM, C::NonNegative);
  a.positionCorrelationS = g.numberOr("position_correlation_s", a.positionCorrelationS, C::Positive);
  a.velocitySdMps = g.numberOr("velocity_sd_mps", a.velocitySdMps, C::NonNegative);
  a.velocityCorrelationS = g.numberOr("velocity_correlation_s", a.velocityCorrelationS, C::Positive);
  a.headingSdDeg = g.numberOr("heading_sd_deg", a.headingSdDeg, C::NonNegative);
  const auto latency = g.pair("latency_s", {a.latencyMinS, a.latencyMaxS});
  a.latencyMinS = latency[0];
  a.latencyMaxS = latency[1];
  a.lossProbability = g.numberOr("loss_probability", a.lossProbability, C::NonNegative);
  a.staticIntervalS = g.numberOr("static_interval_s", a.staticIntervalS, C::Positive);
  if (const JsonValue* e = g.get("test")) a.test = g.boolean(*e, g.pathOf("test"));
  if (const std::string e = a.check(); !e.empty())
    g.fail(*v, g.pathOf(e.substr(0, e.find(':'))), e.substr(e.find(':') + 2));
  g.finish();
  t.ais = a;
}

void readAisAssociation(Fields& f, sim::TrackerSpec& tr) {
  const JsonValue* v = f.get("ais_association");
  if (!v) return;
  Fields g(f.file(), *v, f.pathOf("ais_association"));
  auto& a = tr.aisAssociation;
  using C = Fields::Check;
  if (const JsonValue* e = g.get("enabled")) a.enabled = g.boolean(*e, g.pathOf("enabled"));
  if (const JsonValue* e = g.get("fuse")) a.fuse = g.boolean(*e, g.pathOf("fuse"));
  a.positionLimitM = g.numberOr("position_limit_m", a.positionLimitM, C::Positive);
  a.courseLimitDeg = g.numberOr("course_limit_deg", a.courseLimitDeg, C::Positive);
  a.speedLimitKn = g.numberOr("speed_limit_kn", a.speedLimitKn, C::Positive);
  a.courseMinSpeedKn = g.numberOr("course_min_speed_kn", a.courseMinSpeedKn, C::NonNegative);
  a.associateAfter = g.integerOr("associate_after", 1, 100, a.associateAfter);
  a.dissociateAfter = g.integerOr("dissociate_after", 1, 100, a.dissociateAfter);
  a.rejectAfter = g.integerOr("reject_after", 1, 100, a.rejectAfter);
  a.releaseFactor = g.numberOr("release_factor", a.releaseFactor, C::Positive);
  a.gateProbability = g.numberOr("gate_probability", a.gateProbability, C::NonNegative);
  a.manoeuvreNisProbability = g.numberOr("manoeuvre_nis_probability", a.manoeuvreNisProbability, C::Positive);
  readAisErrors(g, a.errors);
  if (const std::string e = a.check(); !e.empty())
    g.fail(*v, g.pathOf(e.substr(0, e.find(':'))), e.substr(e.find(':') + 2));
  g.finish();
}

void writeTargetAis(JsonWriter& w, const sensors::AisTransmitterSpec& a) {
  w.key("ais").beginObject();
  w.key("class").value(nameOf(kAisClasses, a.cls));
  w.key("mmsi").value(static_cast<std::uint64_t>(a.mmsi));
  w.key("ship_name").value(a.shipName);
  w.key("ship_type").value(a.shipType);
  w.key("antenna_m")
      .numberArray({static_cast<double>(a.toBowM), static_cast<double>(a.toSternM),
                    static_cast<double>(a.toPortM), static_cast<double>(a.toStarboardM)});
  w.key("position_sd_m").value(a.positionSdM);
  w.key("position_correlation_s").value(a.positionCorrelationS);
  w.key("velocity_sd_mps").value(a.velocitySdMps);
  w.key("velocity_correlation_s").value(a.velocityCorrelationS);
  w.key("heading_sd_deg").value(a.headingSdDeg);
  w.key("latency_s").numberArray({a.latencyMinS, a.latencyMaxS});
  w.key("loss_probability").value(a.lossProbability);
  w.key("static_interval_s").value(a.staticIntervalS);
  if (a.test) w.key("test").value(true);
  w.endObject();
}

void writeAisAssociation(JsonWriter& w, const track::AisAssociationConfig& a) {
  if (a == track::AisAssociationConfig{}) return;
  w.key("ais_association").beginObject();
  w.key("enabled").value(a.enabled);
  w.key("fuse").value(a.fuse);
  w.key("position_limit_m").value(a.positionLimitM);
  w.key("course_limit_deg").value(a.courseLimitDeg);
  w.key("speed_limit_kn").value(a.speedLimitKn);
  w.key("course_min_speed_kn").value(a.courseMinSpeedKn);
  w.key("associate_after").value(a.associateAfter);
  w.key("dissociate_after").value(a.dissociateAfter);
  w.key("reject_after").value(a.rejectAfter);
  w.key("release_factor").value(a.releaseFactor);
  w.key("gate_probability").value(a.gateProbability);
  w.key("manoeuvre_nis_probability").value(a.manoeuvreNisProbability);
  const auto& e = a.errors;
  w.key("errors").beginObject();
  w.key("position_sd_accurate_m").value(e.positionSdAccurateM);
  w.key("position_sd_m").value(e.positionSdM);
  w.key("position_correlation_s").value(e.positionCorrelationS);
  w.key("velocity_sd_class_a_mps").value(e.velocitySdClassAMps);
  w.key("velocity_sd_class_b_mps").value(e.velocitySdClassBMps);
  w.key("velocity_correlation_s").value(e.velocityCorrelationS);
  w.key("heading_sd_deg").value(e.headingSdDeg);
  w.key("cog_offset_sd_deg").value(e.cogOffsetSdDeg);
  w.key("unknown_offset_sd_m").value(e.unknownOffsetSdM);
  w.key("unknown_latency_s").value(e.unknownLatencyS);
  w.key("unknown_latency_sd_s").value(e.unknownLatencySdS);
  w.key("acceleration_sd_mps2").value(e.accelerationSdMps2);
  w.endObject();
  w.endObject();
}

}  // namespace reckoner::files::scenario_detail
