#include "ui/bridge/chart_load_worker.h"

#include <exception>

namespace reckoner::ui {

ChartLoadWorker::ChartLoadWorker() {
  qRegisterMetaType<reckoner::ui::ChartLoadAnswer>();
}

void ChartLoadWorker::load(const QString& path, quint64 generation) {
  if (!requests_.begin(generation)) return;  // a newer load is already queued
  ChartLoadAnswer answer;
  answer.generation = generation;
  answer.path = path;
  try {
    answer.result = charts::loadCharts(
        {path.toStdString()},
        [this, generation](std::size_t done, std::size_t total, const std::string&) {
          emit progress(generation, static_cast<int>(done), static_cast<int>(total));
        },
        requests_.cancelFlag());
  } catch (const std::exception& e) {
    answer.problem = QString::fromStdString(e.what());
  }
  emit loaded(answer);
}

}  // namespace reckoner::ui
