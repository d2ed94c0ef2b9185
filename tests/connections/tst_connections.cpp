// The connections library (docs/connections.md): specs, and UDP, multicast, TCP and file sources on
// loopback through a ConnectionHub, with what is dropped counted and memory bounded.
#include <QNetworkInterface>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QUdpSocket>
#include <QtTest>

#include <random>
#include <stdexcept>

#include "connection_test_helpers.h"

using namespace conn_test;

namespace {
constexpr int kCapMs = 60'000;  // generous: the machine is shared
}

class TstConnections : public QObject {
  Q_OBJECT
 private slots:
  void specsParseAndRoundTrip() {
    const conn::SourceConfig u = conn::parseSource("udp://:10110");
    QCOMPARE(u.kind, conn::Kind::Udp);
    QCOMPARE(u.port, 10110);
    QVERIFY(u.host.empty() && !u.multicast);
    QCOMPARE(u.name, std::string("udp:10110"));
    const conn::SourceConfig m = conn::parseSource("udp://239.192.0.1:60001?iface=lo");
    QVERIFY(m.multicast);
    QCOMPARE(m.interfaceName, std::string("lo"));
    const conn::SourceConfig t = conn::parseSource("tcp://localhost:10110?name=kplex&priority=2&role=radar");
    QCOMPARE(t.kind, conn::Kind::Tcp);
    QCOMPARE(t.host, std::string("localhost"));
    QCOMPARE(t.name, std::string("kplex"));
    QCOMPARE(t.priority, 2);
    QCOMPARE(t.role, conn::Role::Radar);
    const conn::SourceConfig s =
        conn::parseSource("serial:///dev/ttyUSB0:38400?accept=RMC,GGA&reject-talkers=AI");
    QCOMPARE(s.device, std::string("/dev/ttyUSB0"));
    QCOMPARE(s.baud, 38400);
    QCOMPARE(s.filter.acceptTypes, (std::vector<std::string>{"RMC", "GGA"}));
    QCOMPARE(conn::parseSource("serial:///dev/ttyS0").baud, 4800);
    const conn::SourceConfig g = conn::parseSource("gpsd://127.0.0.1");
    QCOMPARE(g.kind, conn::Kind::Gpsd);
    QCOMPARE(g.port, 2947);
    const conn::SourceConfig f = conn::parseSource("file:///tmp/a.nmea?rate=x10");
    QCOMPARE(f.path, std::string("/tmp/a.nmea"));
    QVERIFY(f.rate.ownTime && f.rate.speedFactor == 10.0);
    const conn::SourceConfig f2 = conn::parseSource("file:///tmp/a.nmea?rate=25&enabled=0");
    QVERIFY(!f2.rate.ownTime && f2.rate.linesPerSecond == 25.0 && !f2.enabled);
    for (const auto& c : {u, m, t, s, g, f, f2}) QCOMPARE(conn::parseSource(conn::toSpec(c)), c);

    // Bad specs: one message naming the field
    const std::vector<std::pair<std::string, std::string>> bad{{"udp://:0", "port"},
                                                               {"udp://:99999", "port"},
                                                               {"tcp://:10110", "host"},
                                                               {"tcp://host", "port"},
                                                               {"ftp://x:1", "kind"},
                                                               {"serial://", "device"},
                                                               {"serial:///dev/x:fast", "baud"},
                                                               {"file://", "path"},
                                                               {"file:///a?rate=x0", "rate"},
                                                               {"udp://:1?bogus=1", "bogus"},
                                                               {"udp://:1?iface=lo", "iface"},
                                                               {"10110", "kind"}};
    for (const auto& [spec, field] : bad) {
      try {
        conn::parseSource(spec);
        QFAIL(qPrintable(QString::fromStdString("accepted: " + spec)));
      } catch (const std::invalid_argument& e) {
        const std::string what = e.what();
        QVERIFY2(what.find(spec) != std::string::npos && what.find(field + ":") != std::string::npos,
                 e.what());
      }
    }
  }

