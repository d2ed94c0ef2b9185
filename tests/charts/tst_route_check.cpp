// The route check (charts/route/route_check.h) on a real NOAA cell, US5WA22M (Tacoma, Commencement Bay):
//  - a route across charted land reports land on the leg that crosses it, and only there;
//  - a route over a charted wreck reports the wreck on its leg;
//  - a route down the dredged channel (Blair Waterway, its waypoints as the chart's DRGARE names give
//    them) reports no danger;
//  - on 25 random routes, the findings equal an independent check written here: the cell read through
//    GDAL's OGR directly (not our loader), the hazards classified by this file's own table, each leg's
//    corridor built as a rectangle in UTM (EPSG:32610 through OGR's transformation) and tested with
//    OGR's Intersects. Differences are allowed only for features within 0.5 m of a corridor's edge
//    (the two corridors differ by UTM's scale and the rhumb line's curvature in UTM, centimetres).
#include <QTest>

#include <gdal_priv.h>
#include <ogrsf_frmts.h>

#include <GeographicLib/Geodesic.hpp>
#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <set>
#include <string>
#include <tuple>

#include "charts/route/route_check.h"
#include "charts/s57/s57_loader.h"
#include "common/angles.h"
#include "common/units.h"
#include "support/compare_near.h"
#include "support/route_fixtures.h"

using namespace reckoner;
using namespace reckoner::charts;

