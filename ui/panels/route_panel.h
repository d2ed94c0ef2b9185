#pragma once
// The Route dock (docs/gui.md "Routes"): the route library (a list of the routes with New, Import,
// Save, Export, Delete and Activate), the selected route's name and its table (RouteTableModel, cells
// edited in place), its total distance and time at the planned speeds, and the route check's findings
// (leg, kind, class, depth, position). The panel holds no route of its own: the window gives it what to
// show and applies what it asks for (through its RouteLibrary, ui/route_library.h).
#include <QWidget>
#include <vector>

#include "geo/route.h"
#include "ui/common/display_units.h"

QT_BEGIN_NAMESPACE
class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QTableView;
class QTableWidget;
QT_END_NAMESPACE

namespace reckoner::ui {

class RouteTableModel;

/// One row of the findings list, as the window describes a route check's finding.
struct RouteFindingRow {
  int leg = 0;        ///< the leg arriving at waypoint index `leg`
  QString legName;    ///< "WP1 – WP2"
  QString kind;       ///< "land", "safety contour", ...
  QString className;  ///< "Land area (LNDARE)"
  QString depth;      ///< "4.2" or "–"
  QString position;   ///< as the window writes positions
  bool dangerous = true;
  bool turn = false;  ///< a turn that does not fit at waypoint `leg`: legName says where ("at WP3")
};

class RoutePanel : public QWidget {
  Q_OBJECT
 public:
  explicit RoutePanel(QWidget* parent = nullptr);

  /// The library's routes (names, "*" when edited and not saved), the one shown and the active one
  /// (-1: none).
  void setLibrary(const QStringList& names, int current, int active);
  /// The route shown (nullptr: none).
  void setRoute(const geo::Route* route);
  void setUnits(const DisplayUnits& units);
  /// The route check's findings and a line saying what was checked.
  void setFindings(const std::vector<RouteFindingRow>& rows, const QString& summary);
  /// Selects a waypoint's row (from the chart), or none.
  void selectWaypoint(int index);
  /// Starts typing a waypoint's name in its row (the chart's Rename).
  void editWaypointName(int index);

  // For the window and the tests.
  [[nodiscard]] RouteTableModel* model() const { return model_; }
  [[nodiscard]] QTableView* table() const { return table_; }
  [[nodiscard]] QTableWidget* findingsTable() const { return findings_; }
  [[nodiscard]] QComboBox* routeList() const { return routes_; }
  [[nodiscard]] QLabel* totals() const { return totals_; }
  [[nodiscard]] QLabel* checkSummary() const { return summary_; }
  /// "Total 3.42 NM · 0 h 21 min at the planned speeds" (what the totals line says).
  [[nodiscard]] static QString totalsText(const geo::Route& route, const DisplayUnits& units);

 signals:
  void routeChosen(int index);
  void newRequested();
  void importRequested();
  void saveRequested();
  void exportRequested();
  void deleteRequested();
  /// Activate the route shown (true) or deactivate it (false).
  void activateRequested(bool on);
  void renameRouteRequested(const QString& name);
  void checkRequested();
  void waypointSelected(int index);
  void findingSelected(int index);
  /// A cell edited in the table (RouteTableModel::editRequested) or refused (refused).
  void editRequested(const reckoner::geo::Route& after, const QString& what);
  void refused(const QString& message);

 private:
  QWidget* buildLibraryRow();
  QPushButton* button(const QString& text, const QString& name, const QString& tip);

  QComboBox* routes_ = nullptr;
  QLineEdit* name_ = nullptr;
  QPushButton* activate_ = nullptr;
  std::vector<QPushButton*> routeButtons_;  ///< enabled only with a route shown
  RouteTableModel* model_ = nullptr;
  QTableView* table_ = nullptr;
  QLabel* totals_ = nullptr;
  QLabel* summary_ = nullptr;
  QTableWidget* findings_ = nullptr;
  DisplayUnits units_;
  bool shownActive_ = false;
  bool hasRoute_ = false;
};

}  // namespace reckoner::ui
