#pragma once
// The window's one thread idiom: a named worker type (a QObject) living in its own QThread. The GUI
// thread sends it requests as queued calls of its member functions, named by pointer and checked by
// the compiler (post()), never by a string; the worker answers with its own signals, which the GUI
// side connects by function pointer. Calls run in the worker's thread one at a time, in the order they
// were posted. The worker is created with the thread and deleted in it when the thread stops (the
// destructor quits the thread and waits for it: a long job must have been cancelled first, see
// LatestRequest).
#include <QMetaObject>
#include <QObject>
#include <QString>
#include <QThread>
#include <type_traits>
#include <utility>

namespace reckoner::ui {

template <class Worker>
class WorkerThread {
 public:
  explicit WorkerThread(const QString& name) : worker_(new Worker) {
    worker_->moveToThread(&thread_);
    QObject::connect(&thread_, &QThread::finished, worker_, &QObject::deleteLater);
    thread_.setObjectName(name);
    thread_.start();
  }
  ~WorkerThread() {
    thread_.quit();
    thread_.wait();
  }
  WorkerThread(const WorkerThread&) = delete;
  WorkerThread& operator=(const WorkerThread&) = delete;

  /// The worker, for connecting its signals and for its thread-safe parts (its LatestRequest).
  [[nodiscard]] Worker* worker() const { return worker_; }

  /// Queues (worker->*call)(args...) in the worker's thread; the arguments are copied (or moved) into
  /// the call, so nothing is shared with the caller.
  template <class... Params, class... Args>
  void post(void (Worker::*call)(Params...), Args&&... args) {
    static_assert(sizeof...(Params) == sizeof...(Args), "post(): one argument per parameter");
    QMetaObject::invokeMethod(
        worker_,
        [w = worker_, call, ... a = std::decay_t<Params>(std::forward<Args>(args))]() mutable {
          (w->*call)(std::move(a)...);
        },
        Qt::QueuedConnection);
  }

 private:
  QThread thread_;
  Worker* worker_;  // lives in thread_
};

}  // namespace reckoner::ui
