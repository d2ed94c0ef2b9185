#include "connection_hub.h"

#include <QMetaObject>
#include <QThread>

#include <algorithm>
#include <stdexcept>

#include "hub_core.h"
#include "sources.h"

namespace reckoner::conn {

const char* stateName(State s) {
  switch (s) {
    case State::Stopped:
      return "stopped";
    case State::Connecting:
      return "connecting";
    case State::Connected:
      return "connected";
    case State::WaitingRetry:
      return "waiting-retry";
    case State::Error:
      return "error";
    case State::Finished:
      return "finished";
    case State::Disabled:
      return "disabled";
  }
  return "?";
}

const char* verdictName(Verdict v) {
  switch (v) {
    case Verdict::Delivered:
      return "delivered";
    case Verdict::Filtered:
      return "filtered";
    case Verdict::BadChecksum:
      return "bad checksum";
    case Verdict::GpsdJson:
      return "gpsd json";
  }
  return "?";
}

ConnectionHub::ConnectionHub(QObject* parent) : ConnectionHub(HubOptions{}, parent) {}

ConnectionHub::ConnectionHub(HubOptions options, QObject* parent)
    : QObject(parent), options_(options), core_(std::make_unique<detail::HubCore>(options)) {
  core_->notifyLines = [this] { emit linesAvailable(); };
  core_->notifyState = [this](const std::string& name) { emit stateChanged(QString::fromStdString(name)); };
}

ConnectionHub::~ConnectionHub() {
  stop();
}

void ConnectionHub::add(SourceConfig config) {
  if (config.name.empty()) throw std::invalid_argument("connection: name: empty");
  for (const auto& s : slots_)
    if (s->config.name == config.name)
      throw std::invalid_argument("connection '" + config.name + "': name: already taken");
  auto slot = std::make_shared<detail::Slot>();
  slot->status.name = config.name;
  slot->status.kind = config.kind;
  slot->status.role = config.role;
  slot->status.state = config.enabled ? State::Stopped : State::Disabled;
  slot->config = std::move(config);
  slots_.push_back(slot);
  if (running_ && slot->config.enabled) startSource(slot);
}

bool ConnectionHub::remove(const std::string& name) {
  const auto it =
      std::find_if(slots_.begin(), slots_.end(), [&](const auto& s) { return s->config.name == name; });
  if (it == slots_.end()) return false;
  stopSource(*it);
  slots_.erase(it);
  return true;
}

bool ConnectionHub::setEnabled(const std::string& name, bool enabled) {
  const auto it =
      std::find_if(slots_.begin(), slots_.end(), [&](const auto& s) { return s->config.name == name; });
  if (it == slots_.end()) return false;
  const auto& slot = *it;
  if (slot->config.enabled == enabled) return true;
  slot->config.enabled = enabled;  // the source is stopped here: nothing in the I/O thread reads it
  if (!enabled) {
    stopSource(slot);
    core_->setState(*slot, State::Disabled);
  } else {
    core_->setState(*slot, State::Stopped);
    if (running_) startSource(slot);
  }
  return true;
}

void ConnectionHub::start() {
  if (running_) return;
  thread_ = new QThread;
  thread_->setObjectName("reckoner-connections");
  io_ = new QObject;
  io_->moveToThread(thread_);
  thread_->start();
  running_ = true;
  for (const auto& slot : slots_)
    if (slot->config.enabled) startSource(slot);
}

void ConnectionHub::startSource(const std::shared_ptr<detail::Slot>& slot) {
  if (slot->source) return;
  // The config is read only by the I/O thread while the source runs; it is copied in the source's slot.
  QMetaObject::invokeMethod(
      io_,
      [this, slot] {
        detail::Source* s = nullptr;
        switch (slot->config.kind) {
          case Kind::Udp:
            s = new detail::UdpSource(slot, *core_, options_);
            break;
          case Kind::Tcp:
          case Kind::Gpsd:
            s = new detail::TcpSource(slot, *core_, options_);
            break;
          case Kind::Serial:
            s = new detail::SerialSource(slot, *core_, options_);
            break;
          case Kind::File:
            s = new detail::FileSource(slot, *core_, options_);
            break;
        }
        slot->source = s;
        s->start();
      },
      Qt::BlockingQueuedConnection);
}

void ConnectionHub::stopSource(const std::shared_ptr<detail::Slot>& slot) {
  if (!slot->source || !running_) return;
  QMetaObject::invokeMethod(
      io_,
      [this, slot] {
        delete slot->source;  // closes its socket, port or file in the thread that owns it
        slot->source = nullptr;
        core_->setState(*slot, slot->config.enabled ? State::Stopped : State::Disabled);
      },
      Qt::BlockingQueuedConnection);
}

void ConnectionHub::stop() {
  if (!running_) return;
  for (const auto& slot : slots_) stopSource(slot);
  thread_->quit();
  thread_->wait();
  delete io_;
  delete thread_;
  io_ = nullptr;
  thread_ = nullptr;
  running_ = false;
}

bool ConnectionHub::running() const {
  return running_;
}

std::vector<ReceivedLine> ConnectionHub::take(std::size_t max) {
  return core_->take(max);
}

std::vector<SourceStatus> ConnectionHub::status() const {
  std::vector<SourceStatus> out;
  out.reserve(slots_.size());
  for (const auto& slot : slots_) out.push_back(core_->status(*slot));
  return out;
}

std::vector<SourceConfig> ConnectionHub::sources() const {
  std::vector<SourceConfig> out;
  for (const auto& slot : slots_) out.push_back(slot->config);
  return out;
}

HubCounters ConnectionHub::counters() const {
  return core_->counters();
}

std::vector<MonitorLine> ConnectionHub::monitor(const MonitorFilter& filter, std::size_t max) const {
  return core_->monitor(filter, max);
}

}  // namespace reckoner::conn
