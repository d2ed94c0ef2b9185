// Every number of a scenario file, set to every hostile value, is either refused with one error line
// naming the file and line, or gives a run that advances and stays finite (sim/scenario_limits.h). The
// run is cut to its first minute: what is checked is that no value that passes validation hangs,
// overflows or turns to NaN (the limits of this process end a hang or an unbounded allocation).
#include <QTest>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "files/scenario_json.h"
#include "io/input_error.h"
#include "io/json.h"
#include "resources/embedded.h"
#include "sim/simulation_engine.h"
#include "support/resource_limits.h"

using namespace reckoner;

namespace {
void writeValue(io::JsonWriter& w, const io::JsonValue& v) {
  using T = io::JsonValue::Type;
  switch (v.type) {
    case T::Null:
      w.null();
      break;
    case T::Bool:
      w.value(v.boolean);
      break;
    case T::Number:
      w.value(v.number, 17);
      break;
    case T::String:
      w.value(v.string);
      break;
    case T::Array:
      w.beginArray();
      for (const auto& e : v.array) writeValue(w, e);
      w.endArray();
      break;
    case T::Object:
      w.beginObject();
      for (const auto& [k, e] : v.object) {
        w.key(k);
        writeValue(w, e);
      }
      w.endObject();
      break;
  }
}

/// Every numeric leaf of a JSON document: its path and a way to reach it in a copy.
void numbersOf(io::JsonValue& v, const std::string& path,
               std::vector<std::pair<std::string, io::JsonValue*>>& out) {
  if (v.isNumber()) out.emplace_back(path, &v);
  for (std::size_t i = 0; i < v.array.size(); ++i)
    numbersOf(v.array[i], path + "[" + std::to_string(i) + "]", out);
  for (auto& [k, e] : v.object) {
    std::string child = path;
    if (!child.empty()) child += '.';
    numbersOf(e, child + k, out);
  }
}

bool finite(const sim::SimFrame& f) {
  if (!f.estimate.x.allFinite() || !f.estimate.P.allFinite()) return false;
  for (const auto& t : f.tracks)
    if (!t.estimate.x.allFinite() || !t.estimate.P.allFinite()) return false;
  return true;
}
}  // namespace

class TestScenarioLimits : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() { test::limitThisProcess(1200, std::size_t{4} << 30); }

  void everyNumberIsBoundedOrRefused_data() {
    QTest::addColumn<QString>("scenario");
    for (const char* s : {"default", "imo-1", "table3-test1", "radar-fix", "seed002-matched"})
      QTest::newRow(s) << s;
  }
  void everyNumberIsBoundedOrRefused() {
    QFETCH(QString, scenario);
    const auto* file = resources::findScenario(scenario.toStdString());
    QVERIFY(file);
    const io::JsonValue original = io::parseJson(file->text);
    std::vector<std::pair<std::string, io::JsonValue*>> probe;
    io::JsonValue copy = original;
    numbersOf(copy, "", probe);
    const double values[] = {0.0, -1.0, 1e-300, 1e-13, 1e-7, 1e-3, 0.5, 10.0, 1e4, 1e6, 1e13, 1e300};
    int refused = 0, ran = 0;
    for (std::size_t leaf = 0; leaf < probe.size(); ++leaf) {
      for (const double v : values) {
        io::JsonValue doc = original;
        std::vector<std::pair<std::string, io::JsonValue*>> leaves;
        numbersOf(doc, "", leaves);
        leaves[leaf].second->number = v;
        io::JsonWriter w;
        writeValue(w, doc);
        const std::string what = leaves[leaf].first + " = " + std::to_string(v);
        sim::Scenario s;
        try {
          s = files::parseScenario(w.str(), "s.json");
        } catch (const io::InputError& e) {
          const std::string msg = e.what();
          std::string context = what;
          context.append(": ").append(msg);
          QVERIFY2(msg.rfind("s.json:", 0) == 0 && msg.find('\n') == std::string::npos, context.c_str());
          QVERIFY2(e.line() > 0, context.c_str());
          ++refused;
          continue;
        }
        // Accepted: the first minute (10 s under the sanitizers, 30 times slower) advances and stays finite.
        sim::Scenario shortRun = s;
        shortRun.durationUs =
            std::min<TimeUs>(s.durationUs, (test::slowdown() > 1 ? 10 : 60) * kMicrosPerSecond);
        shortRun.stepUs = std::min(shortRun.stepUs, shortRun.durationUs);
        sim::SimulationEngine engine(shortRun, 1);
        TimeUs last = -1;
        while (!engine.finished()) {
          const sim::SimFrame f = engine.step();
          QVERIFY2(f.timeUs > last, what.c_str());
          QVERIFY2(finite(f), what.c_str());
          last = f.timeUs;
        }
        ++ran;
      }
    }
    qInfo("%s: %zu numbers x %zu values: %d refused with a line, %d ran finite", qPrintable(scenario),
          probe.size(), std::size(values), refused, ran);
  }
};

QTEST_APPLESS_MAIN(TestScenarioLimits)
#include "tst_scenario_limits.moc"