  void udpLinesArriveWithTimesAndSequence() {
    // GIVEN a UDP source on a free loopback port that rejects GSV
    const quint16 port = freeUdpPort();
    conn::ConnectionHub hub(fastRetry());
    hub.add(conn::parseSource("udp://127.0.0.1:" + std::to_string(port) + "?name=udp&reject=GSV"));
    QSignalSpy available(&hub, &conn::ConnectionHub::linesAvailable);
    hub.start();
    QTRY_VERIFY_WITH_TIMEOUT(statusOf(hub, "udp").state == conn::State::Connected, kCapMs);
    // WHEN datagrams come with several sentences, one without its CR LF, a bad checksum, a filtered GSV
    const auto s = sentences(4);
    const conn::UtcUs before = nowUtcUs();
    QUdpSocket tx;
    const std::string gsv = sentence("GPGSV,1,1,00");
    std::string bad = s[3];
    bad.back() = bad.back() == '0' ? '1' : '0';
    tx.writeDatagram(QByteArray::fromStdString(s[0] + "\r\n" + s[1] + "\r\n"), QHostAddress::LocalHost, port);
    tx.writeDatagram(QByteArray::fromStdString(gsv + "\r\n" + bad + "\r\n" + s[2]), QHostAddress::LocalHost,
                     port);
    tx.writeDatagram(QByteArray::fromStdString(s[3] + "\r\n"), QHostAddress::LocalHost, port);
    // THEN the good ones come out in order, with receive times and consecutive sequence numbers
    Drain drain{hub, {}};
    QTRY_VERIFY_WITH_TIMEOUT(drain() >= 4, kCapMs);
    QCOMPARE(drain.lines(), (std::vector<std::string>{s[0], s[1], s[2], s[3]}));
    QVERIFY(available.count() >= 1);
    const conn::UtcUs after = nowUtcUs();
    for (std::size_t i = 0; i < drain.got.size(); ++i) {
      QCOMPARE(drain.got[i].source, std::string("udp"));
      QVERIFY(drain.got[i].receivedUtc >= before && drain.got[i].receivedUtc <= after);
      QCOMPARE(drain.got[i].sequence, drain.got[0].sequence + i);
    }
    // AND the rest is counted
    QTRY_VERIFY_WITH_TIMEOUT(statusOf(hub, "udp").filtered == 1, kCapMs);
    const conn::SourceStatus st = statusOf(hub, "udp");
    QCOMPARE(st.badChecksum, 1u);
    QCOMPARE(st.lines, 4u);
    QVERIFY(st.lastSeenUtc.has_value());
    // AND the monitor shows every raw line with what became of it, filterable by text
    const auto mon = hub.monitor(conn::MonitorFilter{"udp", "GSV", 0});
    QCOMPARE(mon.size(), std::size_t{1});
    QCOMPARE(mon[0].verdict, conn::Verdict::Filtered);
    QCOMPARE(hub.monitor().size(), std::size_t{6});
    QCOMPARE(std::string(conn::stateName(st.state)), std::string("connected"));
  }

  void multicastJoinOnLoopbackOrItsError() {
    // The join error path: an interface that does not exist is named in the error
    {
      conn::ConnectionHub hub(fastRetry());
      hub.add(conn::parseSource("udp://239.255.42.1:" + std::to_string(freeUdpPort()) +
                                "?name=mc&iface=nosuch0"));
      hub.start();
      QTRY_VERIFY_WITH_TIMEOUT(statusOf(hub, "mc").state == conn::State::Error, kCapMs);
      const std::string err = statusOf(hub, "mc").lastError;
      QVERIFY2(err.find("239.255.42.1") != std::string::npos && err.find("nosuch0") != std::string::npos,
               err.c_str());
    }
    // Delivery on loopback, where its interface takes multicast
    const QNetworkInterface lo = QNetworkInterface::interfaceFromName("lo");
    const bool required = qEnvironmentVariableIsSet("RECKONER_REQUIRE_MULTICAST");  // multicast_netns.sh
    if (required)
      QVERIFY2(lo.isValid() && (lo.flags() & QNetworkInterface::CanMulticast), "lo takes no multicast");
    if (!lo.isValid() || !(lo.flags() & QNetworkInterface::CanMulticast))
      QSKIP(
          "the loopback interface has no MULTICAST flag here: only the join error path is tested here; "
          "tst_connections_multicast runs delivery in a network namespace (multicast_netns.sh)");
    const quint16 port = freeUdpPort();
    conn::ConnectionHub hub(fastRetry());
    hub.add(conn::parseSource("udp://239.255.42.1:" + std::to_string(port) + "?name=mc&iface=lo"));
    hub.start();
    QTRY_VERIFY_WITH_TIMEOUT(statusOf(hub, "mc").state == conn::State::Connected, kCapMs);
    QUdpSocket tx;
    tx.setMulticastInterface(lo);
    tx.setSocketOption(QAbstractSocket::MulticastLoopbackOption, 1);
    const std::string line = sentences(1)[0] + "\r\n";
    Drain drain{hub, {}};
    QTRY_VERIFY_WITH_TIMEOUT(
        (tx.writeDatagram(QByteArray::fromStdString(line), QHostAddress("239.255.42.1"), port), drain() > 0),
        kCapMs);
    QCOMPARE(drain.got[0].line + "\r\n", line);
  }

