#include <QTest>

#include "io/json.h"

using namespace reckoner::io;

class TestJson : public QObject {
  Q_OBJECT
 private slots:
  void parsesAllTypesWithPositions() {
    const JsonValue v =
        parseJson("{\n  \"a\": [1, -2.5e3, true, false, null],\n  \"s\": \"x\\u00e9\\n\\ud83d\\ude00\"\n}\n");
    QVERIFY(v.isObject());
    const JsonValue* a = v.find("a");
    QVERIFY(a && a->isArray() && a->array.size() == 5);
    QCOMPARE(a->line, 2);
    QCOMPARE(a->column, 8);
    QCOMPARE(a->array[1].number, -2500.0);
    QVERIFY(a->array[2].boolean && !a->array[3].boolean);
    QCOMPARE(a->array[4].type, JsonValue::Type::Null);
    QCOMPARE(v.find("s")->string, std::string("x\xc3\xa9\n\xf0\x9f\x98\x80"));
    QCOMPARE(v.find("s")->line, 3);
    QVERIFY(v.find("missing") == nullptr);
  }
  void rejectsMalformedInput_data() {
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("line");
    QTest::newRow("empty") << "" << 1;
    QTest::newRow("trailing comma") << "{\"a\": 1,\n}" << 2;
    QTest::newRow("duplicate key") << "{\"a\": 1,\n \"a\": 2}" << 2;
    QTest::newRow("unterminated string") << "{\"a\": \"abc" << 1;
    QTest::newRow("bad escape") << "\"\\q\"" << 1;
    QTest::newRow("control character") << "\"a\tb\"" << 1;
    QTest::newRow("leading zero") << "[01]" << 1;
    QTest::newRow("bare dot") << "[1.]" << 1;
    QTest::newRow("NaN") << "[NaN]" << 1;
    QTest::newRow("huge number") << "[1e999]" << 1;
    QTest::newRow("comment") << "{} // no" << 1;
    QTest::newRow("garbage after") << "{}\n\nx" << 3;
    QTest::newRow("lone surrogate") << "\"\\ud800\"" << 1;
    QTest::newRow("missing colon") << "{\"a\" 1}" << 1;
  }
  void rejectsMalformedInput() {
    QFETCH(QString, text);
    QFETCH(int, line);
    try {
      parseJson(text.toStdString());
      QFAIL("accepted malformed JSON");
    } catch (const JsonParseError& e) {
      QCOMPARE(e.line(), line);
      QVERIFY(std::string(e.what()).find("line ") == 0);
    }
  }
  void stringsMustBeUtf8() {
    // RFC 8259: JSON text is UTF-8. A name with bytes that are not is an error with its line, never a
    // string that a writer would turn into invalid JSON.
    QCOMPARE(parseJson("\"\xc3\xa9t\xc3\xa9 \xf0\x9f\x9a\xa2\"").string,
             std::string("\xc3\xa9t\xc3\xa9 \xf0\x9f\x9a\xa2"));
    for (const char* bad :
         {"{\n\"name\": \"a\xff\"}", "{\n\"name\": \"\xc0\xaf\"}", "{\n\"n\xed\xa0\x80\": 1}"}) {
      try {
        parseJson(bad);
        QFAIL(bad);
      } catch (const JsonParseError& e) {
        QCOMPARE(e.line(), 2);
        QVERIFY2(std::string(e.what()).find("invalid UTF-8") != std::string::npos, e.what());
      }
    }
    JsonWriter w;
    w.beginObject()
        .key("name\xff")
        .value(
            "a\xfe\xff"
            "b")
        .endObject();
    const JsonValue v = parseJson(w.str());  // the writer's output is valid JSON
    QCOMPARE(v.find("name\xef\xbf\xbd")->string, std::string("a\xef\xbf\xbd\xef\xbf\xbd"
                                                             "b"));
  }
  void duplicateKeyAmongManyIsFound() {
    std::string text = "{";
    for (int k = 0; k < 100000; ++k) text += "\"k" + std::to_string(k) + "\": 0,\n";
    text += "\"k77777\": 1}";
    try {
      parseJson(text);
      QFAIL("accepted a duplicate key");
    } catch (const JsonParseError& e) {
      QCOMPARE(e.line(), 100001);
      QVERIFY2(std::string(e.what()).find("duplicate key 'k77777'") != std::string::npos, e.what());
    }
  }
  void deepNestingIsAnErrorNotACrash() {
    const std::string deep(100000, '[');
    QVERIFY_THROWS_EXCEPTION(JsonParseError, parseJson(deep));
  }
  void writerRoundTrips() {
    JsonWriter w;
    w.beginObject();
    w.key("name").value("a \"quoted\"\nline");
    w.key("n").value(0.1);
    w.key("i").value(static_cast<std::int64_t>(-42));
    w.key("inf").value(std::numeric_limits<double>::infinity());
    w.key("list").numberArray({1.5, 2.0});
    w.key("empty").beginArray().endArray();
    w.key("nested").beginObject().key("ok").value(true).endObject();
    w.endObject();
    const JsonValue v = parseJson(w.str());
    QCOMPARE(v.find("name")->string, std::string("a \"quoted\"\nline"));
    QCOMPARE(v.find("n")->number, 0.1);
    QCOMPARE(v.find("i")->number, -42.0);
    QCOMPARE(v.find("inf")->type, JsonValue::Type::Null);
    QCOMPARE(v.find("list")->array[0].number, 1.5);
    QVERIFY(v.find("empty")->array.empty());
    QVERIFY(v.find("nested")->find("ok")->boolean);
  }
};

QTEST_APPLESS_MAIN(TestJson)
#include "tst_json.moc"
