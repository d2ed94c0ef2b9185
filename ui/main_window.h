#pragma once
// The ECDIS window: the chart with the navigation overlays in the centre; docks for own ship, sensors,
// the ARPA target table, the error plots, alarms and pick reports; a toolbar with the simulation clock,
// time control and display settings. The simulation runs in a worker thread (SimulationController);
// frames are stored in SimHistory as they arrive and a timer repaints at no more than 30 Hz. Charts
// load in a worker thread of their own (ChartLoadWorker). main_window.cpp holds the state (frames,
// repaints, files, settings); main_window_actions.cpp builds the docks, menus and toolbars.
#include <QElapsedTimer>
#include <QLabel>
#include <QMainWindow>
#include <QTimer>
#include <optional>
#include <vector>

#include "connections/connection_hub.h"
#include "geo/route_turns.h"
#include "ui/bridge/chart_load_worker.h"
#include "ui/bridge/sim_history.h"
#include "ui/bridge/simulation_controller.h"
#include "ui/bridge/worker_thread.h"
#include "ui/map/ecdis_view.h"
#include "ui/route_check_cache.h"

QT_BEGIN_NAMESPACE
class QActionGroup;
class QComboBox;
class QDockWidget;
class QDoubleSpinBox;
class QListWidget;
class QMenu;
class QProgressBar;
class QSortFilterProxyModel;
class QTableView;
class QTextBrowser;
class QToolBar;
class QToolButton;
QT_END_NAMESPACE

namespace reckoner::ui {

class AisTableModel;
class AlertPanel;
class ConnectionIndicator;
class DataMonitor;
class AlertSound;
class MessageBar;
class ChartListPanel;
class ErrorPlots;
class OwnShipPanel;
class PlaybackBar;
class RouteLibrary;
class RoutePanel;
struct RouteFindingRow;
class SensorPanel;
class TargetTableModel;
class VoyagePanel;

struct MainWindowOptions {
  std::string scenarioPath;    ///< empty: the last one (settings) or the embedded default
  std::string encPath;         ///< empty: the last one (settings) or the embedded default chart
  bool restoreSession = true;  ///< reopen the last scenario and chart named in the settings
  /// On closing with unsaved operator changes, ask whether to save them (tests say no).
  bool askToSaveOnClose = true;
  /// The alerts' audible signal (never on the offscreen platform; tests say no).
  bool sound = true;
};

class MainWindow : public QMainWindow {
  Q_OBJECT
 public:
  explicit MainWindow(const MainWindowOptions& options = {}, QWidget* parent = nullptr);
  ~MainWindow() override;

  /// Loads a scenario file ("builtin:NAME" for an embedded one); false with a message on failure.
  bool openScenario(const QString& path);
  void loadScenario(const sim::Scenario& scenario, const QString& source);
  /// What the view does when the charts of a load arrive: show them (File > Open ENC, recent charts:
  /// zoomed to their coverage unless they cover the view's centre already, following own ship
  /// switched off when the view leaves it), or stay where it is (the session's charts at start).
  enum class ChartArrival { Show, Stay };
  /// Starts loading charts (file or folder, or builtin:default) in a background thread; a load still
  /// running is superseded (it stops, and its cells are not shown). The charts loaded replace those
  /// open. This is what File > Open ENC cell / folder call with the chosen path.
  void openCharts(const QString& path, ChartArrival arrival = ChartArrival::Show);
  /// Writes the scenario as edited so far (blocks the GUI only for the file write; the worker answers
  /// a queued request first, waited for with a local event loop).
  bool saveScenario(const QString& path);
  /// Simulated seconds per wall second; 0 pauses, < 0 as fast as possible.
  void setRate(double rate);
  /// Save to the scenario's file, or ask for one (a built-in scenario has none).
  bool save();
  /// Asks for a file name (".json" added when it has no suffix) and saves.
  bool saveAs();
  /// The operator's CPA (NM) and TCPA (min) limits for dangerous targets and their alarm, for this run
  /// and remembered for the next ones (Tracking > CPA/TCPA limits).
  void setCpaLimits(double cpaNm, double tcpaMin);
  /// The mariner's chart settings (shallow, safety and deep contours, safety depth, category...): shown
  /// at once, in the display toolbar too, and remembered for the next runs (Chart > Mariner settings).
  /// Settings that fail marinerSettingsProblem are refused with that message (false).
  bool setMarinerSettings(const charts::MarinerSettings& s);
  /// View > Units: distances and speeds everywhere in these units, remembered for the next runs.
  void setDisplayUnits(const DisplayUnits& units);
  /// View > CCRP: own ship's reference point, metres aft of the bow and to starboard of the centreline
  /// (remembered); refused with a message outside the hull.
  void setCcrp(double fromBowM, double toStarboardM);

