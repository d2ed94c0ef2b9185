#include "ui/common/route_text.h"

#include <algorithm>
#include <cmath>

#include "io/text_format.h"

namespace reckoner::ui {
namespace {

ParsedAngle refuse(const QString& text, const QString& why) {
  return {std::nullopt, QStringLiteral("'%1': %2").arg(text, why)};
}

/// deg [min [sec]] with a hemisphere letter (pos or neg) at either end, or a sign.
ParsedAngle parseAngle(const QString& text, QChar pos, QChar neg, double limit) {
  QString s = text.trimmed().toUpper();
  if (s.isEmpty()) return refuse(text, QStringLiteral("empty"));
  int hemisphere = 0;  // +1 pos, -1 neg
  for (const bool atEnd : {true, false}) {
    if (s.isEmpty()) break;
    const QChar c = atEnd ? s.back() : s.front();
    if (c != pos && c != neg) continue;
    if (hemisphere != 0) return refuse(text, QStringLiteral("two hemisphere letters"));
    hemisphere = c == pos ? 1 : -1;
    s = atEnd ? s.chopped(1) : s.mid(1);
  }
  for (const QChar sep : {QChar(0x00b0), QChar('\''), QChar(0x2032), QChar('"'), QChar(0x2033), QChar(':')})
    s.replace(sep, QLatin1Char(' '));
  const QStringList parts = s.simplified().split(QLatin1Char(' '), Qt::SkipEmptyParts);
  if (parts.isEmpty() || parts.size() > 3)
    return refuse(text, QStringLiteral("not an angle (like 47°17.402'%1 or 47.29)").arg(pos));
  double value = 0.0;
  double unit = 1.0;
  bool negative = false;
  for (int i = 0; i < parts.size(); ++i) {
    const std::string part = parts[i].toStdString();
    const std::optional<double> v = io::parseFiniteNumber(part);
    if (!v) return refuse(text, QStringLiteral("'%1' is not a number").arg(parts[i]));
    if (i == 0) {
      negative = part.front() == '-';
    } else if (*v < 0.0 || *v >= 60.0 || part.front() == '-' || part.front() == '+') {
      return refuse(text, QStringLiteral("minutes and seconds must be in [0, 60)"));
    }
    if (i + 1 < parts.size() && std::floor(*v) != *v)
      return refuse(text, QStringLiteral("only the last part may have decimals"));
    value += std::abs(*v) / unit;
    unit *= 60.0;
  }
  if (negative && hemisphere != 0) return refuse(text, QStringLiteral("a sign and a hemisphere letter"));
  if (negative || hemisphere < 0) value = -value;
  if (!(std::abs(value) <= limit))
    return refuse(text, QStringLiteral("must be in [-%1, %1] degrees").arg(limit, 0, 'f', 0));
  return {value, {}};
}

}  // namespace

ParsedAngle parseLatitude(const QString& text) {
  return parseAngle(text, QLatin1Char('N'), QLatin1Char('S'), 90.0);
}

ParsedAngle parseLongitude(const QString& text) {
  return parseAngle(text, QLatin1Char('E'), QLatin1Char('W'), 180.0);
}

QStringList routeEditProblems(const geo::Route& route) {
  std::vector<std::string> all = route.problems();
  // The first line says "fewer than two waypoints" when there are: a route being built has them.
  if (route.waypoints.size() < 2 && !all.empty()) all.erase(all.begin());
  QStringList out;
  for (const std::string& p : all) out << QString::fromStdString(p);
  return out;
}

int nextWaypointId(const geo::Route& route) {
  int id = 0;
  for (const geo::Waypoint& w : route.waypoints) id = std::max(id, w.id);
  return id + 1;
}

std::string nextWaypointName(const geo::Route& route) {
  for (std::size_t n = route.waypoints.size() + 1;; ++n) {
    std::string name = "WP" + std::to_string(n);
    if (std::none_of(route.waypoints.begin(), route.waypoints.end(),
                     [&](const geo::Waypoint& w) { return w.name == name; }))
      return name;
  }
}

}  // namespace reckoner::ui
