#include "sources.h"

#include <QFile>
#include <QHostAddress>
#include <QNetworkDatagram>
#include <QNetworkInterface>
#include <QNetworkProxy>
#include <QSerialPort>
#include <QTcpSocket>
#include <QTimer>
#include <QUdpSocket>

#include <algorithm>
#include <cmath>

#include "io/nmea.h"

namespace reckoner::conn::detail {

namespace {

constexpr qint64 kReadChunk = qint64{64} * 1024;
/// Qt's own buffer of a TCP socket: beyond it the kernel's window holds the peer back.
constexpr qint64 kSocketBuffer = qint64{1024} * 1024;

QString qs(const std::string& s) {
  return QString::fromStdString(s);
}

/// The UTC time of day a sentence carries (seconds), for the sentences that carry one.
std::optional<double> sentenceTimeS(const std::string& line) {
  std::string talker, type;
  if (!sentenceId(line, talker, type)) return std::nullopt;
  int field = 0;
  if (type == "RMC" || type == "GGA" || type == "GNS" || type == "ZDA" || type == "GST" || type == "GBS")
    field = 1;
  else if (type == "GLL")
    field = 5;
  else
    return std::nullopt;
  std::size_t pos = line.find(',');
  for (int i = 1; i < field && pos != std::string::npos; ++i) pos = line.find(',', pos + 1);
  if (pos == std::string::npos) return std::nullopt;
  const std::size_t end = line.find_first_of(",*", pos + 1);
  const std::string f = line.substr(pos + 1, (end == std::string::npos ? line.size() : end) - pos - 1);
  return reckoner::io::nmea::parseTimeOfDay(f);
}

}  // namespace

Source::Source(std::shared_ptr<Slot> slot, HubCore& core, const HubOptions& options)
    : slot_(std::move(slot)),
      core_(core),
      options_(options),
      framer_(options.maxLineLength),
      retry_(new QTimer(this)),
      backoffMs_(std::max(options.retryInitialMs, 1)) {
  retry_->setSingleShot(true);
  connect(retry_, &QTimer::timeout, this, [this] {
    core_.setState(*slot_, State::Connecting);
    open();
  });
}

Source::~Source() {
  framer_.reset();
  publishCounters();
}

void Source::start() {
  core_.setState(*slot_, State::Connecting);
  open();
}

void Source::publish(std::vector<std::string>& lines) {
  if (fresh_ && !lines.empty()) {
    fresh_ = false;
    backoffMs_ = std::max(options_.retryInitialMs, 1);
  }
  core_.deliver(*slot_, slot_, lines, nowUtc(), framer_.counters());
  lines.clear();
}

void Source::publishCounters() {
  std::vector<std::string> none;
  core_.deliver(*slot_, slot_, none, nowUtc(), framer_.counters());
}

void Source::received(const QByteArray& bytes) {
  framer_.feed(std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())), lines_);
  publish(lines_);
}

void Source::receivedDatagram(const QByteArray& bytes) {
  framer_.feed(std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())), lines_);
  framer_.endOfRecord(lines_);
  publish(lines_);
}

void Source::connected() {
  fresh_ = true;
  core_.noteConnected(*slot_);
}

void Source::failed(const QString& why, State state) {
  if (retry_->isActive()) return;  // one failure reported twice (error, then disconnect)
  framer_.reset();
  publishCounters();
  core_.setState(*slot_, state, why.toStdString());
  retry_->start(backoffMs_);
  backoffMs_ = std::min(backoffMs_ * 2, std::max(options_.retryMaxMs, 1));
}

// ---------------------------------------------------------------------------------------------- UDP

