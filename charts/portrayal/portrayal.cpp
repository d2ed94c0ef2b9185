#include "charts/portrayal/portrayal.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "io/json.h"
#include "resources/embedded.h"

namespace reckoner::charts {
namespace {

Rgb parseRgb(const std::string& s, const std::string& where) {
  unsigned r = 0, g = 0, b = 0;
  if (s.size() != 7 || s[0] != '#' || std::sscanf(s.c_str() + 1, "%02x%02x%02x", &r, &g, &b) != 3)
    throw std::invalid_argument(where + ": colour must be #rrggbb, got '" + s + "'");
  return {static_cast<std::uint8_t>(r), static_cast<std::uint8_t>(g), static_cast<std::uint8_t>(b)};
}

const io::JsonValue* member(const io::JsonValue& o, std::string_view key) {
  for (const auto& [k, v] : o.object)
    if (k == key) return &v;
  return nullptr;
}

std::string stringMember(const io::JsonValue& o, std::string_view key, const std::string& where) {
  const io::JsonValue* v = member(o, key);
  if (!v || !v->isString())
    throw std::invalid_argument(where + "." + std::string(key) + ": must be a string");
  return v->string;
}

std::optional<std::string> optionalString(const io::JsonValue& o, std::string_view key,
                                          const std::string& where) {
  const io::JsonValue* v = member(o, key);
  if (!v) return std::nullopt;
  if (!v->isString()) throw std::invalid_argument(where + "." + std::string(key) + ": must be a string");
  return v->string;
}
}  // namespace

std::optional<Palette> paletteFromName(std::string_view s) {
  if (s == "day") return Palette::Day;
  if (s == "dusk") return Palette::Dusk;
  if (s == "night") return Palette::Night;
  return std::nullopt;
}

std::optional<DisplayCategory> categoryFromName(std::string_view s) {
  if (s == "base") return DisplayCategory::Base;
  if (s == "standard") return DisplayCategory::Standard;
  if (s == "all" || s == "other") return DisplayCategory::Other;
  return std::nullopt;
}

ColourTable ColourTable::parse(std::string_view json) {
  const io::JsonValue root = io::parseJson(json);
  ColourTable t;
  const char* names[] = {"day", "dusk", "night"};
  for (int p = 0; p < 3; ++p) {
    const io::JsonValue* table = member(root, names[p]);
    if (!table || !table->isObject())
      throw std::invalid_argument(std::string("colours.json: palette '") + names[p] + "' missing");
    for (const auto& [token, v] : table->object) {
      if (!v.isString())
        throw std::invalid_argument(std::string("colours.json: ") + names[p] + "." + token +
                                    ": must be a string");
      t.tables_[static_cast<std::size_t>(p)][token] =
          parseRgb(v.string, std::string("colours.json: ") + names[p] + "." + token);
    }
  }
  // Every palette defines the same tokens.
  for (const auto& [token, rgb] : t.tables_[0])
    for (int p = 1; p < 3; ++p)
      if (!t.tables_[static_cast<std::size_t>(p)].count(token))
        throw std::invalid_argument(std::string("colours.json: ") + names[p] + " lacks token " + token);
  return t;
}

Rgb ColourTable::colour(Palette p, std::string_view token) const {
  const auto& table = tables_[static_cast<std::size_t>(p)];
  const auto it = table.find(token);
  if (it == table.end()) throw std::out_of_range("unknown colour token " + std::string(token));
  return it->second;
}

PortrayalTable PortrayalTable::parse(std::string_view json) {
  const io::JsonValue root = io::parseJson(json);
  const io::JsonValue* rules = member(root, "rules");
  if (!rules || !rules->isArray()) throw std::invalid_argument("rules.json: 'rules' must be an array");
  PortrayalTable t;
  for (std::size_t i = 0; i < rules->array.size(); ++i) {
    const io::JsonValue& r = rules->array[i];
    const std::string where = "rules.json: rules[" + std::to_string(i) + "]";
    if (!r.isObject()) throw std::invalid_argument(where + ": must be an object");
    PortrayalRule rule;
    rule.objectClass = stringMember(r, "class", where);
    const std::string prim = stringMember(r, "primitive", where);
    if (prim == "point")
      rule.primitive = Primitive::Point;
    else if (prim == "line")
      rule.primitive = Primitive::Line;
    else if (prim == "area")
      rule.primitive = Primitive::Area;
    else
      throw std::invalid_argument(where + ".primitive: must be point, line or area");
    rule.fill = optionalString(r, "fill", where);
    rule.symbol = optionalString(r, "symbol", where);
    rule.centreSymbol = optionalString(r, "symbol_at_centre", where);
    rule.colour = optionalString(r, "colour", where);
    rule.textAttribute = optionalString(r, "text", where);
    rule.procedure = optionalString(r, "procedure", where);
    static const std::vector<std::string> kProcedures = {
        "depth_area", "depth_contour", "soundings", "danger", "buoy", "beacon", "light", "topmark"};
    if (rule.procedure &&
        std::find(kProcedures.begin(), kProcedures.end(), *rule.procedure) == kProcedures.end())
      throw std::invalid_argument(where + ".procedure: unknown procedure '" + *rule.procedure + "'");
    static const std::vector<std::string> kCentreSymbols = {"anchor", "restricted", "caution", "tss_arrow"};
    if (rule.centreSymbol &&
        std::find(kCentreSymbols.begin(), kCentreSymbols.end(), *rule.centreSymbol) == kCentreSymbols.end())
      throw std::invalid_argument(where + ".symbol_at_centre: unknown symbol '" + *rule.centreSymbol + "'");
    if (const io::JsonValue* l = member(r, "line")) {
      LineStyle ls;
      ls.colour = stringMember(*l, "colour", where + ".line");
      if (const io::JsonValue* w = member(*l, "width")) {
        if (!w->isNumber() || !(w->number > 0.0))
          throw std::invalid_argument(where + ".line.width: must be positive");
        ls.widthPx = w->number;
      }
      const std::string dash = optionalString(*l, "style", where + ".line").value_or("solid");
      if (dash == "solid")
        ls.dash = LineDash::Solid;
      else if (dash == "dash")
        ls.dash = LineDash::Dash;
      else if (dash == "dot")
        ls.dash = LineDash::Dot;
      else if (dash == "dashdot")
        ls.dash = LineDash::DashDot;
      else
        throw std::invalid_argument(where + ".line.style: must be solid, dash, dot or dashdot");
      rule.line = ls;
    }
    if (const io::JsonValue* p = member(r, "priority")) {
      if (!p->isNumber() || p->number < 0 || p->number > 9)
        throw std::invalid_argument(where + ".priority: must be 0-9");
      rule.priority = static_cast<int>(p->number);
    }
    const auto cat = categoryFromName(stringMember(r, "category", where));
    if (!cat) throw std::invalid_argument(where + ".category: must be base, standard or other");
    rule.category = *cat;
    t.byClass_[rule.objectClass].push_back(t.rules_.size());
    t.rules_.push_back(std::move(rule));
  }
  return t;
}

const PortrayalRule* PortrayalTable::find(std::string_view objectClass, Primitive p) const {
  const auto it = byClass_.find(objectClass);
  if (it == byClass_.end()) return nullptr;
  for (std::size_t i : it->second)
    if (rules_[i].primitive == p) return &rules_[i];
  return nullptr;
}

const PortrayalTable& defaultPortrayal() {
  static const PortrayalTable t = PortrayalTable::parse(resources::findPortrayal("rules")->text);
  return t;
}

const ColourTable& defaultColours() {
  static const ColourTable t = ColourTable::parse(resources::findPortrayal("colours")->text);
  return t;
}

std::string depthShade(std::optional<double> drval1M, const MarinerSettings& s) {
  const double d = drval1M.value_or(0.0);
  if (d < 0.0) return "DEPIT";
  if (!s.fourShades) return d >= s.safetyContourM ? "DEPDW" : "DEPVS";
  if (d >= s.deepContourM) return "DEPDW";
  if (d >= s.safetyContourM) return "DEPMD";
  if (d >= s.shallowContourM) return "DEPMS";
  return "DEPVS";
}

std::optional<double> chooseSafetyContour(std::vector<double> values, double settingM) {
  std::sort(values.begin(), values.end());
  for (double v : values)
    if (v >= settingM) return v;
  return std::nullopt;
}

bool isIsolatedDanger(std::optional<double> valsouM, double safetyContourM) {
  return valsouM && *valsouM < safetyContourM;
}

std::pair<std::string, std::string> soundingText(double depthM) {
  const double d = std::abs(depthM);
  if (d >= 31.0 || std::abs(d - std::round(d)) < 0.05) {
    return {std::to_string(static_cast<long>(std::floor(d + (d >= 31.0 ? 0.0 : 0.05)))), ""};
  }
  const long whole = static_cast<long>(std::floor(d));
  const long tenth = static_cast<long>(std::floor((d - static_cast<double>(whole)) * 10.0 + 1e-9));
  return {std::to_string(whole), std::to_string(tenth)};
}

std::string lightDescription(const ChartFeature& light) {
  // LITCHR abbreviations as on paper charts (INT 1, section P), by the S-57 enumeration.
  static const std::map<int, std::string> kCharacter = {
      {1, "F"},      {2, "Fl"},      {3, "LFl"},     {4, "Q"},       {5, "VQ"},
      {6, "UQ"},     {7, "Iso"},     {8, "Oc"},      {9, "IQ"},      {10, "IVQ"},
      {11, "IUQ"},   {12, "Mo"},     {13, "FFl"},    {14, "Fl+LFl"}, {15, "Oc+Fl"},
      {16, "FLFl"},  {17, "Al.Oc"},  {18, "Al.LFl"}, {19, "Al.Fl"},  {20, "Al.Gr"},
      {25, "Q+LFl"}, {26, "VQ+LFl"}, {27, "UQ+LFl"}, {28, "Al"},     {29, "Al.FFl"}};
  static const std::map<int, std::string> kColour = {{1, "W"}, {3, "R"},  {4, "G"},   {5, "Bu"},
                                                     {6, "Y"}, {9, "Am"}, {10, "Vi"}, {11, "Or"}};
  const auto litchr = light.number("LITCHR");
  if (!litchr) return {};
  const auto ch = kCharacter.find(static_cast<int>(*litchr));
  if (ch == kCharacter.end()) return {};
  std::string out = ch->second;
  if (const auto grp = light.text("SIGGRP"); grp && *grp != "()" && *grp != "(1)") out += *grp;
  const auto colours = light.list("COLOUR");
  std::string cols;
  for (auto code : colours)
    if (const auto it = kColour.find(static_cast<int>(code)); it != kColour.end()) cols += it->second;
  if (!cols.empty() && cols != "W") {  // a lone white is left out, as charts do
    if (out.back() != ')') out.push_back(' ');
    out.append(cols);
  }
  auto append = [&out](std::optional<double> v, const char* unit) {
    if (!v || !(*v > 0)) return;
    char buf[64];
    std::snprintf(buf, sizeof buf, " %g%s", *v, unit);
    out.append(buf);
  };
  append(light.number("SIGPER"), "s");
  append(light.number("HEIGHT"), "m");
  append(light.number("VALNMR"), "M");
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

}  // namespace reckoner::charts
