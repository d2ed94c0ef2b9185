#pragma once
// The ECDIS window: the chart with the navigation overlays in the centre; docks for own ship, sensors,
// the ARPA target table, the error plots, alarms and pick reports; a toolbar with the simulation clock,
// time control and display settings. The simulation runs in a worker thread (SimulationController);
// frames are stored in SimHistory as they arrive and a timer repaints at no more than 30 Hz.
#include <QElapsedTimer>
#include <QLabel>
#include <QMainWindow>
#include <QTimer>
#include <atomic>
#include <memory>
#include <optional>
#include <vector>

#include "ui/bridge/sim_history.h"
#include "ui/bridge/simulation_controller.h"
#include "ui/map/ecdis_view.h"

QT_BEGIN_NAMESPACE
class QActionGroup;
class QComboBox;
class QDoubleSpinBox;
class QListWidget;
class QMenu;
class QSortFilterProxyModel;
class QTableView;
class QTextBrowser;
class QToolButton;
QT_END_NAMESPACE

namespace reckoner::ui {

class ErrorPlots;
class OwnShipPanel;
class SensorPanel;
class TargetTableModel;

struct MainWindowOptions {
  std::string scenarioPath;    ///< empty: the last one (settings) or the embedded default
  std::string encPath;         ///< empty: the last one (settings) or the embedded default chart
  bool restoreSession = true;  ///< reopen the last scenario and chart named in the settings
};

class MainWindow : public QMainWindow {
  Q_OBJECT
 public:
  explicit MainWindow(const MainWindowOptions& options = {}, QWidget* parent = nullptr);
  ~MainWindow() override;

  /// Loads a scenario file ("builtin:NAME" for an embedded one); false with a message on failure.
  bool openScenario(const QString& path);
  void loadScenario(const sim::Scenario& scenario, const QString& source);
  /// Starts loading charts (file or folder, or builtin:default) in a background thread.
  void openCharts(const QString& path);
  /// Writes the scenario as edited so far (blocks the GUI only for the file write; the worker answers
  /// a queued request first, waited for with a local event loop).
  bool saveScenario(const QString& path);
  /// Simulated seconds per wall second; 0 pauses, < 0 as fast as possible.
  void setRate(double rate);

  // For tests and the benchmark.
  [[nodiscard]] EcdisView* chart() const { return view_; }
  [[nodiscard]] SimulationController* controller() const { return controller_; }
  [[nodiscard]] const SimHistory& history() const { return history_; }
  [[nodiscard]] SensorPanel* sensorPanel() const { return sensors_; }
  [[nodiscard]] OwnShipPanel* ownShipPanel() const { return ownPanel_; }
  [[nodiscard]] ErrorPlots* ownPlots() const { return ownPlots_; }
  [[nodiscard]] ErrorPlots* targetPlots() const { return targetPlots_; }
  [[nodiscard]] QTableView* targetTable() const { return table_; }
  [[nodiscard]] TargetTableModel* targetModel() const { return model_; }
  [[nodiscard]] bool chartsLoading() const { return loading_ != nullptr; }
  [[nodiscard]] QString lastError() const { return lastError_; }
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

 private:
  void buildRadarMenu();
  /// A checkable action in `menu` that switches one overlay setting.
  QAction* addOverlayToggle(QMenu* menu, const QString& name, bool OverlaySettings::*member);
  void buildActions();
  void buildDocks();
  void onFrame(const LiveFrame& frame);
  void repaintTick();
  void refreshPlots();
  void updateClock();
  void updateAlarms();
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
  QListWidget* alarmList_ = nullptr;
  QLabel* clock_ = nullptr;
  QLabel* alarmBanner_ = nullptr;
  QLabel* cursorLabel_ = nullptr;
  QLabel* chartLabel_ = nullptr;
  QComboBox* rateBox_ = nullptr;
  QAction* runAction_ = nullptr;
  std::vector<QAction*> trackerKindActions_;  ///< Tracking > Filter for new tracks
  QAction* radarMatchAction_ = nullptr;       ///< Radar > Match (follows the scenario's own switch)
  QMenu* recentMenu_ = nullptr;
  QTimer repaintTimer_;
  QTimer plotTimer_;
  bool frameDirty_ = false;
  bool plotsDirty_ = false;
  bool firstFrame_ = true;
  std::optional<geo::LocalFrame> localFrame_;
  QString scenarioSource_;
  QString chartSource_;
  QString lastError_;
  double lastRunRate_ = 10.0;
  std::vector<GuiTiming> guiTimings_;
  struct Loading;
  std::unique_ptr<Loading> loading_;
  quint64 chartLoads_ = 0;
};

}  // namespace reckoner::ui
