#pragma once
// Where Reckoner's NMEA 0183 output goes (docs/outputs.md, "NMEA 0183 output", "Destinations"):
//   udp://HOST:PORT  datagrams to one host, or to a broadcast address (255.255.255.255, x.y.z.255)
//   tcp://:PORT      a TCP server on every interface (tcp://HOST:PORT: on that address) serving every
//                    client that connects; a client whose unsent output passes maxClientBufferBytes
//                    (it stopped reading) is dropped and counted
//   anything else    a file path, created or truncated
// Lines are written with CR LF. UDP packs the lines of one write() into datagrams of at most 1472 bytes
// (lines are never split). Lives in the thread that made it; TCP needs that thread's event loop.
#include <QHostAddress>
#include <QObject>
#include <QString>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

class QFile;
class QTcpServer;
class QTcpSocket;
class QUdpSocket;

namespace reckoner::conn {

struct DestinationSpec {
  enum class Kind : std::uint8_t { Udp, TcpServer, File };
  Kind kind = Kind::File;
  QString host;  ///< UDP: the peer; TCP: the address to listen on (empty: any)
  quint16 port = 0;
  QString path;
};
/// Parses --nmea-out's DEST. Throws std::invalid_argument with a message naming what is wrong.
DestinationSpec parseDestination(const std::string& spec);

struct DestinationCounters {
  long lines = 0;       ///< lines written (to the file, sent in datagrams, queued for TCP clients)
  long datagrams = 0;   ///< UDP
  long sendErrors = 0;  ///< UDP datagrams the system refused
  long clientsAccepted = 0, clientsDropped = 0;  ///< TCP: dropped for not reading
  long linesWithoutClient = 0;                   ///< TCP: written while nobody was connected
};

class NmeaDestination : public QObject {
  Q_OBJECT
 public:
  static constexpr qint64 kDefaultClientBufferBytes = qint64{256} * 1024;
  /// Opens the destination. Throws std::runtime_error naming the file, address or port on failure.
  explicit NmeaDestination(const DestinationSpec& spec, QObject* parent = nullptr,
                           qint64 maxClientBufferBytes = kDefaultClientBufferBytes);
  ~NmeaDestination() override;

  /// Writes lines (without CR LF).
  void write(const std::vector<std::string>& lines);
  /// Flushes the file; for TCP, waits up to timeoutMs for the clients' queues to drain.
  void flush(int timeoutMs = 0);

  /// The TCP server's port (useful with tcp://:0), else the spec's port.
  [[nodiscard]] quint16 port() const;
  [[nodiscard]] int clients() const { return static_cast<int>(clients_.size()); }
  [[nodiscard]] const DestinationCounters& counters() const { return counters_; }

 signals:
  void clientConnected();

 private:
  void accept();
  void sendDatagram(const QByteArray& bytes);

  DestinationSpec spec_;
  QHostAddress udpPeer_;
  qint64 maxClientBufferBytes_;
  std::unique_ptr<QUdpSocket> udp_;
  QTcpServer* server_ = nullptr;
  std::vector<QTcpSocket*> clients_;
  std::unique_ptr<QFile> file_;
  DestinationCounters counters_;
};

}  // namespace reckoner::conn
