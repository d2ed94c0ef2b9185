#pragma once
// The route library (docs/gui.md "Routes"): the routes of one directory of RTZ files
// ($RECKONER_ROUTE_DIR, else the application's data directory + "/routes"), one of them shown and
// edited ("current"), at most one active: the route the ship follows. Edits replace the current route
// as a whole through a QUndoStack (Ctrl+Z undoes the last), and are refused when they would make it
// unusable (geo::Route::problems(), but for having fewer than two waypoints while it is being built).
// Routes are written with io::writeRouteFile (RTZ 1.1); files are read with io::readRouteFile (RTZ or
// GPX), and every file that cannot be read is reported with its reason. The active route is
// remembered (QSettings "routes/active", its file name) and activated again at the next start.
//
// For whoever follows the route: activeRouteChanged(route) is emitted when a route is activated or
// deactivated (an empty route: none) and whenever the active route is edited (and undone); activeRoute()
// gives it at any time.
#include <QObject>
#include <QString>
#include <QStringList>
#include <vector>

#include "geo/route.h"

QT_BEGIN_NAMESPACE
class QUndoStack;
QT_END_NAMESPACE

namespace reckoner::ui {

struct LibraryRoute {
  geo::Route route;
  QString path;           ///< its file in the library's directory (empty until saved)
  bool modified = false;  ///< edited since read or saved
  int uid = 0;            ///< unique in this session (undo commands name the route by it)
};

class RouteLibrary : public QObject {
  Q_OBJECT
 public:
  /// $RECKONER_ROUTE_DIR when set, else QStandardPaths::AppDataLocation + "/routes".
  [[nodiscard]] static QString defaultDirectory();

  explicit RouteLibrary(QObject* parent = nullptr);
  ~RouteLibrary() override;

  /// Reads every *.rtz of `directory` (made when missing) in the order of their names, replacing the
  /// routes held; activates the remembered one. Returns one line per file not read ("file: reason").
  QStringList load(const QString& directory);
  [[nodiscard]] QString directory() const { return directory_; }

  [[nodiscard]] int count() const { return static_cast<int>(routes_.size()); }
  [[nodiscard]] const LibraryRoute& at(int index) const {
    return routes_.at(static_cast<std::size_t>(index));
  }
  /// The names as a list shows them: "*" after a route edited and not saved.
  [[nodiscard]] QStringList names() const;
  [[nodiscard]] int current() const { return current_; }
  [[nodiscard]] const geo::Route* currentRoute() const;
  void setCurrent(int index);
  [[nodiscard]] int active() const { return active_; }
  [[nodiscard]] const geo::Route* activeRoute() const;
  /// Makes route `index` the active one (-1: none), remembered for the next start.
  void setActive(int index);

  /// A new empty route ("Route 3"), made current. Returns its index.
  int newRoute();
  /// Adds a route (made current; not yet saved). Returns its index.
  int add(const geo::Route& route);
  /// Reads an RTZ or GPX file, adds its route and saves it into the library. -1 with *error (the
  /// file and the reason) when it cannot be read.
  int importFile(const QString& path, QString* error);
  /// Writes route `index` to its file in the library (named after the route when it has none yet).
  bool save(int index, QString* error);
  /// Writes route `index` as RTZ to any path (the library keeps its own file).
  bool exportTo(int index, const QString& path, QString* error);
  /// Removes route `index` and its file.
  bool remove(int index, QString* error);

  /// Replaces the current route with `after` through the undo stack; refused (false, *error) when
  /// there is no current route or `after` is not usable.
  bool edit(const geo::Route& after, const QString& what, QString* error);
  [[nodiscard]] QUndoStack* undoStack() const { return undo_; }

 signals:
  /// The names, the modified marks, the current or the active route changed.
  void listChanged();
  void currentChanged(int index);
  /// Route `index`'s content changed (an edit, an undo, a rename).
  void routeChanged(int index);
  /// The active route: activated, edited, undone; empty (no waypoints) when none is active.
  void activeRouteChanged(const reckoner::geo::Route& route);

 private:
  friend class RouteEditCommand;
  /// Puts `route` into the route with this uid, makes it current and says so (undo and redo).
  void apply(int uid, const geo::Route& route);
  [[nodiscard]] int indexOf(int uid) const;
  /// A file name in the directory for the route's name that no other route or file has.
  [[nodiscard]] QString freePath(const geo::Route& route) const;
  void emitActive();

  QString directory_;
  std::vector<LibraryRoute> routes_;
  int current_ = -1;
  int active_ = -1;
  int nextUid_ = 1;
  QUndoStack* undo_;
};

}  // namespace reckoner::ui
