#pragma once
// Our own S-52-style portrayal: a data-driven look-up table (object class + primitive -> colours, line
// style, symbol, text, display priority and category; resources/portrayal/rules.json), colour tables
// per palette (resources/portrayal/colours.json), the mariner's settings, and the pure functions of the
// conditional cases (depth shades, safety contour, danger). Plain C++; drawing is in charts/render.
#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "charts/model/chart_model.h"

namespace reckoner::charts {

enum class Palette : std::uint8_t { Day, Dusk, Night };
enum class DisplayCategory : std::uint8_t { Base, Standard, Other };  ///< Other = "all"
std::optional<Palette> paletteFromName(std::string_view s);
std::optional<DisplayCategory> categoryFromName(std::string_view s);

struct MarinerSettings {
  Palette palette = Palette::Day;
  DisplayCategory category = DisplayCategory::Standard;
  double shallowContourM = 2.0;
  double safetyContourM = 10.0;
  double deepContourM = 30.0;
  double safetyDepthM = 10.0;  ///< soundings at or above it in the bold colour
  bool fourShades = true;
  bool showText = true;
  bool contourLabels = true;  ///< depth contour values along the contours (with showText)
  bool honourScamin = true;
};

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
  friend bool operator==(const Rgb&, const Rgb&) = default;
};

class ColourTable {
 public:
  /// Parses colours.json; throws std::invalid_argument naming the token or palette.
  static ColourTable parse(std::string_view json);
  /// The colour of a token; magenta-ish fallback never: throws std::out_of_range for an unknown token.
  [[nodiscard]] Rgb colour(Palette p, std::string_view token) const;

 private:
  std::array<std::map<std::string, Rgb, std::less<>>, 3> tables_;
};

enum class LineDash : std::uint8_t { Solid, Dash, Dot, DashDot };

struct LineStyle {
  std::string colour;
  double widthPx = 1.0;
  LineDash dash = LineDash::Solid;
};

struct PortrayalRule {
  std::string objectClass;
  Primitive primitive = Primitive::None;
  std::optional<std::string> fill;          ///< area colour token
  std::optional<LineStyle> line;            ///< line or area boundary
  std::optional<std::string> symbol;        ///< point symbol name
  std::optional<std::string> centreSymbol;  ///< area: symbol at its centre
  std::optional<std::string> colour;        ///< symbol colour token
  std::optional<std::string> textAttribute;
  std::optional<std::string> procedure;  ///< conditional procedure name
  int priority = 0;
  DisplayCategory category = DisplayCategory::Standard;
};

class PortrayalTable {
 public:
  /// Parses rules.json; throws std::invalid_argument naming the rule index and field.
  static PortrayalTable parse(std::string_view json);
  /// The rule for a class and primitive, or nullptr (not portrayed).
  [[nodiscard]] const PortrayalRule* find(std::string_view objectClass, Primitive p) const;
  [[nodiscard]] std::size_t size() const { return rules_.size(); }

 private:
  std::vector<PortrayalRule> rules_;
  std::map<std::string, std::vector<std::size_t>, std::less<>> byClass_;
};

/// The built-in table and colours (embedded resources/portrayal/).
const PortrayalTable& defaultPortrayal();
const ColourTable& defaultColours();

// ---- conditional cases (pure)

/// Depth-area shade token for DRVAL1 (shallowest depth of the area) and the settings: DEPIT drying,
/// then DEPVS / DEPMS / DEPMD / DEPDW by the shallow, safety and deep contours (two shades: DEPVS
/// below the safety contour, DEPDW at or beyond it).
std::string depthShade(std::optional<double> drval1M, const MarinerSettings& s);

/// The safety contour actually drawn: the shallowest contour value at or deeper than the setting
/// (the next deeper one when the set value is absent); nullopt when no contour is that deep.
std::optional<double> chooseSafetyContour(std::vector<double> contourValuesM, double settingM);

/// A wreck, obstruction or rock is an isolated danger when its least depth (VALSOU) is known and
/// shallower than the safety contour in water deeper than it.
bool isIsolatedDanger(std::optional<double> valsouM, double safetyContourM);

/// Depth for display the chart way: whole metres, with tenths below 31 m when not whole
/// ("12" and "4" subscript "5" -> {"4", "5"}). The second string is empty for whole metres.
std::pair<std::string, std::string> soundingText(double depthM);

/// A light's description the chart way from LITCHR, SIGGRP, COLOUR, SIGPER, HEIGHT and VALNMR, e.g.
/// "Fl(2)R 6s 12m 5M", "Iso WRG 4s", "Q(9)15s"; empty when the light has no character.
std::string lightDescription(const ChartFeature& light);

}  // namespace reckoner::charts
