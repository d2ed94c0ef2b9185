// The one formatter of error lines: what a user sees of bad input (docs/outputs.md, "Errors").
#include <QTest>

#include "io/error_line.h"
#include "io/input_error.h"
#include "io/utf8.h"

using namespace reckoner;

class TestErrorLine : public QObject {
  Q_OBJECT
 private slots:
  void quotedEscapesWhatATerminalWouldHide() {
    QCOMPARE(io::quoted("abc"), std::string("'abc'"));
    QCOMPARE(io::quoted("a\tb\nc\r"), std::string("'a\\tb\\nc\\r'"));
    QCOMPARE(io::quoted("it's \\"), std::string("'it\\'s \\\\'"));
    QCOMPARE(io::quoted(std::string("\x01\x7f", 2)), std::string("'\\x01\\x7F'"));
    QCOMPARE(io::quoted("\xef\xbb\xbfutc"), std::string("'\xef\xbb\xbfutc'"));  // valid UTF-8 kept
    QCOMPARE(io::quoted("\xff\xfe"), std::string("'\\xFF\\xFE'"));              // not UTF-8
    QCOMPARE(io::quoted("\xed\xa0\x80"), std::string("'\\xED\\xA0\\x80'"));     // a surrogate
    QCOMPARE(io::quoted("\xc0\xaf"), std::string("'\\xC0\\xAF'"));              // overlong
  }
  void quotedCutsLongInput() {
    const std::string big(400000, 'x');
    const std::string q = io::quoted(big);
    QCOMPARE(q.substr(0, 202), "'" + std::string(200, 'x') + "'");
    QCOMPARE(q.substr(202), std::string("... (400000 bytes)"));
    QCOMPARE(io::quoted("abcdef", 3), std::string("'abc'... (6 bytes)"));
  }
  void oneLineJoinsLinesAndCuts() {
    QCOMPARE(io::oneLine("ERROR 1: first\n  second\r\nthird\n"),
             std::string("ERROR 1: first; second; third"));
    QCOMPARE(io::oneLine("a   b\t\tc"), std::string("a b c"));
    QCOMPARE(io::oneLine(std::string("raw \x02 byte \xff", 12)), std::string("raw \\x02 byte \\xFF"));
    QCOMPARE(io::oneLine(std::string(1000, 'm'), 10), std::string(10, 'm') + "...");
  }
  void inputErrorIsOneLineWhateverItHolds() {
    const io::InputError e(std::string("dir/a\nb.json"), 3, std::string(300, 'f'), "bad\nvalue\x01");
    const std::string w = e.what();
    QVERIFY2(w.find('\n') == std::string::npos && w.find('\x01') == std::string::npos, w.c_str());
    QVERIFY(w.rfind("dir/a; b.json:3: ", 0) == 0);
    QVERIFY(w.size() < 900);
  }
  void byteOrderMark() {
    std::string_view t = "\xef\xbb\xbf{}";
    QVERIFY(io::stripByteOrderMark(t));
    QCOMPARE(t, std::string_view("{}"));
    QVERIFY(!io::stripByteOrderMark(t));
  }
  void utf8() {
    QCOMPARE(io::firstInvalidUtf8("plain, \xc3\xa9t\xc3\xa9 \xe2\x82\xac \xf0\x9f\x9a\xa2"),
             std::string_view::npos);
    QCOMPARE(io::firstInvalidUtf8("ok\xff"), std::size_t(2));
    QCOMPARE(io::firstInvalidUtf8("\xf4\x90\x80\x80"), std::size_t(0));  // above U+10FFFF
    QCOMPARE(io::firstInvalidUtf8("\xe2\x82"), std::size_t(0));          // cut short
    QCOMPARE(io::validUtf8("a\xffz"), std::string("a\xef\xbf\xbdz"));
  }
};

QTEST_APPLESS_MAIN(TestErrorLine)
#include "tst_error_line.moc"