namespace {

const std::string kCell = std::string(RECKONER_SHARED_DIR) + "/data/enc/US5WA22M/US5WA22M.000";

geo::Route routeOf(const std::vector<geo::GeoPoint>& points, double xtlNm) {
  return reckoner::test::routeOf(points, xtlNm, "test");
}

geo::GeoPoint offset(const geo::GeoPoint& p, double azimuthDeg, double distM) {
  geo::GeoPoint q;
  GeographicLib::Geodesic::WGS84().Direct(p.latDeg, p.lonDeg, azimuthDeg, distM, q.latDeg, q.lonDeg);
  return q;
}

// ---- the independent check ------------------------------------------------------------------------
using Key = std::tuple<std::size_t, std::string, std::string>;  // leg, LNAM, kind

bool listHas(OGRFeature& f, const char* field, int value) {
  const int i = f.GetFieldIndex(field);
  if (i < 0 || !f.IsFieldSetAndNotNull(i)) return false;
  char** list = f.GetFieldAsStringList(i);
  for (; list && *list; ++list)
    if (std::atoi(*list) == value) return true;
  return false;
}

std::optional<double> real(OGRFeature& f, const char* field) {
  const int i = f.GetFieldIndex(field);
  if (i < 0 || !f.IsFieldSetAndNotNull(i)) return std::nullopt;
  return f.GetFieldAsDouble(i);
}

/// This file's own statement of the hazard rules (docs/routes.md), on OGR's view of a feature.
std::string independentKind(const std::string& layer, OGRFeature& f, double safetyContourM) {
  const OGRwkbGeometryType t = wkbFlatten(f.GetGeometryRef()->getGeometryType());
  const bool polygon = t == wkbPolygon || t == wkbMultiPolygon;
  if (layer == "LNDARE") return "land";
  if (layer == "WRECKS" || layer == "OBSTRN" || layer == "UWTROC") {
    const auto valsou = real(f, "VALSOU");
    const auto watlev = real(f, "WATLEV");
    if ((watlev && (*watlev == 1 || *watlev == 2 || *watlev == 4)) || !valsou || *valsou < safetyContourM)
      return "danger";
    return {};
  }
  if (!polygon) return {};
  if (layer == "DEPARE" || layer == "DRGARE") {
    const auto d = real(f, "DRVAL1");
    return !d || *d < safetyContourM ? "safety_contour" : "";
  }
  if (layer == "UNSARE") return "safety_contour";
  if (layer == "RESARE") {
    if (listHas(f, "RESTRN", 7) || listHas(f, "RESTRN", 14)) return "prohibited_area";
    if (listHas(f, "RESTRN", 8)) return "restricted_area";
    return "special_area";
  }
  if (layer == "MIPARE") return "restricted_area";
  static const std::set<std::string> special = {"ACHARE", "CTNARE", "DMPGRD", "DWRTPT", "ICNARE", "ISTZNE",
                                                "MARCUL", "OSPARE", "PRCARE", "SPLARE", "SUBTLN", "TSEZNE",
                                                "TSSCRS", "TSSLPT", "TSSRON", "TWRTPT"};
  return special.count(layer) ? "special_area" : "";
}

struct IndependentHazard {
  std::string lnam, kind;
  std::unique_ptr<OGRGeometry> utm;
  std::unique_ptr<OGRGeometry> outline;  ///< an area's boundary, else the geometry itself
};

class Independent {
 public:
  explicit Independent(double safetyContourM) {
    GDALAllRegister();
    std::unique_ptr<GDALDataset> ds(static_cast<GDALDataset*>(
        GDALOpenEx(kCell.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr, nullptr, nullptr)));
    if (!ds) qFatal("GDAL cannot open %s", kCell.c_str());
    wgs84_.importFromEPSG(4326);
    wgs84_.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    utm_.importFromEPSG(32610);
    utm_.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    toUtm_.reset(OGRCreateCoordinateTransformation(&wgs84_, &utm_));
    for (OGRLayer* layer : ds->GetLayers()) {
      const std::string name = layer->GetName();
      for (auto& f : *layer) {
        if (!f->GetGeometryRef() || f->GetGeometryRef()->IsEmpty()) continue;
        const std::string kind = independentKind(name, *f, safetyContourM);
        if (kind.empty()) continue;
        std::unique_ptr<OGRGeometry> g(f->GetGeometryRef()->clone());
        if (g->transform(toUtm_.get()) != OGRERR_NONE) qFatal("transform failed");
        const OGRwkbGeometryType t = wkbFlatten(g->getGeometryType());
        std::unique_ptr<OGRGeometry> outline(t == wkbPolygon || t == wkbMultiPolygon ? g->Boundary()
                                                                                     : g->clone());
        hazards_.push_back({f->GetFieldAsString("LNAM"), kind, std::move(g), std::move(outline)});
      }
    }
  }
  OGRPoint utm(const geo::GeoPoint& p) const {
    OGRPoint q(p.lonDeg, p.latDeg);
    q.transform(toUtm_.get());
    return q;
  }
  /// The leg's corridor: a rectangle in UTM, starboard to the right of the leg's direction.
  std::unique_ptr<OGRPolygon> corridor(const geo::Route& r, std::size_t to) const {
    const OGRPoint a = utm(r.waypoints[to - 1].position), b = utm(r.waypoints[to].position);
    const double dx = b.getX() - a.getX(), dy = b.getY() - a.getY(), len = std::hypot(dx, dy);
    const double nx = dy / len, ny = -dx / len;  // to starboard
    const double s = nmToMetres(r.waypoints[to].leg.starboardXtlNm),
                 p = nmToMetres(r.waypoints[to].leg.portXtlNm);
    OGRLinearRing ring;
    ring.addPoint(a.getX() + nx * s, a.getY() + ny * s);
    ring.addPoint(b.getX() + nx * s, b.getY() + ny * s);
    ring.addPoint(b.getX() - nx * p, b.getY() - ny * p);
    ring.addPoint(a.getX() - nx * p, a.getY() - ny * p);
    ring.closeRings();
    auto poly = std::make_unique<OGRPolygon>();
    poly->addRing(&ring);
    return poly;
  }
  /// Findings, and for each hazard its distance to the corridor's edge (for the near-edge allowance).
  std::set<Key> check(const geo::Route& r, std::map<Key, double>& edgeDistance) const {
    std::set<Key> out;
    for (std::size_t to = 1; to < r.waypoints.size(); ++to) {
      const std::unique_ptr<OGRPolygon> c = corridor(r, to);
      const std::unique_ptr<OGRGeometry> edge(c->Boundary());
      for (const auto& h : hazards_) {
        const Key k{to, h.lnam, h.kind};
        edgeDistance[k] = h.outline->Distance(edge.get());
        if (h.utm->Intersects(c.get())) out.insert(k);
      }
    }
    return out;
  }

 private:
  OGRSpatialReference wgs84_, utm_;
  std::unique_ptr<OGRCoordinateTransformation> toUtm_;
  std::vector<IndependentHazard> hazards_;
};

std::set<Key> keysOf(const std::vector<RouteFinding>& findings) {
  std::set<Key> out;
  for (const auto& f : findings) out.insert({f.leg, f.lnam, hazardKindName(f.kind)});
  return out;
}

}  // namespace

class TestRouteCheck : public QObject {
  Q_OBJECT
  CellPtr cell_;