  void tcpReconnectsAndCountsTheHalfLine() {
    // GIVEN a TCP server on loopback and a source connected to it
    QTcpServer server;
    QVERIFY(server.listen(QHostAddress::LocalHost, 0));
    conn::ConnectionHub hub(fastRetry());
    hub.add(conn::parseSource("tcp://127.0.0.1:" + std::to_string(server.serverPort()) + "?name=tcp"));
    hub.start();
    QTRY_VERIFY_WITH_TIMEOUT(server.hasPendingConnections(), kCapMs);
    QTcpSocket* peer = server.nextPendingConnection();
    const auto s = sentences(3);
    // WHEN it sends two lines and half a third, then closes mid-line
    peer->write(QByteArray::fromStdString(s[0] + "\r\n" + s[1] + "\r\n" + s[2].substr(0, 8)));
    QVERIFY(peer->waitForBytesWritten(kCapMs) || peer->bytesToWrite() == 0);
    Drain drain{hub, {}};
    QTRY_VERIFY_WITH_TIMEOUT(drain() >= 2, kCapMs);
    peer->disconnectFromHost();
    // THEN the two lines are delivered, the half line is counted, not delivered
    QTRY_VERIFY_WITH_TIMEOUT(statusOf(hub, "tcp").partial == 1, kCapMs);
    QCOMPARE(drain.lines(), (std::vector<std::string>{s[0], s[1]}));
    QVERIFY(!statusOf(hub, "tcp").lastError.empty());
    // AND the source reconnects by itself when the server accepts again
    QTRY_VERIFY_WITH_TIMEOUT(server.hasPendingConnections(), kCapMs);
    QTcpSocket* again = server.nextPendingConnection();
    again->write(QByteArray::fromStdString(s[2] + "\r\n"));
    QTRY_VERIFY_WITH_TIMEOUT(drain() >= 3, kCapMs);
    QCOMPARE(drain.got[2].line, s[2]);
    QCOMPARE(statusOf(hub, "tcp").state, conn::State::Connected);
    QCOMPARE(statusOf(hub, "tcp").connects, 2u);
    delete peer;
    delete again;
  }

  void floodOfLongLinesAndGarbageKeepsMemoryBounded() {
    // GIVEN a TCP source with a queue of 1000 lines that nobody drains
    QTcpServer server;
    QVERIFY(server.listen(QHostAddress::LocalHost, 0));
    conn::HubOptions o = fastRetry();
    o.queueCapacity = 1000;
    conn::ConnectionHub hub(o);
    hub.add(conn::parseSource("tcp://127.0.0.1:" + std::to_string(server.serverPort()) + "?name=flood"));
    hub.start();
    QTRY_VERIFY_WITH_TIMEOUT(server.hasPendingConnections(), kCapMs);
    QTcpSocket* peer = server.nextPendingConnection();
    // WHEN the peer sends a 10 MB line without a newline, then 100 MB of random bytes, then a sentence
    std::mt19937 rng(19);
    std::uint64_t sent = 0;
    const auto send = [&](const QByteArray& chunk) {
      while (peer->bytesToWrite() > qint64{4} * 1024 * 1024) peer->waitForBytesWritten(1000);
      peer->write(chunk);
      sent += static_cast<std::uint64_t>(chunk.size());
    };
    const QByteArray mb(qsizetype{1024} * 1024, 'A');
    for (int i = 0; i < 10; ++i) send(mb);
    QByteArray garbage(qsizetype{1024} * 1024, '\0');
    for (int i = 0; i < 100; ++i) {
      for (char& c : garbage) c = static_cast<char>(rng() & 0xff);
      send(garbage);
    }
    const std::string last = sentences(1)[0];
    send(QByteArray::fromStdString("\r\n" + last + "\r\n"));
    // THEN every byte is read, the last sentence is the newest line queued, and nothing grew
    QTRY_VERIFY_WITH_TIMEOUT(statusOf(hub, "flood").bytes == sent, 5 * kCapMs);
    const conn::SourceStatus st = statusOf(hub, "flood");
    QVERIFY(st.tooLong >= 1);
    QVERIFY(st.binary > 100'000);  // a newline every 256 bytes on average, most lines with a binary byte
    QVERIFY2(st.framerPeak <= o.maxLineLength, qPrintable(QString::number(st.framerPeak)));
    const conn::HubCounters c = hub.counters();
    QVERIFY(c.peakQueued <= 1000 && c.queued <= 1000);
    QCOMPARE(c.dropped, st.dropped);
    QCOMPARE(st.lines, st.dropped + c.queued);  // every line delivered is queued or counted as dropped
    const auto queued = hub.take();
    QVERIFY(!queued.empty());
    QCOMPARE(queued.back().line, last);
    QVERIFY(hub.monitor({}, 1'000'000).size() <= o.monitorCapacity);
    delete peer;
  }

  void hubAddsEnablesAndRemovesSources() {
    conn::ConnectionHub hub(fastRetry());
    const quint16 port = freeUdpPort();
    hub.add(conn::parseSource("udp://127.0.0.1:" + std::to_string(port) + "?name=a"));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, hub.add(conn::parseSource("udp://:1?name=a")));
    hub.add(conn::parseSource("udp://127.0.0.1:" + std::to_string(freeUdpPort()) + "?name=b&enabled=0"));
    QCOMPARE(statusOf(hub, "b").state, conn::State::Disabled);
    hub.start();
    QTRY_VERIFY_WITH_TIMEOUT(statusOf(hub, "a").state == conn::State::Connected, kCapMs);
    QCOMPARE(statusOf(hub, "b").state, conn::State::Disabled);
    QVERIFY(hub.setEnabled("b", true));
    QTRY_VERIFY_WITH_TIMEOUT(statusOf(hub, "b").state == conn::State::Connected, kCapMs);
    QVERIFY(hub.setEnabled("a", false));
    QCOMPARE(statusOf(hub, "a").state, conn::State::Disabled);
    QVERIFY(hub.remove("a"));
    QVERIFY(!hub.remove("a"));
    QCOMPARE(hub.status().size(), std::size_t{1});
    hub.stop();
    QCOMPARE(statusOf(hub, "b").state, conn::State::Stopped);
  }

