// GIVEN / WHEN / THEN behaviour of the viewport, the portrayal rules and the chart renderer (pixels of
// real NOAA cells from ../shared/data/enc when present).
#include <QGuiApplication>
#include <QImage>
#include <QPainter>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <tuple>

#include "charts/pick/pick_report.h"
#include "charts/portrayal/portrayal.h"
#include "charts/render/chart_extent.h"
#include "charts/render/chart_renderer.h"
#include "charts/render/viewport.h"
#include "charts/s57/s57_loader.h"
#include "common/angles.h"
#include "support/compare_near.h"

using namespace reckoner::charts;
using reckoner::kPi;

namespace {
const std::string kEnc = RECKONER_SHARED_DIR "/data/enc";

QRgb rgbOf(Palette p, const char* token) {
  const Rgb c = defaultColours().colour(p, token);
  return qRgb(c.r, c.g, c.b);
}

}  // namespace

class TestChartRender : public QObject {
  Q_OBJECT
 private slots:
  void viewportRoundTripsAndKeepsTheScale() {
    const Viewport v({47.27, -122.43}, 20000, 1200, 800);
    for (const LatLon p : {LatLon{47.27, -122.43}, LatLon{47.30, -122.50}, LatLon{47.20, -122.35}}) {
      const LatLon back = v.toLatLon(v.toScreen(p));
      RK_COMPARE_NEAR(back.latDeg, p.latDeg, 1e-9);
      RK_COMPARE_NEAR(back.lonDeg, p.lonDeg, 1e-9);
    }
    const ScreenPoint c = v.toScreen({47.27, -122.43});
    RK_COMPARE_NEAR(c.x, 600, 1e-9);
    RK_COMPARE_NEAR(c.y, 400, 1e-9);
    // 1 km east at the centre latitude is 1000 / (20000 * 0.28 mm) = 178.6 px to the right.
    const double dLon = 1000.0 / (6378137.0 * std::cos(47.27 * kPi / 180.0)) * 180.0 / kPi;
    const ScreenPoint e = v.toScreen({47.27, -122.43 + dLon});
    RK_COMPARE_NEAR(e.x - c.x, 1000.0 / (20000 * 0.00028), 0.01);
    RK_COMPARE_NEAR(e.y, c.y, 1e-6);
    QVERIFY(v.toScreen({47.28, -122.43}).y < c.y);  // north is up
    // Course-up at 090: east is up.
    const Viewport r({47.27, -122.43}, 20000, 1200, 800, 0.28, kPi / 2);
    const ScreenPoint er = r.toScreen({47.27, -122.43 + dLon});
    RK_COMPARE_NEAR(er.x, 600, 1e-6);
    RK_COMPARE_NEAR(400 - er.y, 178.571, 0.01);
    const LatLon back = r.toLatLon(er);
    RK_COMPARE_NEAR(back.lonDeg, -122.43 + dLon, 1e-9);
    // The affine Mercator map the renderer uses agrees with toScreen, rotated or not.
    for (const Viewport& vp : {v, r})
      for (const LatLon ll : {LatLon{47.2, -122.5}, LatLon{47.31, -122.38}}) {
        const MercatorPoint m = toMercator(ll);
        const ScreenPoint a = vp.toScreen(ll), b = vp.mercatorToScreen()(m.x, m.y);
        RK_COMPARE_NEAR(a.x, b.x, 1e-6);
        RK_COMPARE_NEAR(a.y, b.y, 1e-6);
      }
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, Viewport({89.0, 0.0}, 1000, 10, 10));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, Viewport({0.0, 0.0}, 0, 10, 10));
  }
  void portrayalTablesAndConditionalCases() {
    QVERIFY(defaultPortrayal().size() > 50);
    QVERIFY(defaultPortrayal().find("DEPARE", Primitive::Area) != nullptr);
    QVERIFY(defaultPortrayal().find("DEPARE", Primitive::Point) == nullptr);
    for (Palette p : {Palette::Day, Palette::Dusk, Palette::Night})
      QVERIFY(!(defaultColours().colour(p, "LANDA") == Rgb{}));
    // Night is dark: every token is dimmer than by day.
    const Rgb day = defaultColours().colour(Palette::Day, "DEPDW"),
              night = defaultColours().colour(Palette::Night, "DEPDW");
    QVERIFY(night.r + night.g + night.b < 0.1 * (day.r + day.g + day.b));
    MarinerSettings s;  // 2 / 10 / 30 m
    QCOMPARE(depthShade(-1.0, s), std::string("DEPIT"));
    QCOMPARE(depthShade(1.0, s), std::string("DEPVS"));
    QCOMPARE(depthShade(5.0, s), std::string("DEPMS"));
    QCOMPARE(depthShade(10.0, s), std::string("DEPMD"));
    QCOMPARE(depthShade(40.0, s), std::string("DEPDW"));
    s.fourShades = false;
    QCOMPARE(depthShade(5.0, s), std::string("DEPVS"));
    QCOMPARE(depthShade(12.0, s), std::string("DEPDW"));
    QCOMPARE(*chooseSafetyContour({5.0, 18.2, 9.1, 30.0}, 10.0), 18.2);  // 10 absent: next deeper
    QCOMPARE(*chooseSafetyContour({5.0, 10.0}, 10.0), 10.0);
    QVERIFY(!chooseSafetyContour({2.0, 5.0}, 10.0).has_value());
    QVERIFY(isIsolatedDanger(3.0, 10.0));
    QVERIFY(!isIsolatedDanger(12.0, 10.0));
    QVERIFY(!isIsolatedDanger(std::nullopt, 10.0));
    QCOMPARE(soundingText(4.5), (std::pair<std::string, std::string>{"4", "5"}));
    QCOMPARE(soundingText(12.0), (std::pair<std::string, std::string>{"12", ""}));
    QCOMPARE(soundingText(35.7), (std::pair<std::string, std::string>{"35", ""}));
    QCOMPARE(soundingText(-1.2), (std::pair<std::string, std::string>{"1", "2"}));  // drying height
    QVERIFY_THROWS_EXCEPTION(
        std::invalid_argument,
        PortrayalTable::parse(R"({"rules": [{"class": "X", "primitive": "volume", "category": "base"}]})"));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             ColourTable::parse(R"({"day": {"A": "#zzzzzz"}, "dusk": {}, "night": {}})"));
  }
  void lightDescriptionsReadTheChartWay() {
    ChartFeature l;
    l.objectClass = "LIGHTS";
    l.attributes = {{"LITCHR", std::int64_t{2}},
                    {"SIGGRP", std::string("(2)")},
                    {"COLOUR", std::vector<std::int64_t>{3}},
                    {"SIGPER", 6.0},
                    {"HEIGHT", 12.0},
                    {"VALNMR", 5.0}};
    QCOMPARE(lightDescription(l), std::string("Fl(2)R 6s 12m 5M"));
    l.attributes = {
        {"LITCHR", std::int64_t{7}}, {"COLOUR", std::vector<std::int64_t>{1, 3, 4}}, {"SIGPER", 4.0}};
    QCOMPARE(lightDescription(l), std::string("Iso WRG 4s"));
    l.attributes = {{"LITCHR", std::int64_t{4}},
                    {"SIGGRP", std::string("(9)")},
                    {"COLOUR", std::int64_t{1}},
                    {"SIGPER", 15.0}};
    QCOMPARE(lightDescription(l), std::string("Q(9) 15s"));  // a lone white is not written
    l.attributes = {{"COLOUR", std::int64_t{1}}};
    QCOMPARE(lightDescription(l), std::string());
    // Unknown procedures and centre symbols are named errors, not silent defaults.
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             PortrayalTable::parse(R"({"rules": [{"class": "X", "primitive": "point",
                               "procedure": "sparkle", "category": "base"}]})"));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             PortrayalTable::parse(R"({"rules": [{"class": "X", "primitive": "area",
                               "symbol_at_centre": "unicorn", "category": "base"}]})"));
  }
  void aCachedImageFollowsPanAndZoom() {
    // GIVEN an image rendered for one view, with a marker pixel
    const Viewport before({47.27, -122.43}, 20000, 400, 300);
    QImage cached(400, 300, QImage::Format_ARGB32_Premultiplied);
    cached.fill(Qt::white);
    cached.setPixel(100, 100, qRgb(255, 0, 0));
    // WHEN the view is dragged 37 px right and 23 px up, THEN the marker moves with it
    const ScreenPoint c = before.toScreen(before.centre());
    const Viewport panned(before.toLatLon({c.x - 37, c.y + 23}), 20000, 400, 300);
    QImage out(400, 300, QImage::Format_ARGB32_Premultiplied);
    {
      QPainter p(&out);
      drawFromCache(p, cached, before, panned, Qt::gray);
    }
    QCOMPARE(out.pixel(137, 77), qRgb(255, 0, 0));
    QCOMPARE(out.pixel(10, 290), QColor(Qt::gray).rgb());  // uncovered strip: the background
    // WHEN zoomed in twice about the centre, THEN a point 50 px right of the centre is 100 px right
    QImage dot(400, 300, QImage::Format_ARGB32_Premultiplied);
    dot.fill(Qt::white);
    for (int y = 148; y <= 152; ++y)
      for (int x = 248; x <= 252; ++x) dot.setPixel(x, y, qRgb(0, 0, 255));
    const Viewport zoomed(before.centre(), 10000, 400, 300);
    {
      QPainter p(&out);
      drawFromCache(p, dot, before, zoomed, Qt::gray);
    }
    QCOMPARE(qBlue(out.pixel(300, 150)), 255);
    QVERIFY(qRed(out.pixel(300, 150)) < 40);
    QCOMPARE(out.pixel(250, 150), qRgb(255, 255, 255));
  }
  void aRendererReusesPreparedCellsAndCanBeCancelled() {
    if (!std::filesystem::is_directory(kEnc)) QSKIP("../shared/data/enc is absent");
    const std::vector<CellPtr> cells{loadCell(kEnc + "/US5WA22M/US5WA22M.000")};
    const Viewport view({47.272, -122.425}, 20000, 600, 400);
    QImage once(600, 400, QImage::Format_ARGB32_Premultiplied),
        twice(600, 400, QImage::Format_ARGB32_Premultiplied);
    renderChart(once, cells, view, MarinerSettings{});
    ChartRenderer r;
    r.render(twice, cells, view, MarinerSettings{});
    QCOMPARE(r.preparedCount(), std::size_t{1});
    r.render(twice, cells, view, MarinerSettings{});
    QCOMPARE(r.preparedCount(), std::size_t{1});
    QCOMPARE(twice, once);  // the prepared cell draws exactly what a fresh one does
    std::atomic<bool> cancel{true};
    QVERIFY(r.render(twice, cells, view, MarinerSettings{}, &cancel).cancelled);
    r.retainOnly({});
    QCOMPARE(r.preparedCount(), std::size_t{0});
  }
  void rendersLandWaterPalettesAndCategories() {
    if (!std::filesystem::is_directory(kEnc)) QSKIP("../shared/data/enc is absent");
    const std::vector<CellPtr> cells{loadCell(kEnc + "/US5WA22M/US5WA22M.000")};
    const Viewport view({47.272, -122.425}, 20000, 1200, 800);
    QImage day(1200, 800, QImage::Format_ARGB32_Premultiplied);
    MarinerSettings s;
    const RenderStats st = renderChart(day, cells, view, s);
    QCOMPARE(st.cellsDrawn, 1);
    QVERIFY(st.featuresDrawn > 500);
    // Land south-west of Commencement Bay, water in the middle of the bay.
    QCOMPARE(day.pixel(100, 700) & 0xFFFFFF, rgbOf(Palette::Day, "LANDA") & 0xFFFFFF);
    const QRgb water = day.pixel(300, 150) & 0xFFFFFF;
    QVERIFY(water == (rgbOf(Palette::Day, "DEPMD") & 0xFFFFFF) ||
            water == (rgbOf(Palette::Day, "DEPMS") & 0xFFFFFF) ||
            water == (rgbOf(Palette::Day, "DEPDW") & 0xFFFFFF));
    // Night differs from day and is dark.
    QImage night(1200, 800, QImage::Format_ARGB32_Premultiplied);
    s.palette = Palette::Night;
    renderChart(night, cells, view, s);
    QCOMPARE(night.pixel(100, 700) & 0xFFFFFF, rgbOf(Palette::Night, "LANDA") & 0xFFFFFF);
    QVERIFY(qGray(night.pixel(300, 150)) < 30);
    // Soundings only in the "all" category.
    s.palette = Palette::Day;
    const Viewport close({47.268, -122.43}, 8000, 900, 600);
    QImage all(900, 600, QImage::Format_ARGB32_Premultiplied),
        base(900, 600, QImage::Format_ARGB32_Premultiplied);
    s.category = DisplayCategory::Other;
    const RenderStats sa = renderChart(all, cells, close, s);
    s.category = DisplayCategory::Base;
    const RenderStats sb = renderChart(base, cells, close, s);
    QVERIFY(sb.featuresDrawn < sa.featuresDrawn);
    // Around every visible sounding the "all" picture has dark text pixels that "base" lacks.
    int checked = 0, withText = 0;
    for (const auto& f : cells[0]->features()) {
      if (f.objectClass != "SOUNDG") continue;
      for (const auto& ll : f.geometry.parts[0]) {
        const ScreenPoint sp = close.toScreen(ll);
        if (sp.x < 20 || sp.y < 20 || sp.x > 880 || sp.y > 580) continue;
        ++checked;
        int darkAll = 0, darkBase = 0;
        for (int dy = -4; dy <= 4; ++dy)
          for (int dx = -6; dx <= 6; ++dx) {
            darkAll += qGray(all.pixel(static_cast<int>(sp.x) + dx, static_cast<int>(sp.y) + dy)) < 150;
            darkBase += qGray(base.pixel(static_cast<int>(sp.x) + dx, static_cast<int>(sp.y) + dy)) < 150;
          }
        withText += darkAll > darkBase + 3;
      }
    }
    QVERIFY(checked > 50);
    QVERIFY2(withText > 0.8 * checked, qPrintable(QString("%1 of %2").arg(withText).arg(checked)));
    QVERIFY(sa.overscale > 1.5);  // 1:15000 cell shown at 1:8000
  }
  void areaNamesAreWrittenOnce() {
    // NOAA encodes an anchorage as an ACHARE and a SEAARE with the same ring and OBJNAM; both rules
    // write the name, and it used to come out twice, one copy under the other.
    if (!std::filesystem::is_directory(kEnc)) QSKIP("../shared/data/enc is absent");
    MarinerSettings s;
    s.category = DisplayCategory::Other;
    for (const auto& [cell, pair, single] :
         {std::tuple{"US5WA22M", "Commencement Bay General Anchorage", "Dalco Passage"},
          std::tuple{"US5BOSCC", "Boston Harbor, MA Savin Hill Yacht Club Anchorage Area",
                     "Dorchester Bay"}}) {
      const std::vector<CellPtr> cells{loadCell(kEnc + "/" + cell + "/" + cell + ".000")};
      // GIVEN the pair in the cell: two features, one ring, one name
      int named = 0;
      for (const auto& f : cells[0]->features())
        named += f.text("OBJNAM") == std::optional<std::string>(pair) ? 1 : 0;
      QCOMPARE(named, 2);
      // WHEN the whole cell is drawn with every name (SCAMIN not honoured), and a closer view of the
      // anchorage as the chart shows it
      const Viewport whole = fitView(cells[0]->coverageBounds(), 1600, 1100, 0.0, 20.0);
      Bounds anchorage;
      for (const auto& f : cells[0]->features())
        if (f.text("OBJNAM") == std::optional<std::string>(pair)) anchorage.add(f.geometry.bounds);
      const Viewport close = fitView(anchorage, 1200, 800, 0.0, 100.0);
      for (int k = 0; k < 2; ++k) {
        const Viewport& view = k == 0 ? whole : close;
        QImage img(view.width(), view.height(), QImage::Format_ARGB32_Premultiplied);
        s.honourScamin = k == 1;
        const RenderStats st = renderChart(img, cells, view, s);
        // THEN the anchorage's name is written once, a name of one area too
        const auto count = [&st](const char* text) {
          return std::count_if(st.texts.begin(), st.texts.end(),
                               [text](const DrawnText& t) { return t.text == QString::fromUtf8(text); });
        };
        QCOMPARE(count(pair), 1);
        if (k == 0) QCOMPARE(count(single), 1);
        // AND no text is written over (or just under) a copy of itself
        for (std::size_t i = 0; i < st.texts.size(); ++i)
          for (std::size_t j = i + 1; j < st.texts.size(); ++j)
            if (st.texts[i].text == st.texts[j].text)
              QVERIFY2(!st.texts[i].box.adjusted(0, 0, 0, 1).intersects(st.texts[j].box),
                       qPrintable(QString("%1: \"%2\" twice").arg(cell, st.texts[i].text)));
        qInfo("%s at 1:%.0f: %zu texts", cell, view.scaleDenominator(), st.texts.size());
      }
    }
  }
  void theDefaultChartRendersAndSaysItIsFictional() {
    // GIVEN the embedded chart (no ../shared needed) WHEN drawn whole at 1:40 000
    const std::vector<CellPtr> cells{loadCell(std::string(kDefaultChartPath))};
    const Viewport view({49.5, -29.5}, 40000, 1600, 1100);
    QImage img(1600, 1100, QImage::Format_ARGB32_Premultiplied);
    const RenderStats st = renderChart(img, cells, view, MarinerSettings{});
    // THEN the not-for-navigation notice is on screen, land is land and deep water deep
    QVERIFY(st.notForNavigation);
    const auto at = [&](double xKm, double yKm) {
      const ScreenPoint p =
          view.toScreen({49.5 + yKm / 110.57, -29.5 + xKm / (111.32 * std::cos(49.5 * kPi / 180))});
      return img.pixel(static_cast<int>(p.x), static_cast<int>(p.y)) & 0xFFFFFF;
    };
    QCOMPARE(at(-5.0, -5.0), rgbOf(Palette::Day, "LANDA") & 0xFFFFFF);
    QCOMPARE(at(-4.0, 3.0), rgbOf(Palette::Day, "LANDA") & 0xFFFFFF);  // Gannet Island
    QCOMPARE(at(-6.5, 4.0), rgbOf(Palette::Day, "DEPDW") & 0xFFFFFF);
    QCOMPARE(at(-6.0, -3.0 + 0.5 * std::sin(-6.0 / 1.9) + 0.35 * std::sin(-6.0 / 0.7 + 1.0) + 0.04),
             rgbOf(Palette::Day, "DEPVS") & 0xFFFFFF);  // just off the coast: very shallow
  }
  void pickReportsSpeakPlainWords() {
    // GIVEN the default chart WHEN the dangerous wreck is clicked
    const std::vector<CellPtr> cells{loadCell(std::string(kDefaultChartPath))};
    const LatLon wreck{49.5 + 1.8 / 110.57, -29.5 + 2.8 / (111.32 * std::cos(49.5 * kPi / 180))};
    const Viewport view(wreck, 10000, 200, 200);
    const ScreenPoint click = view.toScreen(wreck);
    const auto picked = pickFeatures(cells, view, {click.x + 3, click.y - 2});
    // THEN it comes first, decoded from GDAL's catalogue, and the areas under it follow
    QVERIFY(picked.size() >= 3);
    QCOMPARE(picked[0].objectClass, std::string("WRECKS"));
    QCOMPARE(picked[0].className, std::string("Wreck"));
    const auto value = [](const PickedFeature& f, const std::string& name) {
      for (const auto& a : f.attributes)
        if (a.name == name) return a.value;
      return std::string("(absent)");
    };
    QCOMPARE(value(picked[0], "Category of wreck"), std::string("dangerous wreck"));
    QCOMPARE(value(picked[0], "Value of sounding"), std::string("4.2 m"));
    QVERIFY(std::any_of(picked.begin(), picked.end(), [&](const PickedFeature& f) {
      return f.objectClass == "DEPARE" && value(f, "Depth range value 1") == "30 m";
    }));
    QCOMPARE(picked.back().primitive, std::string("area"));
    // AND far from everything but the areas, no point or line is reported
    const auto open = pickFeatures(cells, view, {click.x + 60, click.y + 60});
    QVERIFY(
        std::all_of(open.begin(), open.end(), [](const PickedFeature& f) { return f.primitive == "area"; }));
    // AND measured values carry their units, enumerations and counts none
    const S57Catalogue& cat = S57Catalogue::installed();
    QCOMPARE(cat.valueText("SIGPER", AttributeValue{4.0}), std::string("4 s"));
    QCOMPARE(cat.valueText("VALNMR", AttributeValue{std::int64_t{5}}), std::string("5 NM"));
    QCOMPARE(cat.valueText("ORIENT", AttributeValue{180.0}), std::string("180°"));
    QCOMPARE(cat.valueText("CATLAM", AttributeValue{std::int64_t{1}}), std::string("port-hand lateral mark"));
    // AND list values are decoded one by one
    QCOMPARE(S57Catalogue::installed().valueText("COLOUR", std::vector<std::int64_t>{2, 6}),
             std::string("black, yellow"));
    // AND a catalogue that is not there is a named error
    QVERIFY_THROWS_EXCEPTION(ChartLoadError, S57Catalogue("/nonexistent"));
  }
  void aKnownBuoyIsDrawn() {
    if (!std::filesystem::is_directory(kEnc)) QSKIP("../shared/data/enc is absent");
    // "Mystic River Island End Point Buoy 4": red conical (BOYSHP 1, COLOUR 3) at 42.3874441 N 71.0547772 W.
    const std::vector<CellPtr> cells{loadCell(kEnc + "/US5BOSDC/US5BOSDC.000")};
    const Viewport view({42.3874441, -71.0547772}, 5000, 400, 400);
    QImage img(400, 400, QImage::Format_ARGB32_Premultiplied);
    renderChart(img, cells, view, MarinerSettings{});
    // Inside the cone, a few pixels above the position.
    QCOMPARE(img.pixel(200, 194) & 0xFFFFFF, rgbOf(Palette::Day, "CHRED") & 0xFFFFFF);
  }
  void theEmbeddedChannelIsBuoyedForIalaA() {
    // GIVEN the embedded chart's buoyed channel (IALA region A, entered southwards) WHEN its lateral
    // marks are decoded with GDAL's own S-57 catalogue
    const std::vector<CellPtr> cells{loadCell(std::string(kDefaultChartPath))};
    const S57Catalogue& catalogue = S57Catalogue::installed();
    int red = 0, green = 0;
    for (const auto& f : cells[0]->features()) {
      if (f.objectClass != "BOYLAT") continue;
      const std::string category = catalogue.valueText("CATLAM", f.list("CATLAM"));
      const std::string shape = catalogue.valueText("BOYSHP", f.list("BOYSHP"));
      // THEN red marks are port-hand cans and green marks starboard-hand cones
      if (f.list("COLOUR") == std::vector<std::int64_t>{3}) {
        ++red;
        QCOMPARE(category, std::string("port-hand lateral mark"));
        QCOMPARE(shape, std::string("can (cylindrical)"));
      } else {
        ++green;
        QCOMPARE(f.list("COLOUR"), std::vector<std::int64_t>{4});
        QCOMPARE(category, std::string("starboard-hand lateral mark"));
        QCOMPARE(shape, std::string("conical (nun, ogival)"));
      }
    }
    QCOMPARE(red, 5);
    QCOMPARE(green, 5);
  }
};

int main(int argc, char** argv) {
  qputenv("QT_QPA_PLATFORM", "offscreen");
  QGuiApplication app(argc, argv);
  TestChartRender t;
  return QTest::qExec(&t, argc, argv);
}
#include "tst_chart_render.moc"