 private slots:
  void initTestCase() { cell_ = loadCell(kCell); }

  void landOnTheRightLeg() {
    const ChartHazards hazards({cell_}, SafetySettings{});
    const geo::Route r = routeOf({{47.300, -122.470}, {47.285, -122.460}, {47.250, -122.470}}, 0.05);
    const std::vector<RouteFinding> f = checkRoute(r, hazards);
    const auto land = [&](std::size_t leg) {
      return std::count_if(f.begin(), f.end(), [&](const RouteFinding& x) {
        return x.leg == leg && x.kind == HazardKind::Land && x.objectClass == "LNDARE";
      });
    };
    QCOMPARE(land(1), 0);
    QVERIFY(land(2) >= 1);
    // the land finding lies on the leg's corridor, south of the shore the leg crosses
    for (const auto& x : f) {
      if (x.kind != HazardKind::Land) continue;
      const geo::LegFix fix = geo::legFix(r, x.leg, {x.position.latDeg, x.position.lonDeg});
      RK_COMPARE_NEAR(fix.crossTrackM, 0.0, nmToMetres(0.05) + 1.0);
      QVERIFY(fix.alongTrackM >= -1.0 && fix.alongTrackM <= fix.legLengthM + 1.0);
    }
    // its pick report names the class in words
    const auto it =
        std::find_if(f.begin(), f.end(), [](const RouteFinding& x) { return x.kind == HazardKind::Land; });
    QCOMPARE(QString::fromStdString(findingReport(hazards, *it).className), QStringLiteral("Land area"));
  }

  void wreckOnItsLeg() {
    const ChartHazards hazards({cell_}, SafetySettings{});
    const ChartFeature* wreck = nullptr;
    for (const auto& f : cell_->features()) {
      if (f.objectClass == "WRECKS" && f.geometry.primitive == Primitive::Point &&
          (!f.number("VALSOU") || *f.number("VALSOU") < 10.0)) {
        wreck = &f;
        break;
      }
    }
    QVERIFY(wreck);
    const LatLon w = wreck->geometry.parts[0][0];
    const geo::GeoPoint at{w.latDeg, w.lonDeg};
    const geo::Route r =
        routeOf({offset(at, 250.0, 1500.0), offset(at, 250.0, 600.0), offset(at, 70.0, 600.0)}, 0.05);
    const std::vector<RouteFinding> f = checkRoute(r, hazards);
    const auto onLeg = [&](std::size_t leg) {
      return std::any_of(f.begin(), f.end(),
                         [&](const RouteFinding& x) { return x.leg == leg && x.lnam == wreck->lnam; });
    };
    QVERIFY(!onLeg(1));
    QVERIFY(onLeg(2));
    const auto it =
        std::find_if(f.begin(), f.end(), [&](const RouteFinding& x) { return x.lnam == wreck->lnam; });
    QCOMPARE(it->kind, HazardKind::Danger);
    QCOMPARE(it->position.latDeg, w.latDeg);
    QCOMPARE(it->position.lonDeg, w.lonDeg);
    // deeper than a safety depth of 1 m? only if it has a VALSOU >= 1: else still dangerous
    SafetySettings shallow;
    shallow.safetyDepthM = -5.0;
    const ChartHazards h2({cell_}, shallow);
    const std::vector<RouteFinding> f2 = checkRoute(r, h2);
    const bool stillThere =
        std::any_of(f2.begin(), f2.end(), [&](const RouteFinding& x) { return x.lnam == wreck->lnam; });
    QCOMPARE(stillThere, !wreck->number("VALSOU").has_value() || wreck->number("WATLEV").value_or(0) == 2 ||
                             wreck->number("WATLEV").value_or(0) == 1 ||
                             wreck->number("WATLEV").value_or(0) == 4);
  }

