// io::LineFramer (docs/connections.md, "Framing"): terminators, any chunking, limits, garbage, resets.
#include <QtTest>

#include <string>
#include <vector>

#include "io/line_framer.h"

using reckoner::io::LineFramer;

class TstLineFramer : public QObject {
  Q_OBJECT
 private slots:
  void crLfAndCrlfEndLinesInAnyChunking() {
    // GIVEN a stream with CR, LF and CRLF terminators and an empty line
    const std::string stream = "$GPHDT,1.0,T*00\r\n$GPHDT,2.0,T*00\n\n$GPHDT,3.0,T*00\r$GPHDT,4.0,T*00\r\n";
    const std::vector<std::string> expected{"$GPHDT,1.0,T*00", "$GPHDT,2.0,T*00", "$GPHDT,3.0,T*00",
                                            "$GPHDT,4.0,T*00"};
    // WHEN it is fed whole, byte by byte and in chunks of 7 THEN the same four lines come out
    for (const std::size_t chunk : {stream.size(), std::size_t{1}, std::size_t{7}}) {
      LineFramer f;
      std::vector<std::string> out;
      for (std::size_t i = 0; i < stream.size(); i += chunk) f.feed(stream.substr(i, chunk), out);
      QCOMPARE(out, expected);
      QCOMPARE(f.counters().lines, 4u);
      QCOMPARE(f.counters().bytes, stream.size());
      QCOMPARE(f.buffered(), std::size_t{0});
    }
  }

  void tooLongLineIsDiscardedToItsNewlineWithBoundedMemory() {
    // GIVEN a framer with a limit of 82 and a 10 MB line fed in 64 KiB chunks
    LineFramer f(82);
    std::vector<std::string> out;
    const std::string chunk(std::size_t{64} * 1024, 'A');
    for (int i = 0; i < 160; ++i) {
      f.feed(chunk, out);
      // THEN it never holds more than the limit
      QVERIFY(f.buffered() <= 82);
    }
    QVERIFY(out.empty());
    // WHEN the newline comes, then a good line
    f.feed("AAAA\r\n$GPHDT,1.0,T*00\r\n", out);
    // THEN the long line is counted once, the good one delivered
    QCOMPARE(f.counters().tooLong, 1u);
    QCOMPARE(out, std::vector<std::string>{"$GPHDT,1.0,T*00"});
    QVERIFY(f.counters().peakBuffered <= 82);
    // AND a line of exactly the limit passes
    out.clear();
    f.feed(std::string(82, 'B') + "\n", out);
    QCOMPARE(out.size(), std::size_t{1});
  }

  void binaryBytesDiscardTheirLine() {
    LineFramer f;
    std::vector<std::string> out;
    f.feed(std::string("$GPRMC,12\0\xff"
                       "3,A*00\r\n$GPHDT,1.0,T*00\r\n",
                       36),
           out);
    QCOMPARE(out, std::vector<std::string>{"$GPHDT,1.0,T*00"});
    QCOMPARE(f.counters().binary, 1u);
  }

  void halfLineAtResetIsCountedNotDelivered() {
    LineFramer f;
    std::vector<std::string> out;
    f.feed("$GPHDT,1.0,T*00\r\n$GPHDT,2.", out);
    f.reset();
    QCOMPARE(f.counters().partial, 1u);
    f.feed("0,T*00\r\n", out);  // the rest after a reconnect is a line of its own
    QCOMPARE(out, (std::vector<std::string>{"$GPHDT,1.0,T*00", "0,T*00"}));
    f.reset();  // nothing buffered: nothing counted
    QCOMPARE(f.counters().partial, 1u);
  }

  void endOfRecordEndsADatagramsLastLine() {
    LineFramer f;
    std::vector<std::string> out;
    f.feed("$GPHDT,1.0,T*00\r\n$GPHDT,2.0,T*00", out);
    f.endOfRecord(out);
    QCOMPARE(out, (std::vector<std::string>{"$GPHDT,1.0,T*00", "$GPHDT,2.0,T*00"}));
    QCOMPARE(f.counters().partial, 0u);
  }
};

QTEST_GUILESS_MAIN(TstLineFramer)
#include "tst_line_framer.moc"
