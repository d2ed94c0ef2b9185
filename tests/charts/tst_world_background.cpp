// GIVEN / WHEN / THEN behaviour of the world background (issue 18; docs/charts.md, "World background"):
// GSHHG's binned shorelines decoded and assembled into land and water, checked against geography we
// did not take from the file (where the continents, oceans and lakes are, the share of the globe that
// is land); damaged files named with the variable at fault; the background rendered under the cells,
// with and without the data, to PNGs in screenshots/ (build/ci/tests/screenshots/) to look at.
//
// The GSHHG files come from Debian's gmt-gshhg-low (scripts/bootstrap.sh installs it); tests that need
// them skip, saying so, when it is absent. The decoder's own cases run on arrays made here.
#include <gdal_priv.h>

#include <QDir>
#include <QGuiApplication>
#include <QImage>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "charts/render/chart_renderer.h"
#include "charts/render/viewport.h"
#include "charts/s57/gdal_variables.h"
#include "charts/s57/s57_loader.h"
#include "charts/world/graticule.h"
#include "charts/world/gshhg.h"
#include "charts/world/world_data.h"
#include "common/angles.h"
#include "common/rng.h"
#include "io/text_format.h"
#include "support/compare_near.h"

using namespace reckoner::charts;
using namespace reckoner::charts::world;
using reckoner::degToRad;
using reckoner::kPi;