  /// Live mode (Live > Live mode, docs/gui.md "Live"): the window's connections through the live
  /// session instead of the simulation; false with a message when there is no connection. stopLive()
  /// goes back to the simulation, the scenario loaded again from its start.
  bool startLive();
  void stopLive();
  [[nodiscard]] bool isLive() const;
  /// Live > Play back a record…: the voyage record through the live worker, paused at its start, with
  /// the playback bar (docs/gui.md "Playback"); false with a message when there is no such file (a
  /// record that cannot be read is reported when the worker opens it). stopLive() ends it.
  bool startPlayback(const QString& path);
  [[nodiscard]] bool isPlayback() const;
  /// Live > Record the live run…: the live runs started from now on are recorded to this new file
  /// (docs/recorder.md); empty: not recorded. False with a message when the file exists.
  bool setLiveRecordPath(const QString& path);
  [[nodiscard]] PlaybackBar* playbackBar() const { return playbackBar_; }
  /// Live > NMEA output: where the live run's own ship, tracks and alerts go as NMEA 0183 (a
  /// --nmea-out destination; empty: nowhere), remembered; false with a message naming what is wrong.
  bool setLiveNmeaOut(const QString& spec);

  /// Routes (docs/gui.md "Routes"; main_window_routes.cpp). The library holds the routes, the one shown
  /// and the active one: connect to routeLibrary()->activeRouteChanged(const geo::Route&) to follow
  /// the active route (an empty route: none), or read routeLibrary()->activeRoute().
  [[nodiscard]] RouteLibrary* routeLibrary() const { return routes_; }
  [[nodiscard]] RoutePanel* routePanel() const { return routePanel_; }
  /// The Voyage dock: own ship against the active route, the look-ahead (main_window_voyage.cpp).
  [[nodiscard]] VoyagePanel* voyagePanel() const { return voyagePanel_; }
  /// Route > Edit route (with a new route when none is shown); Esc on the chart ends it.
  void setRouteEditing(bool on);
  /// Route > Import: adds an RTZ or GPX file to the library; false with a message naming the file
  /// and the reason.
  bool importRoute(const QString& path);
  /// Route > Save route: the route shown into the library's directory; false with a message.
  bool saveRoute();
  /// Route > Check route: the route shown against the open charts with the mariner's safety contour
  /// and depth, now (it also runs 300 ms after each edit and when the charts or settings change).
  void checkRoute();
  [[nodiscard]] const std::vector<charts::RouteFinding>& routeFindings() const { return routeFindings_; }
  [[nodiscard]] const RouteCheckCache& routeCheckCache() const { return routeCheck_; }
  /// Whether a route check is waiting for its delay after an edit.
  [[nodiscard]] bool routeCheckPending() const { return routeCheckTimer_.isActive(); }

