#pragma once
// What tst_main_window's tests share: waiting for the simulation and the window on conditions (never
// on elapsed time), and the screenshots.
#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QDir>
#include <QElapsedTimer>
#include <QScopeGuard>
#include <QSettings>
#include <QStandardPaths>
#include <QTest>
#include <cmath>
#include <vector>

#include "common/angles.h"
#include "common/units.h"
#include "ui/main_window.h"

namespace reckoner::ui::test {

// Conditions are waited for, never time; the limit only ends a test that would otherwise hang, so it
// is generous (a machine loaded by a parallel build runs the simulation several times slower). Under
// AddressSanitizer (Debug, -O0) the simulation runs some 30 times slower, and so may the wait.
#if defined(__SANITIZE_ADDRESS__)
inline constexpr int kTimeoutMs = 600000;
#else
inline constexpr int kTimeoutMs = 120000;
#endif

/// Handles events until `holds()` is true, at most timeoutMs; whether it came true. It takes the first
/// time the condition holds. QTRY_VERIFY evaluates its condition once more after its wait and, when
/// that gives false, waits again and then fails ("the requested timeout was too short"): a condition
/// on the window's refresh or the chart's render holds, then stops holding as the next frame of the
/// running simulation arrives, and holds again a tick later, so QTRY_VERIFY failed tests on a loaded
/// machine that had waited well.
template <class Holds>
[[nodiscard]] bool waitUntil(Holds holds, int timeoutMs = kTimeoutMs) {
  const QDeadlineTimer deadline(timeoutMs);
  for (;;) {
    if (holds()) return true;
    if (deadline.hasExpired()) return false;
    QTest::qWait(10);
  }
}

/// QVERIFY that `expr` comes true within kTimeoutMs (see waitUntil: for conditions that can flicker).
#define RK_WAIT_VERIFY(expr)                                                         \
  QVERIFY2(::reckoner::ui::test::waitUntil([&] { return static_cast<bool>(expr); }), \
           "waited in vain for " #expr)

/// Every GUI test starts from nothing of the user's: QStandardPaths' test locations (settings, the alert
/// log) under an application name of its own, its settings cleared.
inline void isolateFromTheUser(const char* testName) {
  QStandardPaths::setTestModeEnabled(true);
  QCoreApplication::setOrganizationName(QStringLiteral("ReckonerTest"));
  QCoreApplication::setApplicationName(QString::fromLatin1(testName));
  QSettings().clear();
}

inline double simTime(const MainWindow& w) {
  return toSeconds(w.history().latest().frame.timeUs);
}

/// Runs as fast as possible to the simulated time tS, where the worker pauses, and waits until the
/// window shows that frame: its repaint tick has run since (which may also move the view: true motion
/// recentres on own ship), so what a test computes from the view stays true while it acts on it.
inline void runUntil(MainWindow& w, double tS) {
  QElapsedTimer clock;
  clock.start();
  const auto done = qScopeGuard([&] { qInfo("runUntil %g: %lld ms", tS, clock.elapsed()); });
  w.controller()->runTo(tS, -1.0);
  RK_WAIT_VERIFY(simTime(w) >= tS - 1e-9 && !w.history().latest().running && !w.refreshPending());
}

/// Drags own ship's ordered-vector handle, as a user would, to a true course and a speed (the length
/// the handle's time base gives it); returns the grid info at own ship (convergence, scale).
inline geo::GridInfo dragHandleTo(MainWindow& w, double courseDeg, double speedKn) {
  EcdisView* v = w.chart();
  const auto handle = v->handlePosition();
  if (!handle) return {};
  const auto& f = w.history().latest().frame;
  const double ox = f.estimate.x[est::drkf::kPosX], oy = f.estimate.x[est::drkf::kPosY];
  const geo::GridInfo gi = v->frame()->gridInfo({ox, oy});
  const double len = knotsToMps(speedKn) * v->handleMinutes() * 60.0 * gi.scale;
  const double g = degToRad(courseDeg) - gi.convergenceRad;
  const QPointF target = v->gridToWidget(ox + len * std::sin(g), oy + len * std::cos(g));
  QTest::mousePress(v, Qt::LeftButton, {}, handle->toPoint());
  QTest::mouseMove(v, ((*handle + target) / 2).toPoint());
  QTest::mouseMove(v, target.toPoint());
  QTest::mouseRelease(v, Qt::LeftButton, {}, target.toPoint());
  return gi;
}

inline MainWindowOptions freshOptions() {
  MainWindowOptions o;
  o.restoreSession = false;
  o.askToSaveOnClose = false;
  o.sound = false;
  return o;
}

inline void waitReady(MainWindow& w) {
  QTRY_VERIFY_WITH_TIMEOUT(!w.history().empty(), kTimeoutMs);
  QTRY_VERIFY_WITH_TIMEOUT(!w.chart()->cells().empty(), kTimeoutMs);
  RK_WAIT_VERIFY(w.chart()->renderedGeneration() == w.chart()->requestedGeneration() && !w.refreshPending());
}

inline void showAndWait(MainWindow& w, QSize size = {1400, 900}) {
  w.resize(size);
  w.show();
  waitReady(w);
}

inline void saveShot(QWidget& w, const QString& name) {
  QDir().mkpath(QStringLiteral("screenshots"));
  const QString path = QStringLiteral("screenshots/%1.png").arg(name);
  QVERIFY(w.grab().save(path));
  qInfo("screenshot: %s", qPrintable(QDir::current().absoluteFilePath(path)));
}

/// Whether the window shows its latest state: the panels, table and plots show the latest frame (the
/// window's repaint and plot ticks have run since it arrived), the layouts their new contents asked
/// for have been applied (handling the events waiting now leaves the chart's size as it is) and the
/// chart render for the current view has arrived.
inline bool settled(MainWindow& w) {
  if (w.refreshPending()) return false;
  const QSize size = w.chart()->size();
  QCoreApplication::sendPostedEvents();
  QCoreApplication::processEvents();
  return w.chart()->size() == size && w.chart()->renderedGeneration() == w.chart()->requestedGeneration();
}

/// A screenshot of the window once it shows its latest state.
inline void saveWindowShot(MainWindow& w, const QString& name) {
  RK_WAIT_VERIFY(settled(w));
  saveShot(w, name);
}

/// The radar fixes of the busy-shore run with matching switched on at 100 s, up to 400 s: one a sweep,
/// most applied, consistent (mean NEES of 3 dof under 6).
inline void verifyRadarFixesFrom100s(const std::vector<RadarFixSample>& fixes) {
  QVERIFY(!fixes.empty());
  QVERIFY(fixes.front().tS >= 100.0);
  int applied = 0;
  double nees = 0.0;
  for (const auto& f : fixes) {
    applied += f.applied ? 1 : 0;
    nees += f.nees;
  }
  qInfo("%zu fixes from 100 to 400 s, %d applied, mean NEES %.2f (3 dof)", fixes.size(), applied,
        nees / static_cast<double>(fixes.size()));
  QVERIFY(fixes.size() >= 140);  // every 2 s sweep
  QVERIFY(applied >= static_cast<int>(fixes.size()) / 2);
  QVERIFY(nees / static_cast<double>(fixes.size()) < 6.0);
}

/// The centre (vertex mean, grid m) of the charted land ring nearest own ship's estimate.
inline est::Vec<2> nearestLandCentre(const LiveFrame& live) {
  const auto& x = live.frame.estimate.x;
  est::Vec<2> nearest(0, 0);
  double best = 1e300;
  for (const auto& ring : live.land->rings()) {
    est::Vec<2> c(0, 0);
    for (const auto& q : ring) c += q;
    c /= static_cast<double>(ring.size());
    const double d = std::hypot(c[0] - x[est::drkf::kPosX], c[1] - x[est::drkf::kPosY]);
    if (d < best) {
      best = d;
      nearest = c;
    }
  }
  return nearest;
}

}  // namespace reckoner::ui::test