namespace {

const std::string kEnc = RECKONER_SHARED_DIR "/data/enc";
const std::string kSystemDir = "/usr/share/gmt-gshhg";

std::string systemFile(char letter) {
  return kSystemDir + "/binned_GSHHS_" + letter + ".nc";
}

#define REQUIRE_GSHHG(letter)                                                                                \
  if (!std::filesystem::exists(systemFile(letter)))                                                          \
  QSKIP(qPrintable(QString::fromStdString(systemFile(letter) + " is absent: install Debian's gmt-gshhg-low " \
                                                               "(scripts/bootstrap.sh deps does)")))

/// The share of the sphere that is land by the areas: odd levels add, even levels (lakes, ponds)
/// take away. Each ring's area on the unit sphere by the trapezoids between its edges and the pole
/// axis, sum over edges of (lon2 - lon1) (sin lat1 + sin lat2) / 2, exact along meridians and close
/// for short edges.
double landFraction(const Shoreline& s) {
  double land = 0.0;
  for (const ShoreBin& b : s.bins())
    for (const ShoreArea& a : b.areas) {
      double area = 0.0;
      for (std::size_t i = 0, j = a.ring.size() - 1; i < a.ring.size(); j = i++)
        area += degToRad(a.ring[i].lonDeg - a.ring[j].lonDeg) *
                (std::sin(degToRad(a.ring[i].latDeg)) + std::sin(degToRad(a.ring[j].latDeg))) / 2.0;
      land += (a.level % 2 == 1 ? 1.0 : -1.0) * std::abs(area);
    }
  return land / (4.0 * kPi);
}

struct Place {
  const char* name;
  LatLon at;
};
// Independent geography: the middle of continents, oceans and large lakes.
const Place kLand[] = {
    {"central Kansas", {38.5, -98.5}},      {"the Sahara", {23.0, 10.0}},
    {"interior Australia", {-25.0, 134.0}}, {"Siberia", {62.0, 100.0}},
    {"interior Antarctica", {-82.0, 30.0}}, {"interior Greenland", {72.0, -40.0}},
    {"the Amazon basin", {-5.0, -62.0}},    {"Manitoulin Island (in Lake Huron)", {45.75, -82.2}}};
const Place kWater[] = {
    {"the mid-Atlantic", {30.0, -40.0}},       {"the mid-Pacific", {5.0, -150.0}},
    {"the Indian Ocean", {-20.0, 80.0}},       {"the middle of the Caspian (a lake)", {41.5, 50.8}},
    {"Lake Superior (a lake)", {47.5, -86.5}}, {"the Southern Ocean", {-60.0, 20.0}},
    {"Lake Baikal (a lake)", {53.5, 108.2}}};

/// A tiny file made here: 2 bins of 180 degrees. Bin 0 (0-180 E) is crossed by one coast from its
/// south side to its north side at x = 20000 of 65535, land on its left (west) as in GSHHG, and holds
/// a closed lake ring on the land; bin 1 (180-360 E) has no segment and corner level `bin1Level`.
reckoner::charts::gdalio::IntegerVariables tinyFile(int bin1Level = 1) {
  reckoner::charts::gdalio::IntegerVariables v;
  v["Bin_size_in_minutes"] = {10800};
  v["N_bins_in_360_longitude_range"] = {2};
  v["N_bins_in_180_degree_latitude_range"] = {1};
  v["N_bins_in_file"] = {2};
  v["N_segments_in_file"] = {2};
  v["N_points_in_file"] = {8};
  v["Id_of_first_segment_in_a_bin"] = {0, 2};
  v["N_segments_in_a_bin"] = {2, 0};
  v["Embedded_node_levels_in_a_bin"] = {0, bin1Level << 9 | bin1Level << 6 | bin1Level << 3 | bin1Level};
  const auto info = [](int points, int level, int entry, int exit) {
    return points << 9 | level << 6 | entry << 3 | exit;
  };
  v["Embedded_npts_levels_exit_entry_for_a_segment"] = {info(3, 1, 0, 2), info(5, 2, 4, 4)};
  v["Id_of_first_point_in_a_segment"] = {0, 3};
  // Coast: (20000, 0) -> (25000, 30000) -> (20000, 65535). Lake: a square 2000-8000 x 30000-36000.
  // Stored as 16-bit signed values, as in the file (65535 is -1).
  v["Relative_longitude_from_SW_corner_of_bin"] = {20000, 25000, 20000, 2000, 8000, 8000, 2000, 2000};
  v["Relative_latitude_from_SW_corner_of_bin"] = {0, 30000, -1, 30000, 30000, 36000, 36000, 30000};
  return v;
}

/// The reason a load fails with, or "" when it does not.
template <typename F>
std::string failure(F&& load) {
  try {
    load();
  } catch (const ChartLoadError& e) {
    return e.what();
  }
  return {};
}

/// Writes `v` as a netCDF file through GDAL's multidimensional API (each variable with a dimension of
/// its own length), the format binned_GSHHS_*.nc has.
void writeNetcdf(const std::string& path, const reckoner::charts::gdalio::IntegerVariables& v) {
  GDALAllRegister();
  GDALDriver* driver = GetGDALDriverManager()->GetDriverByName("netCDF");
  QVERIFY(driver);
  std::unique_ptr<GDALDataset> ds(driver->CreateMultiDimensional(path.c_str(), nullptr, nullptr));
  QVERIFY(ds);
  const auto root = ds->GetRootGroup();
  const GDALExtendedDataType int32 = GDALExtendedDataType::Create(GDT_Int32);
  for (const auto& [name, values] : v) {
    const auto dim = root->CreateDimension("n_" + name, std::string(), std::string(), values.size());
    const auto array = root->CreateMDArray(name, {dim}, int32);
    QVERIFY(array);
    const GUInt64 start = 0;
    const std::size_t count = values.size();
    QVERIFY(array->Write(&start, &count, nullptr, nullptr, int32, values.data()));
  }
}

/// The screen point of a place in a view, as integer pixel coordinates.
QPoint pixelOf(const Viewport& v, const LatLon& p) {
  const ScreenPoint s = v.toScreen(p);
  return {static_cast<int>(std::floor(s.x)), static_cast<int>(std::floor(s.y))};
}

int distance(QRgb a, QRgb b) {
  return std::abs(qRed(a) - qRed(b)) + std::abs(qGreen(a) - qGreen(b)) + std::abs(qBlue(a) - qBlue(b));
}

QRgb rgbOf(Palette p, const char* token) {
  const Rgb c = defaultColours().colour(p, token);
  return qRgb(c.r, c.g, c.b);
}

void saveShot(const QImage& image, const QString& name) {
  QDir().mkpath(QStringLiteral("screenshots"));
  const QString path = QStringLiteral("screenshots/%1.png").arg(name);
  QVERIFY(image.save(path));
  qInfo("screenshot: %s", qPrintable(QDir::current().absoluteFilePath(path)));
}

/// Points the data directory at `dir` while alive ("" for the installed package).
class DataDir {
 public:
  explicit DataDir(const QString& dir) {
    if (dir.isEmpty())
      qunsetenv("RECKONER_GSHHG_DIR");
    else
      qputenv("RECKONER_GSHHG_DIR", dir.toUtf8());
  }
  ~DataDir() { qunsetenv("RECKONER_GSHHG_DIR"); }
  DataDir(const DataDir&) = delete;
  DataDir& operator=(const DataDir&) = delete;
};

const Viewport kWorldView({20.0, 0.0}, 1.25e8, 1024, 800);
const Viewport kTacomaView({47.27, -122.45}, 700000, 1024, 768);

}  // namespace

