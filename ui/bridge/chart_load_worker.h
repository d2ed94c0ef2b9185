#pragma once
// Loads ENC cells in a worker thread for the window (WorkerThread<ChartLoadWorker>): a request is a
// queued call of load() with a path (cell, folder or builtin:default) and its number from requests();
// progress() reports each cell done and loaded() answers with the cells and the failures. Latest
// request wins (LatestRequest): a newer request stops the load in progress between cells, an older
// queued one is skipped, and the window keeps only the answer to its latest request.
#include <QMetaType>
#include <QObject>
#include <QString>

#include "charts/s57/s57_loader.h"
#include "ui/bridge/latest_request.h"

namespace reckoner::ui {

struct ChartLoadAnswer {
  quint64 generation = 0;
  QString path;               ///< as requested
  charts::LoadResult result;  ///< the cells loaded and the files that failed
  QString problem;            ///< an error that stopped the whole load (empty if none)
};

class ChartLoadWorker : public QObject {
  Q_OBJECT
 public:
  ChartLoadWorker();
  /// Thread-safe: the GUI thread numbers each request here before posting it.
  [[nodiscard]] LatestRequest& requests() { return requests_; }

  /// In the worker's thread: loads every cell `path` names unless a newer request has been issued.
  void load(const QString& path, quint64 generation);

 signals:
  void progress(quint64 generation, int done, int total);
  void loaded(const reckoner::ui::ChartLoadAnswer& answer);

 private:
  LatestRequest requests_;
};

}  // namespace reckoner::ui

Q_DECLARE_METATYPE(reckoner::ui::ChartLoadAnswer)
