#pragma once
// The units the window shows distances and speeds in (View ▸ Units: nautical miles or kilometres, knots
// or metres per second), and the one place that turns metres and metres per second into text in them.
// Every readout that shows a distance or a speed (cursor, EBL/VRM, scale bar, helm order, the target
// table, the own-ship panel, the pick report) formats it here; the conversions themselves are
// core/common/units.h's. Small distances (errors, ship dimensions) stay in metres in both.
#include <QString>

namespace reckoner::ui {

enum class DistanceUnit { NauticalMiles = 0, Kilometres = 1 };
enum class SpeedUnit { Knots = 0, MetresPerSecond = 1 };

struct DisplayUnits {
  DistanceUnit distance = DistanceUnit::NauticalMiles;
  SpeedUnit speed = SpeedUnit::Knots;
  friend bool operator==(const DisplayUnits&, const DisplayUnits&) = default;
};

/// "NM" or "km"; "kn" or "m/s".
[[nodiscard]] QString unitName(DistanceUnit u);
[[nodiscard]] QString unitName(SpeedUnit u);
/// A distance in metres in the unit (NM or km), and back.
[[nodiscard]] double distanceIn(double metres, DistanceUnit u);
[[nodiscard]] double metresFrom(double value, DistanceUnit u);
/// A speed in m/s in the unit (kn or m/s), and back.
[[nodiscard]] double speedIn(double mps, SpeedUnit u);
[[nodiscard]] double mpsFrom(double value, SpeedUnit u);

/// "1.23 NM" / "2.28 km" (decimals after the point; the number alone with withUnit false).
[[nodiscard]] QString formatDistance(double metres, const DisplayUnits& u, int decimals = 2,
                                     bool withUnit = true);
/// "12.0 kn" / "6.2 m/s".
[[nodiscard]] QString formatSpeed(double mps, const DisplayUnits& u, int decimals = 1, bool withUnit = true);
/// A true bearing or course, "045.0°" (three digits before the point, radians in).
[[nodiscard]] QString formatBearing(double rad, int decimals = 1);
/// A helm order: "045.0° 12.0 kn".
[[nodiscard]] QString formatCourseSpeed(double courseRad, double speedMps, const DisplayUnits& u);

}  // namespace reckoner::ui