  // For tests and the benchmark.
  /// The window's connections (Live > Connections), loaded from the settings at start.
  [[nodiscard]] conn::ConnectionHub* hub() const { return hub_; }
  [[nodiscard]] AisTableModel* aisModel() const { return aisModel_; }
  [[nodiscard]] QTableView* aisTable() const { return aisTable_; }
  [[nodiscard]] DataMonitor* dataMonitor() const { return monitor_; }
  [[nodiscard]] ConnectionIndicator* connectionIndicator() const { return indicator_; }
  [[nodiscard]] QLabel* clock() const { return clock_; }
  [[nodiscard]] EcdisView* chart() const { return view_; }
  [[nodiscard]] SimulationController* controller() const { return controller_; }
  [[nodiscard]] const SimHistory& history() const { return history_; }
  [[nodiscard]] SensorPanel* sensorPanel() const { return sensors_; }
  [[nodiscard]] OwnShipPanel* ownShipPanel() const { return ownPanel_; }
  [[nodiscard]] ErrorPlots* ownPlots() const { return ownPlots_; }
  [[nodiscard]] ErrorPlots* targetPlots() const { return targetPlots_; }
  [[nodiscard]] QTableView* targetTable() const { return table_; }
  [[nodiscard]] TargetTableModel* targetModel() const { return model_; }
  [[nodiscard]] AlertPanel* alertPanel() const { return alertPanel_; }
  [[nodiscard]] AlertSound* alertSound() const { return sound_; }
  [[nodiscard]] ChartListPanel* chartList() const { return chartList_; }
  /// The toolbar banner with the most urgent alert (shown while there is one).
  [[nodiscard]] QLabel* alarmBanner() const { return alarmBanner_; }
  /// The alert log file: every alert change, one line each, appended across runs (docs/alerts.md).
  [[nodiscard]] QString alertLogPath() const { return alertLogPath_; }
  /// Help > About: the program's version and those of Qt, GDAL, GeographicLib and Eigen.
  [[nodiscard]] static QString aboutText();
  /// Help > Keyboard shortcuts.
  [[nodiscard]] static QString shortcutsText();
  /// Whether the latest chart load has not answered yet (no answer to an older one can follow it).
  [[nodiscard]] bool chartsLoading() const { return chartsLoading_; }
  [[nodiscard]] QString lastError() const { return lastError_; }
  /// The bar above the chart that shows the latest error until dismissed.
  [[nodiscard]] MessageBar* messageBar() const { return messageBar_; }
  /// Whether a frame has arrived that the panels, table, chart overlays or plots do not show yet
  /// (they follow at the window's repaint and plot ticks).
  [[nodiscard]] bool refreshPending() const { return frameDirty_ || plotsDirty_; }
  void setPalette(charts::Palette palette);
  /// GUI-thread work, timed: each frame arrival, each repaint (panels, table, chart with overlays)
  /// and each plot refresh.
  struct GuiTiming {
    enum class Kind { Frame, Repaint, Plots };
    Kind kind;
    double ms;
  };
  [[nodiscard]] const std::vector<GuiTiming>& guiTimings() const { return guiTimings_; }
  void clearGuiTimings() { guiTimings_.clear(); }

 protected:
  void closeEvent(QCloseEvent* event) override;
  void showEvent(QShowEvent* event) override;

