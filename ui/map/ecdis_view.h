#pragma once
// The ECDIS chart display: the chart (ChartView) with the navigation overlays painted on top at every
// repaint from the GUI thread's SimHistory: own ship (estimated position with the own-ship symbol,
// heading line, COG vector with minute marks, past track, 95% covariance ellipse, latest GPS and
// Loran-C fixes, truth), radar targets (ARPA symbols by status, true or relative vectors, past
// positions, 95% ellipses, labels, raw plots), range rings, one EBL and one VRM, a scale bar and the
// cursor readout. Mouse: drag the handle at the tip of own ship's ordered vector to order course and
// speed; Ctrl+click steers towards a point; click a target to select it; the right button opens the
// context menu (add a target by dragging its vector, acquire, cancel a track, EBL/VRM, pick report).
// Keys: left/right alter course 5 deg (1 with Shift), up/down speed 0.5 kn.
// ecdis_view.cpp holds the state and the input handling, ecdis_paint.cpp the painting, ecdis_radar.cpp
// the radar overlay.
#include <QImage>
#include <QMenu>
#include <QPainterPath>
#include <cmath>
#include <optional>

#include "geo/local_frame.h"
#include "ui/bridge/sim_history.h"
#include "ui/map/chart_view.h"

namespace reckoner::ui {

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
  std::optional<double> eblBearingRad;  ///< true bearing from own ship
  std::optional<double> vrmRangeM;
  double ownLengthM = 120.0, ownBeamM = 20.0;  ///< true-scale own-ship outline when larger than 6 mm
  bool courseUp = false;
  bool followOwnShip = true;
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
  explicit EcdisView(QWidget* parent = nullptr);

  /// The run to draw (owned by the caller, read at every repaint) and its local frame.
  void setHistory(const SimHistory* history, const geo::LocalFrame& frame);
  [[nodiscard]] const std::optional<geo::LocalFrame>& frame() const { return frame_; }
  void setOverlay(const OverlaySettings& s);
  [[nodiscard]] const OverlaySettings& overlay() const { return overlay_; }
  void setSelectedTrack(std::optional<int> trackId);
  [[nodiscard]] std::optional<int> selectedTrack() const { return selected_; }
  /// After a new frame: follows own ship (true motion with reset, course-up) and repaints.
  void frameUpdated();
  /// Centres the view on own ship's estimated position.
  void centreOnOwnShip();
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
  /// The context menu for a widget point (tests trigger its actions).
  QMenu* buildContextMenu(QPointF at);
  [[nodiscard]] bool addingTarget() const { return addTargetFrom_.has_value(); }
  /// The box of the cursor / EBL / VRM readout at the top left (widget pixels; empty when it has no
  /// line). The chart's own notes keep clear of it (the overscale note is at the bottom centre).
  [[nodiscard]] QRect readoutRect() const;
  [[nodiscard]] bool steeringTarget() const { return steerTarget_.has_value(); }

 signals:
  /// Helm order from the mouse or keyboard: true heading, speed through the water.
  void orderRequested(double trueHeadingRad, double speedMps);
  void addTargetRequested(double xM, double yM, double vxMps, double vyMps);
  /// Steer a simulated target (its truth id): true course and speed over ground.
  void steerTargetRequested(int targetId, double trueCourseRad, double speedMps);
  void acquireRequested(double xM, double yM);
  void cancelTrackRequested(int trackId);
  void trackSelected(std::optional<int> trackId);
  void pickRequested(QPointF widgetPoint);
  void overlayChanged(const reckoner::ui::OverlaySettings& s);
  void cursorReadout(const QString& text);

 protected:
  void paintOverlay(QPainter& painter, const charts::Viewport& view) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void contextMenuEvent(QContextMenuEvent* event) override;
  void keyPressEvent(QKeyEvent* event) override;

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
  /// The ordered (or, without an order, the present) true course and speed through the water.
  [[nodiscard]] std::pair<double, double> orderedCourseSpeed() const;
  /// Emits orderRequested and remembers the order until a frame carries it.
  void requestOrder(double trueCourseRad, double speedMps);
  // ecdis_paint.cpp
  /// The 95% ellipse of a grid position covariance (m^2) around a point, in widget pixels.
  static QPolygonF ellipse95(const Local& at, double pxx, double pxy, double pyy, int points);
  [[nodiscard]] QColor colour(const char* role) const;
  void paintRings(QPainter& p, const Local& own);
  void paintOwnShip(QPainter& p);
  void paintPastTrack(QPainter& p);
  void paintTruth(QPainter& p, const Local& own);
  void paintFixes(QPainter& p);
  void paintOwnEllipse(QPainter& p, const Local& own);
  void paintSeed002(QPainter& p);
  void paintCourseVector(QPainter& p, const Local& own);
  void paintOrderedVector(QPainter& p, const Local& own);
  void paintOwnSymbol(QPainter& p, const Local& own);
  void paintTargets(QPainter& p);
  void paintTarget(QPainter& p, const sim::TrackSnapshot& t, const TargetPaint& k);
  void paintPlots(QPainter& p);
  void paintScaleBar(QPainter& p, const charts::Viewport& view);
  void paintReadouts(QPainter& p);
  [[nodiscard]] QStringList readoutLines() const;
  [[nodiscard]] QFont readoutFont() const;
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
  std::optional<geo::GridPoint> addTargetFrom_;  // add-target mode: the target's start
  std::optional<QPointF> addTargetTo_;
  std::optional<int> steerTarget_;  // steer-target mode: the target's truth id (addTargetFrom_: its track)
  int steerTrack_ = 0;              // ... and the track the operator chose it by (the number shown)
  std::optional<QPointF> cursor_;
  double appliedRotation_ = 0.0;
  double lastHeadingRad_ = 0.0;  // grid
  struct PendingOrder {
    double course, speed;  // true course, speed through the water
    quint64 sequence;      // the latest frame when it was given
  };
  std::optional<PendingOrder> pendingOrder_;
  // The radar picture coloured (rebuilt when the raster or the colour changes), and the charted land
  // as one even-odd path in grid metres with a surrounding rectangle: the water, to clip to.
  QImage radarImage_;
  const void* radarImageOf_ = nullptr;
  QRgb radarImageColour_ = 0;
  QPainterPath water_;
  const void* waterOf_ = nullptr;
};

}  // namespace reckoner::ui
