// EcdisView's display modes: own ship's heading and CCRP as the display takes them, the orientation
// (north-up, course-up stabilised, head-up) and the motion (true motion with reset, relative motion,
// centred or off-centred). The state and input are in ecdis_view.cpp.
#include <algorithm>
#include <cmath>

#include "common/angles.h"
#include "ui/map/ecdis_view.h"

namespace reckoner::ui {
namespace {
constexpr double kCourseUpStepRad = 5.0 * kPi / 180.0;  // course-up turns when the course moved this much
constexpr double kHeadUpStepRad = 0.05 * kPi / 180.0;   // head-up: every visible heading change
constexpr double kMinHeadingSpeedMps = 0.3;             // below this the heading is held
/// Off-centred: own ship this fraction of the range (centre to nearest edge) astern of the centre.
constexpr double kOffCentreFraction = 0.5;
}  // namespace

double EcdisView::headingGridRad() const {
  if (!haveOwnShip()) return lastHeadingRad_;
  const auto& x = history_->latest().frame.estimate.x;
  const double vx = x[est::drkf::kVelX], vy = x[est::drkf::kVelY];
  return std::hypot(vx, vy) > kMinHeadingSpeedMps ? bearingOf(vx, vy) : lastHeadingRad_;
}

double EcdisView::headingTrueRad() const {
  if (!haveOwnShip()) return lastHeadingRad_;
  const auto& x = history_->latest().frame.estimate.x;
  return wrapTwoPi(headingGridRad() +
                   frame_->gridInfo({x[est::drkf::kPosX], x[est::drkf::kPosY]}).convergenceRad);
}

geo::GridPoint EcdisView::ccrpOffsetGrid() const {
  if (!haveOwnShip()) return {};
  // The DRKF estimates one point, the ship's centre; the CCRP lies `along` ahead of it and `across` to
  // starboard, turned by the heading (grid), and grid metres are true metres times the point scale.
  const auto& x = history_->latest().frame.estimate.x;
  const double k = frame_->gridInfo({x[est::drkf::kPosX], x[est::drkf::kPosY]}).scale;
  const double along = 0.5 * overlay_.ownLengthM - overlay_.ccrpFromBowM, across = overlay_.ccrpToStarboardM;
  const double h = headingGridRad(), s = std::sin(h), c = std::cos(h);
  return {k * (along * s + across * c), k * (along * c - across * s)};
}

geo::GridPoint EcdisView::ccrpGrid() const {
  if (!haveOwnShip()) return {};
  const auto& x = history_->latest().frame.estimate.x;
  const geo::GridPoint off = ccrpOffsetGrid();
  return {x[est::drkf::kPosX] + off.xM, x[est::drkf::kPosY] + off.yM};
}

QPointF EcdisView::ccrpWidget() const {
  const geo::GridPoint c = ccrpGrid();
  return gridToWidget(c.xM, c.yM);
}

QPointF EcdisView::ownShipPlace() const {
  const QPointF centre(width() / 2.0, height() / 2.0);
  if (!overlay_.offCentred || !haveOwnShip()) return centre;
  const double d = kOffCentreFraction * 0.5 * std::min(width(), height());
  // Astern: straight down in course-up and head-up; in north-up opposite the course over ground, as
  // course-up stabilises it (appliedRotation_ follows the course in steps of 5 degrees).
  if (overlay_.orientation != Orientation::NorthUp) return centre + QPointF(0.0, d);
  const double b = appliedRotation_ - viewport().rotationRad();
  return centre - QPointF(d * std::sin(b), -d * std::cos(b));
}

double EcdisView::wantedRotation() {
  const double now = viewport().rotationRad();
  const auto& x = history_->latest().frame.estimate.x;
  const double gamma = frame_->gridInfo({x[est::drkf::kPosX], x[est::drkf::kPosY]}).convergenceRad;
  const double cog = wrapTwoPi(
      bearingOf(x[est::drkf::kVelX] + x[est::drkf::kCurX], x[est::drkf::kVelY] + x[est::drkf::kCurY]) +
      gamma);
  // The stabilised course: course-up's up direction, and north-up's off-centring direction.
  if (rotationStale_ || std::abs(angleDiff(cog, appliedRotation_)) > kCourseUpStepRad) {
    appliedRotation_ = cog;
    rotationStale_ = false;
  }
  switch (overlay_.orientation) {
    case Orientation::NorthUp:
      return 0.0;
    case Orientation::CourseUp:
      return appliedRotation_;
    case Orientation::HeadUp: {
      const double h = headingTrueRad();
      return std::abs(angleDiff(h, now)) > kHeadUpStepRad ? h : now;
    }
  }
  return now;
}

void EcdisView::placeAt(const geo::GridPoint& g, QPointF at, double rotationRad) {
  const geo::GeoPoint gp = frame_->toGeodetic(g);
  const charts::LatLon target{gp.latDeg, gp.lonDeg};
  const charts::Viewport v = viewport();
  // The scale is referred to the centre's latitude, so the centre that puts g at `at` is found by a
  // few fixed-point steps (each exact but for that latitude's change).
  charts::LatLon centre = target;
  for (int i = 0; i < 3; ++i) {
    const charts::Viewport t(centre, v.scaleDenominator(), v.width(), v.height(), 0.28, rotationRad);
    const charts::ScreenPoint s = t.toScreen(target);
    centre = t.toLatLon({0.5 * v.width() + (s.x - at.x()), 0.5 * v.height() + (s.y - at.y())});
  }
  if (centre.latDeg == v.centre().latDeg && centre.lonDeg == v.centre().lonDeg &&
      rotationRad == v.rotationRad())
    return;
  setView(centre, v.scaleDenominator(), rotationRad);
}

void EcdisView::applyMotion(double rotationRad, bool force) {
  const charts::Viewport v = viewport();
  const bool turned = rotationRad != v.rotationRad();
  if (!overlay_.followOwnShip) {
    if (turned) setView(v.centre(), v.scaleDenominator(), rotationRad);  // about the centre
    return;
  }
  const geo::GridPoint c = ccrpGrid();
  if (force || overlay_.motion == Motion::Relative) {
    placeAt(c, ownShipPlace(), rotationRad);
    return;
  }
  // True motion with reset: back to its place when own ship leaves the middle 60% of the screen; a
  // turn of the chart (course-up, head-up) turns it about own ship, which stays where it is.
  const QPointF p = gridToWidget(c.xM, c.yM);
  const bool outside =
      std::abs(p.x() - width() / 2.0) > 0.3 * width() || std::abs(p.y() - height() / 2.0) > 0.3 * height();
  if (outside)
    placeAt(c, ownShipPlace(), rotationRad);
  else if (turned)
    placeAt(c, p, rotationRad);
}

}  // namespace reckoner::ui
