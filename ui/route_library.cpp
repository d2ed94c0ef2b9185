#include "ui/route_library.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSettings>
#include <QStandardPaths>
#include <QUndoCommand>
#include <QUndoStack>
#include <algorithm>
#include <stdexcept>

#include "io/input_error.h"
#include "io/route_files.h"
#include "ui/common/route_text.h"

namespace reckoner::ui {

/// One edit of a route: the route before and after it, named by the route's uid.
class RouteEditCommand : public QUndoCommand {
 public:
  RouteEditCommand(RouteLibrary* library, int uid, geo::Route before, geo::Route after, const QString& text)
      : QUndoCommand(text),
        library_(library),
        uid_(uid),
        before_(std::move(before)),
        after_(std::move(after)) {}
  void undo() override { library_->apply(uid_, before_); }
  void redo() override { library_->apply(uid_, after_); }

 private:
  RouteLibrary* library_;
  int uid_;
  geo::Route before_, after_;
};

namespace {
const QString kActiveKey = QStringLiteral("routes/active");

QString errorText(const std::exception& e) {
  return QString::fromStdString(e.what());
}
}  // namespace

QString RouteLibrary::defaultDirectory() {
  const QByteArray env = qgetenv("RECKONER_ROUTE_DIR");
  if (!env.isEmpty()) return QString::fromLocal8Bit(env);
  return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + QStringLiteral("/routes");
}

RouteLibrary::RouteLibrary(QObject* parent) : QObject(parent), undo_(new QUndoStack(this)) {}

RouteLibrary::~RouteLibrary() = default;

QStringList RouteLibrary::load(const QString& directory) {
  QStringList failures;
  directory_ = directory;
  routes_.clear();
  undo_->clear();
  current_ = active_ = -1;
  QDir dir(directory);
  if (!dir.exists() && !QDir().mkpath(directory))
    failures << tr("%1: cannot make the route directory").arg(directory);
  const QString remembered = QSettings().value(kActiveKey).toString();
  for (const QFileInfo& f : dir.entryInfoList({QStringLiteral("*.rtz")}, QDir::Files, QDir::Name)) {
    try {
      routes_.push_back(
          {io::readRouteFile(f.absoluteFilePath().toStdString()), f.absoluteFilePath(), false, nextUid_++});
      if (f.fileName() == remembered) active_ = count() - 1;
    } catch (const std::exception& e) {
      failures << errorText(e);
    }
  }
  current_ = active_ >= 0 ? active_ : (routes_.empty() ? -1 : 0);
  emit listChanged();
  emit currentChanged(current_);
  emitActive();
  return failures;
}

QStringList RouteLibrary::names() const {
  QStringList out;
  for (const LibraryRoute& r : routes_) {
    QString n = r.route.name.empty() ? tr("(unnamed)") : QString::fromStdString(r.route.name);
    out << (r.modified ? n + QLatin1Char('*') : n);
  }
  return out;
}

const geo::Route* RouteLibrary::currentRoute() const {
  return current_ >= 0 && current_ < count() ? &routes_[static_cast<std::size_t>(current_)].route : nullptr;
}

const geo::Route* RouteLibrary::activeRoute() const {
  return active_ >= 0 && active_ < count() ? &routes_[static_cast<std::size_t>(active_)].route : nullptr;
}

void RouteLibrary::setCurrent(int index) {
  if (index < -1 || index >= count() || index == current_) return;
  current_ = index;
  emit listChanged();
  emit currentChanged(current_);
}

void RouteLibrary::setActive(int index) {
  if (index < -1 || index >= count()) return;
  active_ = index;
  const QString path = index >= 0 ? routes_[static_cast<std::size_t>(index)].path : QString();
  QSettings().setValue(kActiveKey, QFileInfo(path).fileName());
  emit listChanged();
  emitActive();
}

void RouteLibrary::emitActive() {
  const geo::Route* r = activeRoute();
  emit activeRouteChanged(r ? *r : geo::Route{});
}

int RouteLibrary::indexOf(int uid) const {
  for (int i = 0; i < count(); ++i)
    if (routes_[static_cast<std::size_t>(i)].uid == uid) return i;
  return -1;
}

int RouteLibrary::newRoute() {
  QStringList taken = names();
  int n = count() + 1;
  while (taken.contains(tr("Route %1").arg(n)) || taken.contains(tr("Route %1*").arg(n))) ++n;
  geo::Route r;
  r.name = tr("Route %1").arg(n).toStdString();
  return add(r);
}

int RouteLibrary::add(const geo::Route& route) {
  routes_.push_back({route, {}, true, nextUid_++});
  current_ = count() - 1;
  emit listChanged();
  emit currentChanged(current_);
  return current_;
}

int RouteLibrary::importFile(const QString& path, QString* error) {
  geo::Route route;
  try {
    route = io::readRouteFile(path.toStdString());
  } catch (const std::exception& e) {
    if (error) *error = errorText(e);
    return -1;
  }
  if (route.name.empty()) route.name = QFileInfo(path).completeBaseName().toStdString();
  const int index = add(route);
  save(index, error);  // kept in the library (unsaved, marked, when the directory cannot be written)
  return index;
}

QString RouteLibrary::freePath(const geo::Route& route) const {
  QString stem = QString::fromStdString(route.name).trimmed();
  for (QChar& c : stem)
    if (!(c.isLetterOrNumber() || c == QLatin1Char(' ') || c == QLatin1Char('-') || c == QLatin1Char('_')))
      c = QLatin1Char('_');
  if (stem.isEmpty()) stem = QStringLiteral("route");
  const QDir dir(directory_);
  for (int n = 1;; ++n) {
    QString path = dir.absoluteFilePath(n == 1 ? stem + QStringLiteral(".rtz")
                                               : QStringLiteral("%1 (%2).rtz").arg(stem).arg(n));
    const bool held =
        std::any_of(routes_.begin(), routes_.end(), [&](const LibraryRoute& r) { return r.path == path; });
    if (!held && !QFileInfo::exists(path)) return path;
  }
}

bool RouteLibrary::save(int index, QString* error) {
  if (index < 0 || index >= count()) return false;
  LibraryRoute& r = routes_[static_cast<std::size_t>(index)];
  const QString path = r.path.isEmpty() ? freePath(r.route) : r.path;
  try {
    io::writeRouteFile(path.toStdString(), r.route);
  } catch (const std::exception& e) {
    if (error) *error = tr("%1: not saved: %2").arg(QString::fromStdString(r.route.name), errorText(e));
    return false;
  }
  r.path = path;
  r.modified = false;
  if (index == active_) QSettings().setValue(kActiveKey, QFileInfo(path).fileName());
  emit listChanged();
  return true;
}

bool RouteLibrary::exportTo(int index, const QString& path, QString* error) {
  if (index < 0 || index >= count()) return false;
  try {
    io::writeRouteFile(path.toStdString(), routes_[static_cast<std::size_t>(index)].route);
  } catch (const std::exception& e) {
    if (error) *error = tr("%1: not exported: %2").arg(path, errorText(e));
    return false;
  }
  return true;
}

bool RouteLibrary::remove(int index, QString* error) {
  if (index < 0 || index >= count()) return false;
  const LibraryRoute& r = routes_[static_cast<std::size_t>(index)];
  if (!r.path.isEmpty() && QFileInfo::exists(r.path) && !QFile::remove(r.path)) {
    if (error) *error = tr("%1: cannot delete the file").arg(r.path);
    return false;
  }
  const bool wasActive = index == active_;
  routes_.erase(routes_.begin() + index);
  undo_->clear();  // its edits name a route that is gone
  if (wasActive) {
    active_ = -1;
    QSettings().remove(kActiveKey);
  } else if (active_ > index) {
    --active_;
  }
  current_ = std::min(index, count() - 1);
  emit listChanged();
  emit currentChanged(current_);
  if (wasActive) emitActive();
  return true;
}

bool RouteLibrary::edit(const geo::Route& after, const QString& what, QString* error) {
  const geo::Route* before = currentRoute();
  if (!before) {
    if (error) *error = tr("%1: no route selected (Route ▸ New route)").arg(what);
    return false;
  }
  if (const QStringList problems = routeEditProblems(after); !problems.isEmpty()) {
    if (error) *error = tr("%1 refused: %2").arg(what, problems.front());
    return false;
  }
  if (after == *before) return true;
  undo_->push(
      new RouteEditCommand(this, routes_[static_cast<std::size_t>(current_)].uid, *before, after, what));
  return true;
}

void RouteLibrary::apply(int uid, const geo::Route& route) {
  const int index = indexOf(uid);
  if (index < 0) return;
  LibraryRoute& r = routes_[static_cast<std::size_t>(index)];
  r.route = route;
  r.modified = true;
  const bool moved = current_ != index;
  current_ = index;
  emit listChanged();
  if (moved) emit currentChanged(current_);
  emit routeChanged(index);
  if (index == active_) emitActive();
}

}  // namespace reckoner::ui
