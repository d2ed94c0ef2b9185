#pragma once
// The ECDIS chart display: the chart (ChartView) with the navigation overlays painted on top at every
// repaint from the GUI thread's SimHistory: own ship (estimated position with the own-ship symbol,
// heading line, COG vector with minute marks, past track, 95% covariance ellipse, latest GPS and
// Loran-C fixes, truth), radar targets (ARPA symbols by status, true or relative vectors, past
// positions, 95% ellipses, labels that never overlap, raw plots), range rings, one EBL and one VRM, a
// scale bar, the north arrow, the display modes and the cursor readout. Own ship's reference for range,
// bearing, rings, EBL/VRM, vectors and CPA is the CCRP (a point of the hull, docs/gui.md "CCRP").
// Orientation north-up, course-up (stabilised) or head-up; true motion with reset or relative motion
// (own ship fixed on screen, centred or off-centred); a drag pans and stops following own ship.
// Mouse: drag the handle at the tip of own ship's ordered vector to order course and speed; Ctrl+click
// steers towards a point; click a target to select it; the right button opens the context menu (add a
// target by dragging its vector, acquire, cancel a track, EBL/VRM, pick report).
// The route (route_overlay.h) is drawn under own ship and the targets; in Route edit mode it takes the
// mouse first (a click adds a waypoint, a drag of one moves it, the context menu inserts and deletes).
// Keys: left/right alter course 5 deg (1 with Shift), up/down speed 0.5 kn.
// ecdis_view.cpp holds the state and the input handling, ecdis_motion.cpp the orientation, motion and
// CCRP, ecdis_paint.cpp the painting of own ship and targets, ecdis_indications.cpp the readouts and
// indications, ecdis_radar.cpp the radar overlay, ecdis_route.cpp the route (its state and mouse input
// in RouteOverlay, route_overlay.h).
#include <QImage>
#include <QMenu>
#include <QPainterPath>
#include <cmath>
#include <optional>

#include "geo/local_frame.h"
#include "ui/bridge/sim_history.h"
#include "ui/common/display_units.h"
#include "ui/map/chart_view.h"
#include "ui/map/ecdis_ais.h"
#include "ui/map/guard_zones.h"
#include "ui/map/route_overlay.h"

namespace reckoner::ui {

/// What is up on the chart: north; own ship's course over ground, stabilised (the chart turns when the
/// course has moved more than 5 degrees); own ship's heading, unstabilised (the chart turns with every
/// heading change).
enum class Orientation { NorthUp = 0, CourseUp = 1, HeadUp = 2 };
/// True motion with reset (own ship moves over a still chart, back to its place when it leaves the
/// middle 60%) or relative motion (own ship still on screen, the chart moving under it).
enum class Motion { True = 0, Relative = 1 };

struct OverlaySettings {
  bool relativeVectors = false;
  double vectorMinutes = 6.0;
  bool showTruth = true;
  bool showEllipses = true;
  bool showPlots = false;
  bool showPastTrack = true;
  double pastTrackMinutes = 15.0;
  /// Range rings around own ship out to the displayed range, at its standard interval (range_scale.h).
  bool showRings = true;
  std::optional<double> eblBearingRad;  ///< true bearing from own ship's CCRP
  std::optional<double> vrmRangeM;
  double ownLengthM = 120.0, ownBeamM = 20.0;  ///< true-scale own-ship outline when larger than 6 mm
  /// The CCRP in the hull: metres aft of the bow and to starboard of the centreline (default the
  /// ship's centre, the point the DRKF estimates).
  double ccrpFromBowM = 60.0, ccrpToStarboardM = 0.0;
  Orientation orientation = Orientation::NorthUp;
  Motion motion = Motion::True;
  /// Own ship's place on screen (relative motion, and where a true-motion reset puts it): the centre,
  /// or off-centred astern by half the range so that one and a half ranges show ahead.
  bool offCentred = false;
  /// Whether the view follows own ship at all (a pan switches it off; "centre own ship" on again).
  bool followOwnShip = true;
  /// Targets' past positions: this many dots this far apart (0 dots: none).
  int targetPastCount = 6;
  double targetPastIntervalS = 30.0;
  bool showTargetLabels = true;
  /// Also draw one of seed 002's own-ship estimates (position and 95% ellipse): 0 none, 1 the
  /// geodetic KF, 2 least squares.
  int seed002Shown = 0;
  /// Radar overlay (seed 004): the simulated picture, drawn over the whole chart or under the chart's
  /// land areas (it then shows on water only), in one of the radar colours with this opacity; and the
  /// echoes of the latest match with the chart points they were matched to.
  bool showRadarPicture = false;
  bool radarOverChart = true;
  double radarOpacity = 0.6;
  int radarColour = 0;  ///< kRadarColours
  bool showRadarEchoes = false;
  /// AIS targets (Live mode) as IEC 62288 draws them (ecdis_ais.h).
  bool showAis = true;
  /// An AIS station associated with a radar track shows one symbol: the AIS one, or with this the
  /// radar track's; the other appears when the track is selected.
  bool associatedAsRadar = false;
};

/// The radar picture's colours: name and day colour (dimmed at dusk and night).
struct RadarColour {
  const char* name;
  QRgb day;
};
inline constexpr RadarColour kRadarColours[] = {
    {"Amber", qRgb(255, 170, 0)},
    {"Green", qRgb(40, 200, 40)},
    {"Yellow", qRgb(235, 225, 0)},
    {"Cyan", qRgb(0, 200, 230)},
};

class EcdisView : public ChartView {
  Q_OBJECT
 public:
  /// The cursor readout at widget point p: position, and true bearing and range from own ship along the
  /// geodesic (valid anywhere on the chart).
  [[nodiscard]] QString cursorText(QPointF p) const;
  /// True bearing and range of a point from own ship's CCRP ("045.0° 1.23 NM"), or empty without own
  /// ship or where the geodesic fails.
  [[nodiscard]] QString fromOwnShipText(charts::LatLon where) const;
  explicit EcdisView(QWidget* parent = nullptr);