void UdpSource::open() {
  const SourceConfig& c = slot_->config;
  if (!socket_) {
    socket_ = new QUdpSocket(this);
    socket_->setProxy(QNetworkProxy::NoProxy);
    connect(socket_, &QUdpSocket::readyRead, this, [this] {
      while (socket_->hasPendingDatagrams()) receivedDatagram(socket_->receiveDatagram().data());
    });
  }
  socket_->close();
  QHostAddress bindAddress = c.host.empty() ? QHostAddress(QHostAddress::AnyIPv4) : QHostAddress(qs(c.host));
  if (!c.host.empty() && bindAddress.isNull()) {
    failed(QString("udp %1: address '%2' is not an IP address").arg(qs(c.name), qs(c.host)), State::Error);
    return;
  }
  if (c.multicast)
    bindAddress = bindAddress.protocol() == QAbstractSocket::IPv6Protocol
                      ? QHostAddress(QHostAddress::AnyIPv6)
                      : QHostAddress(QHostAddress::AnyIPv4);
  if (!socket_->bind(bindAddress, c.port, QUdpSocket::ShareAddress | QUdpSocket::ReuseAddressHint)) {
    failed(QString("udp %1: cannot bind port %2: %3").arg(qs(c.name)).arg(c.port).arg(socket_->errorString()),
           State::Error);
    return;
  }
  // A 10,000 sentence/s feed is about 8 MB/s of kernel buffer accounting on loopback; the default
  // 208 kB holds some 25 ms of it, so a reader held up for longer loses datagrams the kernel counts
  // nowhere we can see. 4 MB (Linux caps it at net.core.rmem_max) rides out half a second.
  socket_->setSocketOption(QAbstractSocket::ReceiveBufferSizeSocketOption, 4 * 1024 * 1024);
  if (c.multicast) {
    const QHostAddress group(qs(c.host));
    bool joined = false;
    if (c.interfaceName.empty()) {
      joined = socket_->joinMulticastGroup(group);
    } else {
      const QNetworkInterface iface = QNetworkInterface::interfaceFromName(qs(c.interfaceName));
      joined = iface.isValid() && socket_->joinMulticastGroup(group, iface);
    }
    if (!joined) {
      const QString why =
          QString("udp %1: cannot join multicast group %2%3: %4")
              .arg(qs(c.name), qs(c.host), c.interfaceName.empty() ? QString() : " on " + qs(c.interfaceName),
                   socket_->errorString());
      socket_->close();
      failed(why, State::Error);
      return;
    }
  }
  connected();
}

// ---------------------------------------------------------------------------------------------- TCP

TcpSource::TcpSource(std::shared_ptr<Slot> slot, HubCore& core, const HubOptions& options)
    : Source(std::move(slot), core, options), socket_(new QTcpSocket(this)), connectTimer_(new QTimer(this)) {
  socket_->setReadBufferSize(kSocketBuffer);
  // Instruments on the bridge LAN are reached directly: no system proxy lookup (libproxy may go to
  // the network for WPAD) and no HTTP proxy between us and a multiplexer.
  socket_->setProxy(QNetworkProxy::NoProxy);
  connectTimer_->setSingleShot(true);
  const bool gpsd = slot_->config.kind == Kind::Gpsd;
  connect(connectTimer_, &QTimer::timeout, this, [this] {
    socket_->abort();
    failed(QString("%1: no connection to %2:%3 within %4 ms")
               .arg(qs(slot_->config.name), qs(slot_->config.host))
               .arg(slot_->config.port)
               .arg(options_.connectTimeoutMs));
  });
  connect(socket_, &QTcpSocket::connected, this, [this, gpsd] {
    connectTimer_->stop();
    socket_->setSocketOption(QAbstractSocket::KeepAliveOption, 1);
    // gpsd relays the NMEA sentences of its devices as they come (raw mode 1 for NMEA devices).
    if (gpsd) socket_->write("?WATCH={\"enable\":true,\"nmea\":true,\"raw\":1}\n");
    connected();
  });
  connect(socket_, &QTcpSocket::readyRead, this, &TcpSource::readAll);
  const auto lost = [this] {
    connectTimer_->stop();
    readAll();
    const QString why =
        QString("%1: %2:%3: %4")
            .arg(qs(slot_->config.name), qs(slot_->config.host))
            .arg(slot_->config.port)
            .arg(socket_->error() == QAbstractSocket::UnknownSocketError ? QString("connection closed")
                                                                         : socket_->errorString());
    socket_->abort();
    failed(why);
  };
  connect(socket_, &QTcpSocket::errorOccurred, this, lost);
  connect(socket_, &QTcpSocket::disconnected, this, lost);
}

void TcpSource::readAll() {
  while (socket_->bytesAvailable() > 0) received(socket_->read(kReadChunk));
}

void TcpSource::open() {
  socket_->abort();
  connectTimer_->start(options_.connectTimeoutMs);
  socket_->connectToHost(qs(slot_->config.host), slot_->config.port);
}

// ------------------------------------------------------------------------------------------- serial

