#include "ui/common/display_units.h"

#include "common/angles.h"
#include "common/units.h"

namespace reckoner::ui {
namespace {
constexpr double kMetresPerKilometre = 1000.0;
}

QString unitName(DistanceUnit u) {
  return u == DistanceUnit::Kilometres ? QStringLiteral("km") : QStringLiteral("NM");
}

QString unitName(SpeedUnit u) {
  return u == SpeedUnit::MetresPerSecond ? QStringLiteral("m/s") : QStringLiteral("kn");
}

double distanceIn(double metres, DistanceUnit u) {
  return u == DistanceUnit::Kilometres ? metres / kMetresPerKilometre : metresToNm(metres);
}

double metresFrom(double value, DistanceUnit u) {
  return u == DistanceUnit::Kilometres ? value * kMetresPerKilometre : nmToMetres(value);
}

double speedIn(double mps, SpeedUnit u) {
  return u == SpeedUnit::MetresPerSecond ? mps : mpsToKnots(mps);
}

double mpsFrom(double value, SpeedUnit u) {
  return u == SpeedUnit::MetresPerSecond ? value : knotsToMps(value);
}

QString formatDistance(double metres, const DisplayUnits& u, int decimals, bool withUnit) {
  const QString n = QString::number(distanceIn(metres, u.distance), 'f', decimals);
  return withUnit ? n + QLatin1Char(' ') + unitName(u.distance) : n;
}

QString formatSpeed(double mps, const DisplayUnits& u, int decimals, bool withUnit) {
  const QString n = QString::number(speedIn(mps, u.speed), 'f', decimals);
  return withUnit ? n + QLatin1Char(' ') + unitName(u.speed) : n;
}

QString formatBearing(double rad, int decimals) {
  // Width 4 + decimals: "045.0"; a value that rounds to 360.0 reads 000.0.
  double deg = radToDeg(wrapTwoPi(rad));
  if (QString::number(deg, 'f', decimals).toDouble() >= 360.0) deg = 0.0;
  return QStringLiteral("%1°").arg(deg, decimals > 0 ? 4 + decimals : 3, 'f', decimals, QChar('0'));
}

QString formatCourseSpeed(double courseRad, double speedMps, const DisplayUnits& u) {
  return formatBearing(courseRad) + QLatin1Char(' ') + formatSpeed(speedMps, u);
}

}  // namespace reckoner::ui
