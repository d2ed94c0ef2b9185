#pragma once
// Reading what an operator types for a route (docs/gui.md "Routes"): positions as the window writes
// them (io::formatLatitude / formatLongitude: "47°17.402'N", "122°28.200'W") or in the other usual
// ways ("47 17.402 N", "47°17'24\"N", "47.29", "-122.47"), and the check every route edit passes, from
// the chart and the route table alike.
#include <QString>
#include <QStringList>
#include <optional>

#include "geo/route.h"

namespace reckoner::ui {

/// A typed angle: the value in degrees, or why it was refused.
struct ParsedAngle {
  std::optional<double> deg;
  QString problem;  ///< empty when deg is set
};

/// Degrees, degrees and decimal minutes, or degrees, minutes and seconds, with N/S before or after
/// (or a sign, not both), separated by °, ', ", spaces or colons; [-90, 90].
[[nodiscard]] ParsedAngle parseLatitude(const QString& text);
/// The same with E/W; [-180, 180].
[[nodiscard]] ParsedAngle parseLongitude(const QString& text);

/// What makes an edited route unusable (geo::Route::problems()), except having fewer than two
/// waypoints, which a route has while it is being built.
[[nodiscard]] QStringList routeEditProblems(const geo::Route& route);

/// The next waypoint id of a route (one more than the largest) and a name not yet used ("WP4").
[[nodiscard]] int nextWaypointId(const geo::Route& route);
[[nodiscard]] std::string nextWaypointName(const geo::Route& route);

}  // namespace reckoner::ui