void SerialSource::open() {
  const SourceConfig& c = slot_->config;
  if (!port_) {
    port_ = new QSerialPort(this);
    port_->setReadBufferSize(kSocketBuffer);
    connect(port_, &QSerialPort::readyRead, this, [this] {
      while (port_->bytesAvailable() > 0) received(port_->read(kReadChunk));
    });
    connect(port_, &QSerialPort::errorOccurred, this, [this](QSerialPort::SerialPortError e) {
      if (e == QSerialPort::NoError || e == QSerialPort::TimeoutError || !port_->isOpen()) return;
      const QString why = QString("serial %1: %2: %3")
                              .arg(qs(slot_->config.name), qs(slot_->config.device), port_->errorString());
      port_->close();
      failed(why);
    });
  }
  port_->close();
  port_->setPortName(qs(c.device));
  if (!port_->open(QIODevice::ReadOnly)) {
    failed(QString("serial %1: cannot open %2: %3").arg(qs(c.name), qs(c.device), port_->errorString()));
    return;
  }
  if (!port_->setBaudRate(c.baud) || !port_->setDataBits(QSerialPort::Data8) ||
      !port_->setParity(QSerialPort::NoParity) || !port_->setStopBits(QSerialPort::OneStop) ||
      !port_->setFlowControl(QSerialPort::NoFlowControl)) {
    const QString why = QString("serial %1: %2: cannot set %3 baud 8N1: %4")
                            .arg(qs(c.name), qs(c.device))
                            .arg(c.baud)
                            .arg(port_->errorString());
    port_->close();
    failed(why, State::Error);
    return;
  }
  connected();
}

// --------------------------------------------------------------------------------------------- file

FileSource::FileSource(std::shared_ptr<Slot> slot, HubCore& core, const HubOptions& options)
    : Source(std::move(slot), core, options), pace_(new QTimer(this)) {
  pace_->setSingleShot(true);
  connect(pace_, &QTimer::timeout, this, &FileSource::pump);
}

void FileSource::open() {
  delete file_;
  file_ = new QFile(qs(slot_->config.path), this);
  if (!file_->open(QIODevice::ReadOnly)) {
    failed(QString("file %1: cannot open %2: %3")
               .arg(qs(slot_->config.name), qs(slot_->config.path), file_->errorString()));
    return;
  }
  pending_.clear();
  t0S_.reset();
  sent_ = 0;
  eof_ = false;
  connected();
  clock_.start();
  pump();
}

bool FileSource::refill() {
  if (eof_) return false;
  const QByteArray chunk = file_->read(kReadChunk);
  if (chunk.isEmpty()) {
    eof_ = true;
    return false;
  }
  std::vector<std::string> lines;
  framer_.feed(std::string_view(chunk.constData(), static_cast<std::size_t>(chunk.size())), lines);
  for (std::string& l : lines) pending_.push_back(std::move(l));
  return true;
}

void FileSource::pump() {
  const FileRate& rate = slot_->config.rate;
  constexpr int kBatch = 1000;  // then the I/O thread serves the other sources
  std::vector<std::string> out;
  for (int n = 0; n < kBatch;) {
    if (pending_.empty()) {
      if (refill()) continue;
      publish(out);
      framer_.reset();
      publishCounters();
      core_.setState(*slot_, State::Finished);
      return;
    }
    std::optional<double> dueS;
    if (!rate.ownTime) {
      dueS = static_cast<double>(sent_) / rate.linesPerSecond;
    } else if (const auto t = sentenceTimeS(pending_.front())) {
      double s = *t + dayOffsetS_;
      if (t0S_ && s < lastS_ - 43'200.0) {  // past midnight
        dayOffsetS_ += 86'400.0;
        s += 86'400.0;
      }
      if (!t0S_) t0S_ = s;
      lastS_ = std::max(lastS_, s);
      dueS = (s - *t0S_) / rate.speedFactor;
    }
    const double nowS = static_cast<double>(clock_.nsecsElapsed()) * 1e-9;
    if (dueS && *dueS > nowS + 0.0005) {
      publish(out);
      // This line waits for its time and is looked at again then (lastS_ already holds it, so its
      // day is not counted twice).
      pace_->start(static_cast<int>(std::ceil((*dueS - nowS) * 1000.0)));
      return;
    }
    out.push_back(std::move(pending_.front()));
    pending_.pop_front();
    ++sent_;
    ++n;
  }
  publish(out);
  pace_->start(0);
}

}  // namespace reckoner::conn::detail
