#pragma once
// One class per source kind (internal; docs/connections.md). Each lives in the hub's I/O thread from
// construction to deletion, frames its bytes with an io::LineFramer and hands the lines to the hub's
// core; on a failure it counts the half line, waits (1 s doubling to 30 s by default) and tries again.
#include <QByteArray>
#include <QElapsedTimer>
#include <QObject>
#include <QString>

#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "hub_core.h"
#include "io/line_framer.h"

class QTimer;
class QUdpSocket;
class QTcpSocket;
class QSerialPort;
class QFile;

namespace reckoner::conn::detail {

class Source : public QObject {
 public:
  Source(std::shared_ptr<Slot> slot, HubCore& core, const HubOptions& options);
  /// Stopping counts the half line buffered, as a disconnect does.
  ~Source() override;
  Source(const Source&) = delete;
  Source& operator=(const Source&) = delete;
  /// Opens (binds, connects); failures are retried with back-off.
  virtual void start();

 protected:
  virtual void open() = 0;
  /// Bytes of a stream; lines completed by them go to the hub.
  void received(const QByteArray& bytes);
  /// One datagram: its last line ends with it.
  void receivedDatagram(const QByteArray& bytes);
  void connected();
  /// The stream ended or failed: the half line is counted, a retry scheduled.
  void failed(const QString& why, State state = State::WaitingRetry);
  void publish(std::vector<std::string>& lines);
  void publishCounters();

  std::shared_ptr<Slot> slot_;
  HubCore& core_;
  HubOptions options_;
  reckoner::io::LineFramer framer_;
  std::vector<std::string> lines_;

 private:
  QTimer* retry_ = nullptr;
  int backoffMs_ = 0;
  bool fresh_ = false;  ///< connected and no line yet: the back-off is reset by the first line
};

class UdpSource final : public Source {
 public:
  using Source::Source;

 private:
  void open() override;
  QUdpSocket* socket_ = nullptr;
};

/// TCP client; with gpsd, asks gpsd for its NMEA relay (?WATCH) and skips its JSON.
class TcpSource final : public Source {
 public:
  TcpSource(std::shared_ptr<Slot> slot, HubCore& core, const HubOptions& options);

 private:
  void open() override;
  void readAll();
  QTcpSocket* socket_ = nullptr;
  QTimer* connectTimer_ = nullptr;
};

class SerialSource final : public Source {
 public:
  using Source::Source;

 private:
  void open() override;
  QSerialPort* port_ = nullptr;
};

/// A recording played at its own UTC pace (times N) or at a fixed line rate.
class FileSource final : public Source {
 public:
  FileSource(std::shared_ptr<Slot> slot, HubCore& core, const HubOptions& options);

 private:
  void open() override;
  void pump();
  bool refill();
  QFile* file_ = nullptr;
  QTimer* pace_ = nullptr;
  std::deque<std::string> pending_;
  QElapsedTimer clock_;
  std::optional<double> t0S_;  ///< the first sentence time (seconds of the day, unwrapped)
  double lastS_ = 0.0, dayOffsetS_ = 0.0;
  std::uint64_t sent_ = 0;
  bool eof_ = false;
};

}  // namespace reckoner::conn::detail