  void dredgedChannelIsClear() {
    // The cell's depth areas are bounded by fathom contours in metres (0, 1.8, 3.6, 9.1, 18.2, ...):
    // with a 10 m safety contour the whole bay (DEPARE 9.1 to 182.8 m) is unsafe, as S-52 has it, so a
    // navigator of this chart sets 9 m.
    SafetySettings nine;
    nine.safetyContourM = 9.0;
    const ChartHazards hazards({cell_}, nine);
    // Blair Waterway's centre line: the points its DRGARE quadrants are named after, from the bay to
    // the turning basin
    const geo::Route r = routeOf({{47.2802, -122.4162},
                                  {47.273194, -122.404889},
                                  {47.271028, -122.401361},
                                  {47.265889, -122.393139},
                                  {47.2588, -122.3818}},
                                 0.015);
    const std::vector<RouteFinding> f = checkRoute(r, hazards);
    for (const auto& x : f) {
      qInfo("leg %zu: %s %s %s", x.leg, hazardKindName(x.kind), x.objectClass.c_str(), x.lnam.c_str());
    }
    QVERIFY(std::none_of(f.begin(), f.end(), [](const RouteFinding& x) { return isDangerous(x.kind); }));
    // what it does list are cautions: the security zone (RESARE, entry restricted) and caution areas
    QVERIFY(std::all_of(f.begin(), f.end(), [](const RouteFinding& x) {
      return (x.kind == HazardKind::Restricted && x.objectClass == "RESARE") ||
             (x.kind == HazardKind::SpecialArea && x.objectClass == "CTNARE");
    }));
    // the same route with a 30 m safety contour crosses it at the channel's first metre
    SafetySettings deep;
    deep.safetyContourM = 30.0;
    const std::vector<RouteFinding> f30 = checkRoute(r, ChartHazards({cell_}, deep));
    QVERIFY(std::any_of(f30.begin(), f30.end(), [](const RouteFinding& x) {
      return x.leg == 1 && x.kind == HazardKind::SafetyContour && x.objectClass == "DRGARE";
    }));
  }

  void randomRoutesAgreeWithGdal() {
    // four safety contours: between the chart's depth bands and on them
    const std::vector<double> contours{5.0, 9.0, 10.0, 20.0};
    std::vector<std::unique_ptr<ChartHazards>> hazards;
    std::vector<std::unique_ptr<Independent>> gdal;
    for (const double sc : contours) {
      SafetySettings s;
      s.safetyContourM = sc;
      hazards.push_back(std::make_unique<ChartHazards>(std::vector<CellPtr>{cell_}, s));
      gdal.push_back(std::make_unique<Independent>(sc));
    }
    std::mt19937_64 rng(20261204);
    std::uniform_real_distribution<double> lat(47.24, 47.32), lon(-122.54, -122.37), brg(0.0, 360.0),
        len(300.0, 2000.0), xtl(0.01, 0.1);
    std::uniform_int_distribution<int> legs(2, 5);
    std::size_t findings = 0, nearEdge = 0;
    const int routes = 25;
    for (int n = 0; n < routes; ++n) {
      std::vector<geo::GeoPoint> pts{{lat(rng), lon(rng)}};
      for (int k = legs(rng); k > 0; --k) pts.push_back(offset(pts.back(), brg(rng), len(rng)));
      geo::Route r = routeOf(pts, 0.0);
      for (auto& w : r.waypoints) {
        w.leg.portXtlNm = xtl(rng);
        w.leg.starboardXtlNm = xtl(rng);
      }
      const std::size_t which = static_cast<std::size_t>(n) % contours.size();
      const std::set<Key> ours = keysOf(checkRoute(r, *hazards[which]));
      std::map<Key, double> edge;
      const std::set<Key> theirs = gdal[which]->check(r, edge);
      std::set<Key> diff;
      std::set_symmetric_difference(ours.begin(), ours.end(), theirs.begin(), theirs.end(),
                                    std::inserter(diff, diff.begin()));
      for (const Key& k : diff) {
        const double d = edge.count(k) ? edge.at(k) : -1.0;
        if (d < 0.0 || d > 0.5) {
          QFAIL(qPrintable(
              QStringLiteral("route %1 leg %2: %3 %4 found by %5 only, %6 m from the corridor's edge")
                  .arg(n)
                  .arg(std::get<0>(k))
                  .arg(QString::fromStdString(std::get<2>(k)), QString::fromStdString(std::get<1>(k)),
                       ours.count(k) ? "Reckoner" : "GDAL")
                  .arg(d)));
        }
        ++nearEdge;
      }
      findings += theirs.size();
    }
    qInfo("%d random routes: %zu findings by GDAL, %zu differing within 0.5 m of a corridor's edge", routes,
          findings, nearEdge);
    QVERIFY(findings >= 50);  // the routes do meet the chart
  }
};

QTEST_GUILESS_MAIN(TestRouteCheck)
#include "tst_route_check.moc"