  /// The run to draw (owned by the caller, read at every repaint) and its local frame.
  void setHistory(const SimHistory* history, const geo::LocalFrame& frame);
  [[nodiscard]] const std::optional<geo::LocalFrame>& frame() const { return frame_; }
  void setOverlay(const OverlaySettings& s);
  [[nodiscard]] const OverlaySettings& overlay() const { return overlay_; }
  void setSelectedTrack(std::optional<int> trackId);
  /// Trial manoeuvre mode (docs/trial.md): a drag of the ordered-vector handle proposes a trial course
  /// and speed (trialRequested) instead of ordering them; the frame's trial is drawn with a "T".
  void setTrialMode(bool on);
  [[nodiscard]] bool trialMode() const { return trialMode_; }
  [[nodiscard]] std::optional<int> selectedTrack() const { return selected_; }
  /// After a new frame: turns the chart (course-up, head-up), follows own ship (true motion with reset,
  /// relative motion) and repaints.
  void frameUpdated();
  /// Follows own ship again and puts its CCRP at its place on screen now (the centre, or off-centred):
  /// the true-motion reset, and what "centre own ship" does after a pan.
  void centreOnOwnShip();
  void setUnits(const DisplayUnits& units);
  [[nodiscard]] const DisplayUnits& units() const { return units_; }

  // Own ship as the display takes it (ecdis_motion.cpp).
  /// Own ship's heading (grid, rad): the direction of the estimated velocity through the water, held
  /// from the last time the ship was moving clearly enough to have one.
  [[nodiscard]] double headingGridRad() const;
  /// The same, true (what head-up turns to).
  [[nodiscard]] double headingTrueRad() const;
  /// The CCRP's grid position: the estimate plus the CCRP's offset in the hull turned by the heading.
  [[nodiscard]] geo::GridPoint ccrpGrid() const;
  /// The CCRP's offset from the estimated position, grid metres (zero at the default CCRP).
  [[nodiscard]] geo::GridPoint ccrpOffsetGrid() const;
  [[nodiscard]] QPointF ccrpWidget() const;
  /// Where own ship's CCRP is kept on screen: the centre, or off-centred astern.
  [[nodiscard]] QPointF ownShipPlace() const;
  /// The largest of the usual scales (1:25 000 to 1:700 000) that shows own ship and every present
  /// target inside a margin, centred on them (the first view of a scenario).
  void fitOwnShipAndTargets();
  /// Centres on own ship at the scale that shows rangeNm to the nearest edge.
  void setRangeNm(double rangeNm);
  /// To the next standard range up (step > 0, '-' key) or down (step < 0, '+' key).
  void stepRange(int step);