  void fullQueueDropsTheOldestAndCountsThem() {
    const quint16 port = freeUdpPort();
    conn::HubOptions o = fastRetry();
    o.queueCapacity = 10;
    conn::ConnectionHub hub(o);
    hub.add(conn::parseSource("udp://127.0.0.1:" + std::to_string(port) + "?name=u"));
    hub.start();
    QTRY_VERIFY_WITH_TIMEOUT(statusOf(hub, "u").state == conn::State::Connected, kCapMs);
    const auto s = sentences(50);
    std::string all;
    for (const auto& l : s) all += l + "\r\n";
    QUdpSocket tx;
    tx.writeDatagram(QByteArray::fromStdString(all), QHostAddress::LocalHost, port);
    QTRY_VERIFY_WITH_TIMEOUT(statusOf(hub, "u").lines == 50, kCapMs);
    QCOMPARE(statusOf(hub, "u").dropped, 40u);
    const auto got = hub.take();
    QCOMPARE(got.size(), std::size_t{10});
    QCOMPARE(got.front().line, s[40]);
    QCOMPARE(got.back().line, s[49]);
  }

  void filePlaysAtItsOwnTimeAndAtAFixedRate() {
    // GIVEN a recording of 20 fixes one second apart, each with a heading after it, the last half
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    std::vector<std::string> lines;
    for (int i = 0; i < 20; ++i) {
      const int sod = (86'390 + i) % 86'400;  // 23:59:50 to 00:00:09
      char t[16];
      std::snprintf(t, sizeof t, "%02d%02d%02d.00", sod / 3600, sod / 60 % 60, sod % 60);
      std::string rmc("GPRMC,");
      rmc += t;
      rmc += ",A,5400.000,N,01000.000,E,5.0,90.0,011224,,,A";
      lines.push_back(sentence(rmc));
      lines.push_back(sentences(i + 1).back());
    }
    std::string text;
    for (const auto& l : lines) text += l + "\r\n";
    text += "$GPHDT,1";  // the recording stops mid-line
    const QString path = dir.filePath("rec.nmea");
    {
      QFile f(path);
      QVERIFY(f.open(QIODevice::WriteOnly));
      f.write(QByteArray::fromStdString(text));
    }
    // WHEN it is played ten times faster than its own time (across midnight), and at 50 lines/s
    for (const std::string rate : {"x10", "50"}) {
      conn::ConnectionHub hub(fastRetry());
      hub.add(conn::parseSource("file://" + path.toStdString() + "?name=f&rate=" + rate));
      hub.start();
      Drain drain{hub, {}};
      QTRY_VERIFY_WITH_TIMEOUT(statusOf(hub, "f").state == conn::State::Finished, kCapMs);
      drain();
      // THEN every line comes in order, the half line is counted, and the pace was kept (a lower
      // bound: a loaded machine is only slower)
      QCOMPARE(drain.lines(), lines);
      QCOMPARE(statusOf(hub, "f").partial, 1u);
      const double spanS =
          static_cast<double>(drain.got.back().receivedUtc - drain.got.front().receivedUtc) * 1e-6;
      const double expectS = rate == "x10" ? 19.0 / 10.0 : 39.0 / 50.0;
      QVERIFY2(spanS >= 0.95 * expectS, qPrintable(QString("%1 s for %2").arg(spanS).arg(expectS)));
    }
  }
};

QTEST_GUILESS_MAIN(TstConnections)
#include "tst_connections.moc"