class TestWorldBackground : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() { qunsetenv("RECKONER_GSHHG_DIR"); }

  void crudeAndLowShowLandAndWaterWhereTheyAre() {
    REQUIRE_GSHHG('c');
    REQUIRE_GSHHG('l');
    for (const char letter : {'c', 'l'}) {
      const Shoreline s =
          loadGshhg(systemFile(letter), letter == 'c' ? ShoreResolution::Crude : ShoreResolution::Low);
      QCOMPARE(s.binSizeDeg() * s.columns(), 360.0);
      QCOMPARE(s.binSizeDeg() * s.rows(), 180.0);
      for (const Place& p : kLand) QVERIFY2(s.isLand(p.at), p.name);
      for (const Place& p : kWater) QVERIFY2(!s.isLand(p.at), p.name);
      // The same places a whole turn of longitude away.
      QVERIFY(s.isLand({38.5, -98.5 + 360.0}));
      QVERIFY(!s.isLand({30.0, -40.0 - 360.0}));
    }
    // The Caspian lies inside one bin of 20 degrees at crude resolution: a lake ring of level 2.
    QCOMPARE(loadGshhg(systemFile('c'), ShoreResolution::Crude).levelAt({41.5, 50.8}), 2);
  }

  void lowResolutionSeparatesPugetSoundFromTheOlympicPeninsula() {
    REQUIRE_GSHHG('l');
    const Shoreline s = loadGshhg(systemFile('l'), ShoreResolution::Low);
    QVERIFY2(!s.isLand({47.6, -122.45}), "Puget Sound, off Seattle");
    QVERIFY2(s.isLand({47.8, -123.6}), "the Olympic peninsula");
    QVERIFY2(s.isLand({47.25, -122.0}), "east of Tacoma");
    QVERIFY2(!s.isLand({47.0, -125.5}), "the Pacific off the Washington coast");
    // A bin that no shoreline crosses is filled whole by its corners' level: one four-corner ring.
    const ShoreBin& sahara = s.binAt({23.0, 10.0});
    QCOMPARE(sahara.lines.size(), std::size_t{0});
    QCOMPARE(sahara.areas.size(), std::size_t{1});
    QCOMPARE(sahara.areas[0].ring.size(), std::size_t{4});
  }

  void aboutTwentyNinePercentOfTheGlobeIsLand() {
    REQUIRE_GSHHG('c');
    REQUIRE_GSHHG('l');
    // 29.2% of the Earth's surface is land (148.9 of 510.1 million km2), Antarctica's ice included.
    for (const auto& [letter, r] : {std::pair{'c', ShoreResolution::Crude}, {'l', ShoreResolution::Low}}) {
      const double f = landFraction(loadGshhg(systemFile(letter), r));
      qInfo("land fraction at %c: %.4f", letter, f);
      QVERIFY2(f > 0.25 && f < 0.33, qPrintable(QString("%1: %2").arg(letter).arg(f)));
    }
  }

  void theDecoderAssemblesLandOnTheLeftOfEachSegment() {
    const Shoreline s = decodeGshhg(tinyFile(), "tiny.nc", ShoreResolution::Crude);
    QCOMPARE(s.bins().size(), std::size_t{2});
    // Bin 0: land west of the coast (x < 20000 of 65535, about 55 degrees east), the lake on it.
    QCOMPARE(s.levelAt({-45.0, 10.0}), 1);
    QCOMPARE(s.levelAt({0.0, 120.0}), 0);
    const double lakeLon = 5000.0 / 65535.0 * 180.0, lakeLat = 33000.0 / 65535.0 * 180.0 - 90.0;
    QCOMPARE(s.levelAt({lakeLat, lakeLon}), 2);
    QVERIFY(!s.isLand({lakeLat, lakeLon}));
    // The land ring: the coast, then the boundary counter-clockwise from its exit: NW, SW corners.
    const ShoreArea& land = s.bins()[0].areas[0];
    QCOMPARE(land.level, 1);
    QCOMPARE(land.ring.size(), std::size_t{5});
    RK_COMPARE_NEAR(land.ring[3].lonDeg, 0.0, 1e-12);
    RK_COMPARE_NEAR(land.ring[3].latDeg, 90.0, 1e-12);
    RK_COMPARE_NEAR(land.ring[4].latDeg, -90.0, 1e-12);
    QCOMPARE(s.bins()[0].lines.size(), std::size_t{2});
    // Bin 1: no segment; its corners say land, or sea.
    QCOMPARE(s.levelAt({10.0, 250.0}), 1);
    QCOMPARE(s.levelAt({10.0, -110.0}), 1);
    QCOMPARE(decodeGshhg(tinyFile(0), "tiny.nc", ShoreResolution::Crude).levelAt({10.0, 250.0}), 0);
  }

  void badValuesAreNamedWithTheVariable() {
    const auto broken = [](const char* name, auto change) {
      auto v = tinyFile();
      change(v[name]);
      return failure([&] { decodeGshhg(v, "tiny.nc", ShoreResolution::Crude); });
    };
    using Values = std::vector<std::int32_t>;
    const std::string beyond = broken("Id_of_first_point_in_a_segment", [](Values& a) { a[1] = 7; });
    QVERIFY2(beyond.find("tiny.nc: variable 'Id_of_first_point_in_a_segment'") == 0, beyond.c_str());
    QVERIFY2(beyond.find("the file holds 8") != std::string::npos, beyond.c_str());
    const std::string cut =
        broken("Relative_latitude_from_SW_corner_of_bin", [](Values& a) { a.pop_back(); });
    QVERIFY2(
        cut.find(
            "variable 'Relative_latitude_from_SW_corner_of_bin': holds 7 values, N_points_in_file says 8") !=
            std::string::npos,
        cut.c_str());
    const std::string side =
        broken("Embedded_npts_levels_exit_entry_for_a_segment", [](Values& a) { a[0] |= 7; });
    QVERIFY2(
        side.find("'Embedded_npts_levels_exit_entry_for_a_segment': segment 0 (bin 0)") != std::string::npos,
        side.c_str());
    const std::string off = broken("Relative_latitude_from_SW_corner_of_bin", [](Values& a) { a[2] = 100; });
    QVERIFY2(off.find("not on its entry and exit sides") != std::string::npos, off.c_str());
    const std::string bins = broken("N_segments_in_a_bin", [](Values& a) { a[1] = 5; });
    QVERIFY2(bins.find("'Id_of_first_segment_in_a_bin': bin 1 holds segments 2 to 7") != std::string::npos,
             bins.c_str());
    const std::string size = broken("Bin_size_in_minutes", [](Values& a) { a[0] = 7; });
    QVERIFY2(size.find("'Bin_size_in_minutes': 7 does not divide 180 degrees") != std::string::npos,
             size.c_str());
    auto missing = tinyFile();
    missing.erase("N_segments_in_a_bin");
    const std::string gone = failure([&] { decodeGshhg(missing, "tiny.nc", ShoreResolution::Crude); });
    QCOMPARE(QString::fromStdString(gone), QString("tiny.nc: has no variable 'N_segments_in_a_bin'"));
  }

  void damagedFilesGiveAClearErrorNamingTheFileAndTheVariable() {
    REQUIRE_GSHHG('c');
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    // GIVEN the crude file cut at half its length WHEN it is loaded THEN the error names the file.
    const std::string cut = dir.filePath("binned_GSHHS_c.nc").toStdString();
    {
      std::ifstream in(systemFile('c'), std::ios::binary);
      const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      std::ofstream(cut, std::ios::binary)
          .write(bytes.data(), static_cast<std::streamsize>(bytes.size() / 2));
    }
    const std::string truncated = failure([&] { loadGshhg(cut, ShoreResolution::Crude); });
    QVERIFY2(truncated.find(cut + ": cannot be opened as netCDF") == 0, truncated.c_str());
    // GIVEN a netCDF copy whose point latitudes stop short WHEN loaded THEN the variable is named.
    auto v = reckoner::charts::gdalio::readIntegerVariables(systemFile('c'), gshhgRequiredVariables(),
                                                            gshhgOptionalVariables());
    QVERIFY(decodeGshhg(v, "copy", ShoreResolution::Crude).vertexCount() > 10000);
    auto& lat = v["Relative_latitude_from_SW_corner_of_bin"];
    lat.resize(lat.size() / 2);
    const std::string shortened = dir.filePath("binned_GSHHS_l.nc").toStdString();
    writeNetcdf(shortened, v);
    const std::string why = failure([&] { loadGshhg(shortened, ShoreResolution::Low); });
    QVERIFY2(why.find(shortened + ": variable 'Relative_latitude_from_SW_corner_of_bin': holds 7069 values, "
                                  "N_points_in_file says 14138") == 0,
             why.c_str());
    // A variable left out is named too.
    v.erase("Embedded_node_levels_in_a_bin");
    const std::string without = dir.filePath("binned_GSHHS_i.nc").toStdString();
    writeNetcdf(without, v);
    const std::string gone = failure([&] { loadGshhg(without, ShoreResolution::Intermediate); });
    QVERIFY2(gone.find(without + ": has no variable 'Embedded_node_levels_in_a_bin'") == 0, gone.c_str());
    // WHEN a view renders over those files THEN it falls back to water and the graticule, the problem
    // named, and nothing crashes.
    const DataDir data(dir.path());
    QImage image(kWorldView.width(), kWorldView.height(), QImage::Format_ARGB32_Premultiplied);
    ChartRenderer renderer;
    const RenderStats st = renderer.render(image, {}, kWorldView, MarinerSettings{});
    QCOMPARE(st.worldResolution, '\0');
    QVERIFY2(st.worldProblem.find(cut + ": cannot be opened as netCDF") == 0, st.worldProblem.c_str());
    QCOMPARE(image.pixel(pixelOf(kWorldView, {38.5, -98.5})),
             image.pixel(pixelOf(kWorldView, {30.0, -40.0})));
  }

  void mutatedFilesAreDecodedOrRefusedNeverACrash() {
    REQUIRE_GSHHG('c');
    // GIVEN the crude file's variables WHEN 400 copies each have a few values changed (fixed seed:
    // bit flips, values set to 0, -1, huge or a neighbour's, arrays cut) THEN each decodes or is
    // refused with a line naming the file, and nothing crashes or hangs.
    const auto original = reckoner::charts::gdalio::readIntegerVariables(
        systemFile('c'), gshhgRequiredVariables(), gshhgOptionalVariables());
    reckoner::Rng rng(18, 1);
    const auto pick = [&rng](std::size_t n) {
      return static_cast<std::size_t>(rng.uniform() * static_cast<double>(n));
    };
    int refused = 0;
    for (int k = 0; k < 400; ++k) {
      auto v = original;
      for (int m = 0; m < 3; ++m) {
        auto it = std::next(v.begin(), static_cast<std::ptrdiff_t>(pick(v.size())));
        std::vector<std::int32_t>& a = it->second;
        if (a.empty()) continue;
        std::int32_t& x = a[pick(a.size())];
        switch (pick(5)) {
          case 0:
            x ^= static_cast<std::int32_t>(1U << pick(31));
            break;
          case 1:
            x = 0;
            break;
          case 2:
            x = -1;
            break;
          case 3:
            x = 0x7fffffff;
            break;
          default:
            a.resize(pick(a.size()));
            break;
        }
      }
      try {
        const Shoreline s = decodeGshhg(v, "mutated.nc", ShoreResolution::Crude);
        QCOMPARE(s.bins().size(), static_cast<std::size_t>(s.columns() * s.rows()));
      } catch (const ChartLoadError& e) {
        ++refused;
        QVERIFY2(std::string(e.what()).find("mutated.nc: ") == 0, e.what());
        QVERIFY2(std::string(e.what()).find('\n') == std::string::npos, e.what());
      }
    }
    qInfo("%d of 400 mutated copies refused", refused);
    QVERIFY(refused > 100);
  }

  void graticuleIntervalsAreRoundAndLabelsShort() {
    // One degree 3 px long (a world view): 45 degrees; 200 px: 1 degree; 1 px per minute: 2 degrees.
    QCOMPARE(graticuleStepSeconds(2.8), 45 * 3600);
    QCOMPARE(graticuleStepSeconds(200.0), 3600);
    QCOMPARE(graticuleStepSeconds(60.0), 2 * 3600);
    QCOMPARE(graticuleStepSeconds(1e6), 1);
    // Tacoma at 1:700 000: a degree of longitude is 75.5 km there, 385 px; lines 20' apart, 128 px.
    const double pxPerDegree =
        kTacomaView.toScreen({47.27, -121.45}).x - kTacomaView.toScreen({47.27, -122.45}).x;
    RK_COMPARE_NEAR(pxPerDegree, 6378137.0 * degToRad(1.0) * std::cos(degToRad(47.27)) / (700000 * 0.00028),
                    1e-6);
    QCOMPARE(graticuleStepSeconds(pxPerDegree), 1200);
    const std::vector<double> lats = graticuleValues(46.61, 47.93, 1200);
    QCOMPARE(lats.size(), std::size_t{4});
    RK_COMPARE_NEAR(lats.front(), 46.0 + 40.0 / 60.0, 1e-12);
    RK_COMPARE_NEAR(lats.back(), 47.0 + 40.0 / 60.0, 1e-12);
    QCOMPARE(graticuleValues(-180.0, 180.0, 45 * 3600).size(), std::size_t{9});
    QCOMPARE(graticuleValues(0.0, 100.0, 1, 50).size(), std::size_t{50});
    using reckoner::io::formatLatitudeLabel;
    using reckoner::io::formatLongitudeLabel;
    QCOMPARE(QString::fromStdString(formatLatitudeLabel(47.0)), QString("47°N"));
    QCOMPARE(QString::fromStdString(formatLatitudeLabel(-47.125)), QString("47°07'30\"S"));
    QCOMPARE(QString::fromStdString(formatLatitudeLabel(0.0)), QString("0°"));
    QCOMPARE(QString::fromStdString(formatLongitudeLabel(-122.5)), QString("122°30'W"));
    QCOMPARE(QString::fromStdString(formatLongitudeLabel(180.0)), QString("180°"));
    QCOMPARE(QString::fromStdString(formatLongitudeLabel(-180.0)), QString("180°"));
    QCOMPARE(QString::fromStdString(formatLongitudeLabel(225.0)), QString("135°W"));
    QCOMPARE(QString::fromStdString(formatLongitudeLabel(59.99999)), QString("60°E"));
  }

  void viewsChooseTheirResolutionFromTheirScale() {
    QCOMPARE(resolutionFor(kWorldView.metresPerPixel()), ShoreResolution::Crude);
    QCOMPARE(resolutionFor(Viewport({47.0, -122.0}, 3e6, 800, 600).metresPerPixel()), ShoreResolution::Low);
    QCOMPARE(resolutionFor(kTacomaView.metresPerPixel()), ShoreResolution::Intermediate);
    const DataDir data(QStringLiteral("/nowhere"));
    QCOMPARE(QString::fromStdString(gshhgPath(ShoreResolution::Low)), QString("/nowhere/binned_GSHHS_l.nc"));
  }

  void theWorldViewShowsLandAndWaterWithTheDataAndWaterWithout() {
    REQUIRE_GSHHG('c');
    QTemporaryDir empty;
    for (const bool withData : {true, false}) {
      const DataDir data(withData ? QString() : empty.path());
      QImage image(kWorldView.width(), kWorldView.height(), QImage::Format_ARGB32_Premultiplied);
      ChartRenderer renderer;
      const RenderStats st = renderer.render(image, {}, kWorldView, MarinerSettings{});
      saveShot(image, withData ? "world_background_world" : "world_background_world_no_data");
      const QRgb water = image.pixel(pixelOf(kWorldView, kWater[0].at));
      for (const Place& p : kWater)
        if (std::abs(p.at.latDeg) < 80) QVERIFY2(image.pixel(pixelOf(kWorldView, p.at)) == water, p.name);
      const QRgb land = image.pixel(pixelOf(kWorldView, kLand[0].at));
      for (const Place& p : {kLand[0], kLand[1], kLand[2], kLand[3]})
        QVERIFY2(image.pixel(pixelOf(kWorldView, p.at)) == (withData ? land : water), p.name);
      // Neither tone is an ENC's: not LANDA, not DEPDW, not NODTA; land leans to LANDA, water to DEPDW.
      for (const char* token : {"LANDA", "DEPDW", "NODTA"}) {
        QVERIFY(distance(land, rgbOf(Palette::Day, token)) > 12);
        QVERIFY(distance(water, rgbOf(Palette::Day, token)) > 12);
      }
      if (withData) {
        QVERIFY(distance(land, rgbOf(Palette::Day, "LANDA")) < distance(land, rgbOf(Palette::Day, "DEPDW")));
        QVERIFY(distance(water, rgbOf(Palette::Day, "DEPDW")) <
                distance(water, rgbOf(Palette::Day, "LANDA")));
        QCOMPARE(st.worldResolution, 'c');
        QVERIFY(st.worldProblem.empty());
        QVERIFY(st.worldBinsDrawn >= 162);  // every bin of 20 degrees is in view, some twice
      } else {
        QCOMPARE(st.worldResolution, '\0');
        QVERIFY2(st.worldProblem.find(empty.path().toStdString() + "/binned_GSHHS_c.nc: no such file") == 0,
                 st.worldProblem.c_str());
      }
      // The graticule: the equator and the Greenwich meridian, 45 degrees apart from the others.
      const QPoint origin = pixelOf(kWorldView, {0.0, 0.0});
      QVERIFY(image.pixel(origin.x() + 30, origin.y()) != water ||
              image.pixel(origin.x() + 30, origin.y() - 1) != water);
      QVERIFY(image.pixel(origin.x(), origin.y() - 30) != water ||
              image.pixel(origin.x() - 1, origin.y() - 30) != water);
    }
  }

  void tacomaAtOneToSevenHundredThousand() {
    REQUIRE_GSHHG('i');
    QImage image(kTacomaView.width(), kTacomaView.height(), QImage::Format_ARGB32_Premultiplied);
    ChartRenderer renderer;
    const RenderStats st = renderer.render(image, {}, kTacomaView, MarinerSettings{});
    saveShot(image, "world_background_tacoma");
    QCOMPARE(st.worldResolution, 'i');
    QVERIFY(st.worldBinsDrawn >= 1 && st.worldBinsDrawn <= 4);
    const QRgb land = image.pixel(pixelOf(kTacomaView, {47.8, -123.6}));    // the Olympic peninsula
    const QRgb water = image.pixel(pixelOf(kTacomaView, {47.6, -122.42}));  // Puget Sound off Seattle
    QVERIFY(land != water);
    QCOMPARE(image.pixel(pixelOf(kTacomaView, {47.05, -122.8})), land);    // south of Olympia
    QCOMPARE(image.pixel(pixelOf(kTacomaView, {47.5, -121.6})), land);     // the Cascades' foothills
    QCOMPARE(image.pixel(pixelOf(kTacomaView, {47.35, -122.55})), water);  // Colvos Passage
    QVERIFY(distance(land, rgbOf(Palette::Day, "LANDA")) < distance(land, rgbOf(Palette::Day, "DEPDW")));
    // Night keeps the same geography in night's tones, far darker.
    MarinerSettings night;
    night.palette = Palette::Night;
    renderer.render(image, {}, kTacomaView, night);
    saveShot(image, "world_background_tacoma_night");
    const QRgb nightLand = image.pixel(pixelOf(kTacomaView, {47.8, -123.6}));
    QVERIFY(nightLand != image.pixel(pixelOf(kTacomaView, {47.6, -122.42})));
    QVERIFY(qRed(nightLand) + qGreen(nightLand) + qBlue(nightLand) <
            (qRed(land) + qGreen(land) + qBlue(land)) / 4);
  }

  void cellsCoverTheBackgroundWithinTheirCoverage() {
    REQUIRE_GSHHG('i');
    const std::string path = kEnc + "/US5WA22M/US5WA22M.000";
    if (!std::filesystem::exists(path)) QSKIP("../shared/data/enc is absent");
    const std::vector<CellPtr> cells{loadCell(path)};
    const Viewport view({47.27, -122.45}, 150000, 1024, 768);
    QImage with(view.width(), view.height(), QImage::Format_ARGB32_Premultiplied);
    QImage without(view.width(), view.height(), QImage::Format_ARGB32_Premultiplied);
    ChartRenderer renderer;
    const RenderStats st = renderer.render(with, cells, view, MarinerSettings{});
    saveShot(with, "world_background_tacoma_with_cell");
    renderer.setWorldBackground(false);
    const RenderStats off = renderer.render(without, cells, view, MarinerSettings{});
    QCOMPARE(st.cellsDrawn, 1);
    QCOMPARE(off.worldResolution, '\0');
    // Inside the cell's coverage the two images agree; outside it, the plain one is NODTA and the
    // world background shows land and water.
    const Bounds b = cells[0]->bounds();
    const LatLon inside{(b.minLatDeg + b.maxLatDeg) / 2, (b.minLonDeg + b.maxLonDeg) / 2};
    QCOMPARE(with.pixel(pixelOf(view, inside)), without.pixel(pixelOf(view, inside)));
    const LatLon puyallup{47.19, -122.29};  // land south-east of the cell
    QVERIFY(!b.contains(puyallup));
    QCOMPARE(without.pixel(pixelOf(view, puyallup)), rgbOf(Palette::Day, "NODTA"));
    QVERIFY(with.pixel(pixelOf(view, puyallup)) != rgbOf(Palette::Day, "NODTA"));
  }
};

int main(int argc, char** argv) {
  QGuiApplication app(argc, argv);
  TestWorldBackground t;
  return QTest::qExec(&t, argc, argv);
}

#include "tst_world_background.moc"