  // Geometry shared with the tests: widget pixels of a grid point, and back.
  [[nodiscard]] QPointF gridToWidget(double xM, double yM) const;
  [[nodiscard]] geo::GridPoint widgetToGrid(QPointF p) const;
  /// Widget position of the ordered-vector handle (own ship's ordered course and speed).
  [[nodiscard]] std::optional<QPointF> handlePosition() const;
  /// The time base of the handle: the vector time, halved until the handle is on screen (down to
  /// 30 s) while own ship is; a drag orders the speed that covers the dragged length in this time.
  [[nodiscard]] double handleMinutes() const;
  /// The ordered (or, without an order, the present) true course and speed through the water.
  [[nodiscard]] std::pair<double, double> orderedCourseSpeed() const;
  /// Orders own ship's true course and speed through the water (typed in the own-ship panel): shown
  /// at once, sent as orderRequested.
  void requestOrder(double trueCourseRad, double speedMps);
  /// The labels of the last paint (the helm order's readout and the target labels): text and box.
  struct PlacedLabel {
    QString text;
    QRectF box;
  };
  [[nodiscard]] const std::vector<PlacedLabel>& placedLabels() const { return placedLabels_; }
  /// The own-ship symbol's box in the last paint (labels keep out of it).
  [[nodiscard]] QRectF ownSymbolBox() const;
  /// The display modes as the chart shows them, top right ("H UP   RM", "VECT T 6 min", ...).
  [[nodiscard]] QStringList modeLines() const;
  /// The north arrow's centre in the last paint (none in north-up).
  [[nodiscard]] std::optional<QPointF> northArrowAt() const { return northArrowAt_; }
  /// The context menu for a widget point (tests trigger its actions).
  QMenu* buildContextMenu(QPointF at);
  [[nodiscard]] bool addingTarget() const { return addTargetFrom_.has_value(); }
  /// The box of the cursor / EBL / VRM readout at the top left (widget pixels; empty when it has no
  /// line). The chart's own notes keep clear of it (the overscale note is at the bottom centre).
  [[nodiscard]] QRect readoutRect() const;
  [[nodiscard]] bool steeringTarget() const { return steerTarget_.has_value(); }
  /// Own ship's polar frame on screen (range and true bearing from the estimated position); nullopt
  /// before the first frame.
  [[nodiscard]] std::optional<PolarMap> polarMap() const;
  /// The guard zones drawn: being dragged, else just edited (until a frame has them), else the frame's.
  [[nodiscard]] std::vector<track::AcquisitionZone> shownZones() const;
  /// The route shown, its findings and route editing (route_overlay.h); the view draws it and passes
  /// it the mouse and keys.
  [[nodiscard]] RouteOverlay* routeOverlay() const { return routeOverlay_; }

 signals:
  /// Helm order from the mouse or keyboard: true heading, speed through the water.
  void orderRequested(double trueHeadingRad, double speedMps);
  /// A trial course and speed dragged in trial mode (true heading, speed through the water).
  void trialRequested(double trueHeadingRad, double speedMps);
  void addTargetRequested(double xM, double yM, double vxMps, double vyMps);
  /// Steer a simulated target (its truth id): true course and speed over ground.
  void steerTargetRequested(int targetId, double trueCourseRad, double speedMps);
  void acquireRequested(double xM, double yM);
  void cancelTrackRequested(int trackId);
  void trackSelected(std::optional<int> trackId);
  void pickRequested(QPointF widgetPoint);
  void overlayChanged(const reckoner::ui::OverlaySettings& s);
  void cursorReadout(const QString& text);
  /// The guard zones as the operator edited them on the chart (drag an edge; the context menu).
  void zonesEdited(const std::vector<reckoner::track::AcquisitionZone>& zones);
  /// The ordered course and speed shown changed (a drag, a key, a typed order, or a frame).
  void orderShown(double trueCourseRad, double speedMps);
  /// The CCRP's offset from the estimated position changed (grid metres; the convergence at own ship).
  void ccrpOffsetChanged(double dxM, double dyM, double convergenceRad);