 private:
  // main_window_actions.cpp: the docks, menus and toolbars.
  /// A dock holding `w` in a scroll area (so that no dock sets the window's minimum size).
  QDockWidget* addScrollDock(const QString& title, const QString& name, QWidget* w, Qt::DockWidgetArea area);
  void buildDocks();
  void arrangeDocks();
  void buildActions();
  void buildFileMenu();
  void buildSimulationToolbar();
  void buildDisplayToolbar();
  void buildRangeBox(QToolBar* bar);
  void buildTrackingMenu();
  /// Tracking > Trial manoeuvre, its delay, and the symbol of associated AIS targets (main_window_trial.cpp).
  void buildTrialActions(QMenu* tracking);
  void setTrialShown(bool on);
  void askCpaLimits();
  void editMarinerSettings();
  void buildCentre();                                          ///< the chart with the message bar above it
  void showMarinerSettings(const charts::MarinerSettings& s);  ///< in the display toolbar
  void buildViewMenu();
  void buildHelpMenu();
  void buildRadarMenu();
  // main_window_display.cpp: the display modes.
  void buildDisplayModes(QToolBar* bar);
  void buildDisplayMenu(QMenu* viewMenu);
  void buildUnitsMenu(QMenu* units);
  /// The display's actions shared by the toolbar and the View menu, made at the first call.
  QAction* displayAction(const char* name);
  void connectDisplay();
  void readDisplaySettings();
  void rememberDisplaySettings(const OverlaySettings& o);
  void askCcrp();
  // main_window_charts.cpp: the chart list dock, the chart items of the View menu, arriving charts.
  void buildChartDock();
  void buildChartViewActions(QMenu* viewMenu);
  /// View > Centre on own ship (Home; also in the display toolbar): centres and follows own ship again.
  QAction* centreOwnShipAction();
  /// After a load from the user: moves the view to the charts unless they cover its centre (see
  /// ChartArrival) and says what happened in the status bar (with `failures`, the first failure).
  void showArrivedCharts(const std::vector<charts::CellPtr>& cells, const QString& failures);
  /// The status bar's chart figures after a render: cells, scale, overscale, render time.
  void showChartStatus(double renderMs);
  // main_window_playback.cpp: playback of a voyage record.
  void buildPlayback(QMenu* liveMenu);
  void showPlayback(const LiveFrame& live);
  // main_window_voyage.cpp: the active route to the simulation, route monitoring.
  void buildVoyageDock();
  void buildVoyageActions(QMenu* routeMenu);
  /// The library's active route (when it has a leg and no problems; else none) and Follow route to the
  /// simulation and a live run.
  void sendActiveRoute();
  void showVoyage(const LiveFrame& live);
  // main_window_routes.cpp: routes.
  void buildRouteDock();
  void buildRouteMenu();
  void connectRoutes();
  /// The library's current route in the dock and on the chart (with the active one when another).
  void showCurrentRoute();
  void applyRouteEdit(const geo::Route& after, const QString& what);
  void askExportRoute();
  void askDeleteRoute();
  [[nodiscard]] std::vector<RouteFindingRow> routeTurnRows(const geo::Route& route) const;
  [[nodiscard]] std::vector<RouteFindingRow> routeFindingRows(const geo::Route& route) const;
  /// A finding chosen in the list: the chart centred on it, its feature's pick report.
  void showRouteFinding(int index);
  /// A waypoint chosen in the table: selected on the chart, brought on screen when it is off it.
  void showRouteWaypoint(int index);
  void stopFollowingOwnShip();
  /// On closing: routes edited and not saved are saved, left, or the window stays open (asked).
  [[nodiscard]] bool confirmUnsavedRoutes();
  // main_window_live.cpp: Live mode.
  void buildLive();
  void buildLiveMenu();
  void askLiveNmeaOut();
  /// A live frame: the view's grid frame follows the live run's origin.
  void liveFrameArrived(const LiveFrame& frame);
  void refreshAisTable(const LiveFrame& live);
  [[nodiscard]] QString liveClockText(const LiveFrame& live) const;
  /// A checkable action in `menu` that switches one overlay setting.
  QAction* addOverlayToggle(QMenu* menu, const QString& name, bool OverlaySettings::*member);

  void onFrame(const LiveFrame& frame);
  void onChartLoadProgress(quint64 generation, int done, int total);
  void onChartsLoaded(const ChartLoadAnswer& answer);
  void repaintTick();
  void refreshPlots();
  void updateClock();
  void updateAlarms();
  void appendAlertLog(const LiveFrame& frame);
  void updateTitle();
  void showPick(QPointF widgetPoint);
  void showPickedFeatures(const std::vector<charts::PickedFeature>& features, charts::LatLon where);
  void addRecent(const QString& key, const QString& path);
  void rebuildRecentMenu();
  void readSettings();
  void writeSettings();
  void reportError(const QString& message);
  void selectTrack(std::optional<int> id);

