#include "nmea_destination.h"

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QFile>
#include <QHostInfo>
#include <QTcpServer>
#include <QTcpSocket>
#include <QUdpSocket>

#include <stdexcept>

namespace reckoner::conn {
namespace {

constexpr qsizetype kMaxDatagramBytes = 1472;  // one Ethernet frame of UDP payload

quint16 portOf(const std::string& spec, const std::string& text) {
  bool ok = false;
  const uint p = QString::fromStdString(text).toUInt(&ok);
  if (!ok || p > 65535)
    throw std::invalid_argument("--nmea-out " + spec + ": port must be 0-65535, got \"" + text + "\"");
  return static_cast<quint16>(p);
}

/// HOST:PORT (HOST may be empty, or [IPv6]).
std::pair<std::string, quint16> hostPort(const std::string& spec, const std::string& rest) {
  const std::size_t colon = rest.rfind(':');
  if (colon == std::string::npos)
    throw std::invalid_argument("--nmea-out " + spec + ": expected HOST:PORT after the scheme");
  std::string host = rest.substr(0, colon);
  if (host.size() >= 2 && host.front() == '[' && host.back() == ']') host = host.substr(1, host.size() - 2);
  return {host, portOf(spec, rest.substr(colon + 1))};
}

}  // namespace

DestinationSpec parseDestination(const std::string& spec) {
  DestinationSpec d;
  if (spec.empty()) throw std::invalid_argument("--nmea-out: empty destination");
  if (spec.rfind("udp://", 0) == 0) {
    const auto [host, port] = hostPort(spec, spec.substr(6));
    if (host.empty())
      throw std::invalid_argument("--nmea-out " + spec + ": UDP needs a host (udp://HOST:PORT)");
    if (port == 0) throw std::invalid_argument("--nmea-out " + spec + ": UDP needs a port other than 0");
    d.kind = DestinationSpec::Kind::Udp;
    d.host = QString::fromStdString(host);
    d.port = port;
  } else if (spec.rfind("tcp://", 0) == 0) {
    const auto [host, port] = hostPort(spec, spec.substr(6));
    d.kind = DestinationSpec::Kind::TcpServer;
    d.host = QString::fromStdString(host);
    d.port = port;
  } else if (spec.find("://") != std::string::npos) {
    throw std::invalid_argument("--nmea-out " + spec +
                                ": unknown scheme (udp://HOST:PORT, tcp://:PORT or a file path)");
  } else {
    d.kind = DestinationSpec::Kind::File;
    d.path = QString::fromStdString(spec);
  }
  return d;
}

NmeaDestination::NmeaDestination(const DestinationSpec& spec, QObject* parent, qint64 maxClientBufferBytes)
    : QObject(parent), spec_(spec), maxClientBufferBytes_(maxClientBufferBytes) {
  switch (spec.kind) {
    case DestinationSpec::Kind::Udp: {
      udpPeer_ = QHostAddress(spec.host);
      if (udpPeer_.isNull()) {
        const QHostInfo info = QHostInfo::fromName(spec.host);
        for (const QHostAddress& a : info.addresses())
          if (a.protocol() == QAbstractSocket::IPv4Protocol) {
            udpPeer_ = a;
            break;
          }
        if (udpPeer_.isNull() && !info.addresses().isEmpty()) udpPeer_ = info.addresses().first();
      }
      if (udpPeer_.isNull())
        throw std::runtime_error("--nmea-out udp://" + spec.host.toStdString() + ":" +
                                 std::to_string(spec.port) + ": cannot resolve the host");
      udp_ = std::make_unique<QUdpSocket>();
      break;
    }
    case DestinationSpec::Kind::TcpServer: {
      server_ = new QTcpServer(this);
      const QHostAddress at = spec.host.isEmpty() ? QHostAddress(QHostAddress::Any) : QHostAddress(spec.host);
      if (at.isNull() || !server_->listen(at, spec.port))
        throw std::runtime_error("--nmea-out tcp://" + spec.host.toStdString() + ":" +
                                 std::to_string(spec.port) +
                                 ": cannot listen: " + server_->errorString().toStdString());
      connect(server_, &QTcpServer::newConnection, this, &NmeaDestination::accept);
      break;
    }
    case DestinationSpec::Kind::File: {
      file_ = std::make_unique<QFile>(spec.path);
      if (!file_->open(QIODevice::WriteOnly | QIODevice::Truncate))
        throw std::runtime_error("--nmea-out " + spec.path.toStdString() +
                                 ": cannot write: " + file_->errorString().toStdString());
      break;
    }
  }
}

NmeaDestination::~NmeaDestination() {
  if (file_) file_->flush();
  for (QTcpSocket* c : clients_) c->disconnectFromHost();
}

quint16 NmeaDestination::port() const {
  return server_ ? server_->serverPort() : spec_.port;
}

void NmeaDestination::accept() {
  while (QTcpSocket* c = server_->nextPendingConnection()) {
    ++counters_.clientsAccepted;
    clients_.push_back(c);
    connect(c, &QTcpSocket::disconnected, this, [this, c] {
      std::erase(clients_, c);
      c->deleteLater();
    });
    c->readAll();  // what a client sends is not read: this is an output
    connect(c, &QTcpSocket::readyRead, c, [c] { c->readAll(); });
    emit clientConnected();
  }
}

void NmeaDestination::sendDatagram(const QByteArray& bytes) {
  if (bytes.isEmpty()) return;
  ++counters_.datagrams;
  if (udp_->writeDatagram(bytes, udpPeer_, spec_.port) != bytes.size()) ++counters_.sendErrors;
}

void NmeaDestination::write(const std::vector<std::string>& lines) {
  if (lines.empty()) return;
  counters_.lines += static_cast<long>(lines.size());
  QByteArray all;
  for (const auto& l : lines) {
    const QByteArray one = QByteArray::fromStdString(l) + "\r\n";
    if (udp_ && !all.isEmpty() && all.size() + one.size() > kMaxDatagramBytes) {
      sendDatagram(all);
      all.clear();
    }
    all += one;
  }
  if (udp_) {
    sendDatagram(all);
  } else if (file_) {
    file_->write(all);
  } else {
    if (clients_.empty()) counters_.linesWithoutClient += static_cast<long>(lines.size());
    for (QTcpSocket* c : std::vector<QTcpSocket*>(clients_)) {
      if (c->bytesToWrite() + all.size() > maxClientBufferBytes_) {
        // It stopped reading: drop it rather than hold an unbounded queue.
        ++counters_.clientsDropped;
        std::erase(clients_, c);
        c->disconnect(this);
        c->abort();
        c->deleteLater();
        continue;
      }
      c->write(all);
    }
  }
}

void NmeaDestination::flush(int timeoutMs) {
  if (file_) file_->flush();
  if (!server_) return;
  const QDeadlineTimer deadline(timeoutMs);
  while (!deadline.hasExpired()) {
    bool pending = false;
    for (QTcpSocket* c : clients_)
      if (c->bytesToWrite() > 0) pending = true;
    if (!pending) break;
    for (QTcpSocket* c : std::vector<QTcpSocket*>(clients_)) c->waitForBytesWritten(10);
  }
}

}  // namespace reckoner::conn