 protected:
  void paintOverlay(QPainter& painter, const charts::Viewport& view) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void contextMenuEvent(QContextMenuEvent* event) override;
  void keyPressEvent(QKeyEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  bool chartClicked(QPointF at) override;

 private:
  static constexpr double kHandleRadiusPx = 7.0;
  /// A grid point's widget position and the local Jacobian of widget pixels per grid metre.
  struct Local {
    QPointF p;
    double a = 1, b = 0, c = 0, d = 1;  // widget px per grid metre
    [[nodiscard]] QPointF offset(double dxM, double dyM) const {
      return {p.x() + a * dxM + b * dyM, p.y() + c * dxM + d * dyM};
    }
    [[nodiscard]] double pxPerMetre() const { return std::sqrt(std::abs(a * d - b * c)); }
  };
  /// What every target's symbol needs from the frame (paintTargets -> paintTarget).
  struct TargetPaint {
    double ownVx = 0.0, ownVy = 0.0;  ///< own ship's velocity over ground, grid m/s
    double radiusPx = 0.0;            ///< symbol radius
    bool flashOn = true;              ///< the 1 Hz flash of unacknowledged dangerous targets
    double nowS = 0.0;
  };
  // ecdis_view.cpp
  [[nodiscard]] Local localAt(double xM, double yM) const;
  [[nodiscard]] std::optional<int> trackNear(QPointF p, double tolPx = 14.0) const;
  [[nodiscard]] bool haveOwnShip() const { return history_ && !history_->empty() && frame_; }
  /// The handle's position for a time base (minutes).
  [[nodiscard]] std::optional<QPointF> handleAt(double minutes) const;
  /// True bearing (rad) and range (true m) of grid point g from the CCRP.
  [[nodiscard]] std::pair<double, double> bearingRangeFromCcrp(const geo::GridPoint& g) const;
  /// The course and speed the handle at widget point p orders (with the handle's time base).
  [[nodiscard]] std::pair<double, double> orderAt(QPointF p, double minutes) const;
  void emitOrderShown();
  void emitCcrpOffset();
  // ecdis_motion.cpp
  /// The rotation (rad, the up direction's true bearing) the orientation asks for now.
  [[nodiscard]] double wantedRotation();
  /// Sets the view so that the grid point g shows at widget point at, with this rotation.
  void placeAt(const geo::GridPoint& g, QPointF at, double rotationRad);
  /// Follows own ship after a frame or a change of mode (true motion: a reset when it leaves the
  /// middle; relative: always at its place; rotation about own ship).
  void applyMotion(double rotationRad, bool force);
  // ecdis_paint.cpp
  /// The 95% ellipse of a grid position covariance (m^2) around a point, in widget pixels.
  static QPolygonF ellipse95(const Local& at, double pxx, double pxy, double pyy, int points);
  [[nodiscard]] QColor colour(const char* role) const;
  void paintRings(QPainter& p, const Local& own);
  void paintZones(QPainter& p);
  void addZoneActions(QMenu* menu, QPointF at);
  void editZones(const std::vector<track::AcquisitionZone>& zones);
  void paintOwnShip(QPainter& p);
  void paintPastTrack(QPainter& p);
  void paintTruth(QPainter& p, const Local& own);
  void paintFixes(QPainter& p);
  void paintOwnEllipse(QPainter& p, const Local& own);
  void paintSeed002(QPainter& p);
  void paintCourseVector(QPainter& p, const Local& own);
  void paintOrderedVector(QPainter& p, const Local& own);
  /// The true-scale outline around the estimate, or none when it would be under 6 mm.
  [[nodiscard]] QPolygonF ownOutline(const Local& est) const;
  void paintOwnSymbol(QPainter& p, const Local& est, const Local& ccrp);
  void paintTargets(QPainter& p);
  void paintTarget(QPainter& p, const sim::TrackSnapshot& t, const TargetPaint& k);
  void paintPlots(QPainter& p);
  void paintLabels(QPainter& p);
  // ecdis_indications.cpp
  void paintScaleBar(QPainter& p, const charts::Viewport& view);
  void paintNorthArrow(QPainter& p, const charts::Viewport& view, QPointF centre);
  /// The display modes, top right ("H UP  RM  VECT T 6 min"); returns the box it took.
  QRectF paintModes(QPainter& p);
  /// The readouts top left; returns the box it took (empty when none).
  QRectF paintReadouts(QPainter& p);
  [[nodiscard]] QStringList readoutLines() const;
  // ecdis_ais.cpp
  /// The AIS targets of the latest frame; their symbols are made again when the table changed.
  void paintAis(QPainter& p);
  // ecdis_trial.cpp
  void paintTrial(QPainter& p);
  void paintDangerSectors(QPainter& p, const sim::TrialResult& r, const Local& own);
  // ecdis_route.cpp
  void paintRoute(QPainter& p);
  void paintLookAhead(QPainter& p);
  void paintRouteLegs(QPainter& p, const RouteGeometry& g, const QColor& c, bool dashed);
  /// The cross-track limits, the turn arcs and the wheel-over lines.
  void paintRouteMarks(QPainter& p, const RouteGeometry& g, const QColor& c);
  void paintRouteWaypoints(QPainter& p, const geo::Route& route, const RouteGeometry& g, const QColor& c,
                           std::optional<std::size_t> selected);
  void paintRouteFindings(QPainter& p);
  // ecdis_radar.cpp
  void paintRadarPicture(QPainter& p);
  void paintRadarEchoes(QPainter& p);
  /// The radar colour for the palette (dimmed at dusk and night).
  [[nodiscard]] QColor radarColour() const;

  const SimHistory* history_ = nullptr;
  std::optional<geo::LocalFrame> frame_;
  OverlaySettings overlay_;
  std::optional<int> selected_;
  bool draggingHandle_ = false;
  std::optional<QPointF> handleDrag_;            // where the handle is being dragged
  double dragMinutes_ = 6.0;                     // ... and its time base, fixed at the press
  std::optional<geo::GridPoint> addTargetFrom_;  // add-target mode: the target's start
  std::optional<QPointF> addTargetTo_;
  std::optional<int> steerTarget_;  // steer-target mode: the target's truth id (addTargetFrom_: its track)
  int steerTrack_ = 0;              // ... and the track the operator chose it by (the number shown)
  std::optional<QPointF> cursor_;
  GuardZoneEditor zoneEditor_;
  std::optional<std::vector<track::AcquisitionZone>> pendingZones_;  // edited, not yet in a frame
  double appliedRotation_ = 0.0;  // the stabilised course: course-up's up, north-up's off-centring
  bool rotationStale_ = true;     // ... taken afresh at the next frame whatever the course
  double lastHeadingRad_ = 0.0;   // grid, held (headingGridRad)
  DisplayUnits units_;
  std::vector<PlacedLabel> placedLabels_;
  std::optional<QPointF> northArrowAt_;
  // What a label must not cover, collected while painting: own ship, the targets' symbols, the boxes.
  std::vector<QRectF> labelObstacles_;
  struct PendingLabel {
    QString text;
    QPointF anchor;
    double clearancePx;
    QColor colour;
    double pointSize;
    bool boxed;  // on a panel-coloured box (the helm order's readout)
  };
  std::vector<PendingLabel> pendingLabels_;
  std::optional<std::pair<double, double>> lastOrderShown_;
  std::optional<geo::GridPoint> lastCcrpOffset_;
  struct PendingOrder {
    double course, speed;  // true course, speed through the water
    quint64 sequence;      // the latest frame when it was given
  };
  std::optional<PendingOrder> pendingOrder_;
  // The radar picture coloured (rebuilt when the raster or the colour changes), and the charted land
  // as one even-odd path in grid metres with a surrounding rectangle: the water, to clip to.
  QImage radarImage_;
  std::shared_ptr<const RadarRaster> radarImageOf_;  // held, so a new raster is never taken for it by address
  QRgb radarImageColour_ = 0;
  QPainterPath water_;
  std::shared_ptr<const radar::LandMask> waterOf_;  // held, likewise
  // The AIS symbols of the latest table (made again when the frame brings another table).
  std::vector<AisSymbol> aisSymbols_;
  bool trialMode_ = false;
  RouteOverlay* routeOverlay_ = nullptr;
  std::shared_ptr<const std::vector<track::AisTarget>> aisSymbolsOf_;  // held: never mistaken by address
};

}  // namespace reckoner::ui