  SimulationController* controller_;
  SimHistory history_;
  EcdisView* view_;
  OwnShipPanel* ownPanel_ = nullptr;
  SensorPanel* sensors_ = nullptr;
  TargetTableModel* model_ = nullptr;
  QSortFilterProxyModel* proxy_ = nullptr;
  QTableView* table_ = nullptr;
  ErrorPlots* ownPlots_ = nullptr;
  ErrorPlots* targetPlots_ = nullptr;
  QTextBrowser* pick_ = nullptr;
  AlertPanel* alertPanel_ = nullptr;
  AlertSound* sound_ = nullptr;
  MessageBar* messageBar_ = nullptr;
  ChartListPanel* chartList_ = nullptr;
  QLabel* clock_ = nullptr;
  QLabel* alarmBanner_ = nullptr;
  QAction* alarmBannerAction_ = nullptr;  ///< the banner's toolbar action (shows and hides it)
  QString alertLogPath_;
  QLabel* cursorLabel_ = nullptr;
  QLabel* chartLabel_ = nullptr;
  QComboBox* rateBox_ = nullptr;
  QComboBox* categoryBox_ = nullptr;     ///< display toolbar: the display category
  QDoubleSpinBox* safetyBox_ = nullptr;  ///< display toolbar: the safety contour (shallow to deep)
  QAction* runAction_ = nullptr;
  std::vector<QAction*> trackerKindActions_;  ///< Tracking > Filter for new tracks
  QAction* trialAction_ = nullptr;            ///< Tracking > Trial manoeuvre
  double trialDelayS_ = 30.0;
  QAction* autoAcquireAction_ = nullptr;  ///< Tracking > Automatic acquisition (follows the tracker)
  QAction* radarMatchAction_ = nullptr;   ///< Radar > Match (follows the scenario's own switch)
  QMenu* recentMenu_ = nullptr;
  QProgressBar* chartProgress_ = nullptr;  ///< shown while charts load
  QTimer repaintTimer_;
  QTimer plotTimer_;
  bool frameDirty_ = false;
  bool plotsDirty_ = false;
  bool firstFrame_ = true;
  bool docksSized_ = false;  ///< the dock column sized to the window (once; or restored from settings)
  std::optional<geo::LocalFrame> localFrame_;
  QString scenarioSource_;
  QString scenarioName_;
  MainWindowOptions options_;
  QString chartSource_;
  QString lastError_;
  double lastRunRate_ = 10.0;
  std::vector<GuiTiming> guiTimings_;
  WorkerThread<ChartLoadWorker> chartLoad_{QStringLiteral("chart-load")};
  bool chartsLoading_ = false;
  ChartArrival chartArrival_ = ChartArrival::Stay;  ///< of the latest load
  // Routes.
  RouteLibrary* routes_ = nullptr;
  RoutePanel* routePanel_ = nullptr;
  QAction* routeEditAction_ = nullptr;
  QAction* routeActivateAction_ = nullptr;
  VoyagePanel* voyagePanel_ = nullptr;
  PlaybackBar* playbackBar_ = nullptr;
  QAction* recordLiveAction_ = nullptr;
  QToolBar* playbackToolbar_ = nullptr;
  QAction* followRouteAction_ = nullptr;
  bool lastFollowing_ = false;
  QTimer routeCheckTimer_;  ///< the check after an edit (single shot)
  RouteCheckCache routeCheck_;
  std::vector<charts::RouteFinding> routeFindings_;
  /// The current route's turns that do not fit (rows after the findings) and their waypoints' ids.
  std::vector<geo::TurnFit> routeTurns_;
  std::vector<int> routeTurnIds_;
  // Live mode.
  conn::ConnectionHub* hub_ = nullptr;
  ConnectionIndicator* indicator_ = nullptr;
  DataMonitor* monitor_ = nullptr;
  AisTableModel* aisModel_ = nullptr;
  QSortFilterProxyModel* aisProxy_ = nullptr;
  QTableView* aisTable_ = nullptr;
  QAction* liveAction_ = nullptr;
  /// The AIS table the AIS dock shows (held, so that a new table is never taken for it by address).
  std::shared_ptr<const std::vector<track::AisTarget>> aisShown_;
  QElapsedTimer aisRefreshed_;  ///< when the AIS list was last refreshed
  /// What only the simulation uses (disabled in Live mode).
  std::vector<QWidget*> simulationControls_;
  std::vector<QAction*> simulationActions_;
};

}  // namespace reckoner::ui
