// chart info|render|pick PATH...: S-57 cells (files or folders; builtin:default is the embedded
// fictional chart). Their output is JSON on stdout; render also writes the PNG named by --out.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <QGuiApplication>
#include <QImage>

#include "charts/pick/pick_report.h"
#include "charts/portrayal/portrayal.h"
#include "charts/render/chart_renderer.h"
#include "charts/s57/s57_loader.h"
#include "cli/cli_options.h"
#include "cli/commands.h"
#include "io/error_line.h"
#include "io/input_error.h"
#include "io/json.h"

namespace reckoner::cli {
namespace {

double secondsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// The cells of paths; each failure as an error line on stderr.
charts::LoadResult loadReporting(const std::vector<std::string>& paths) {
  charts::LoadResult r = charts::loadCharts(paths);
  for (const auto& f : r.failures)
    std::fprintf(stderr, "reckoner-cli: error: %s: %s\n", f.file.c_str(), f.reason.c_str());
  return r;
}

CLI::Option* addPaths(CLI::App& app, std::vector<std::string>& paths) {
  return addListArgument(app, "PATH", paths, 1, "S-57 cells (.000) or folders of them; builtin:default");
}

// ---- info ----------------------------------------------------------------------------------------
void writeCellJson(io::JsonWriter& w, const charts::ChartCell& c) {
  const charts::CellInfo& i = c.info();
  w.beginObject();
  w.key("name").value(i.name);
  w.key("path").value(i.path);
  w.key("edition").value(i.edition);
  w.key("update_number").value(i.updateNumber);
  w.key("updates_applied").beginArray();
  for (const auto& u : i.updatesApplied) w.value(u);
  w.endArray();
  w.key("issue_date").value(i.issueDate);
  w.key("update_date").value(i.updateDate);
  w.key("agency").value(i.agency);
  w.key("intended_usage").value(i.intendedUsage);
  w.key("compilation_scale").value(i.compilationScale);
  w.key("comment").value(i.comment);
  const charts::Bounds& b = c.bounds();
  w.key("bounds").beginObject();
  w.key("min_lat_deg").value(b.minLatDeg, 9).key("max_lat_deg").value(b.maxLatDeg, 9);
  w.key("min_lon_deg").value(b.minLonDeg, 9).key("max_lon_deg").value(b.maxLonDeg, 9);
  w.endObject();
  w.key("coverage_areas").value(static_cast<std::int64_t>(c.coverage().size()));
  w.key("features").value(static_cast<std::int64_t>(c.features().size()));
  w.key("soundings").value(static_cast<std::int64_t>(c.soundingCount()));
  w.key("feature_counts").beginObject();
  for (const auto& [cls, n] : c.countsByClass()) w.key(cls).value(static_cast<std::int64_t>(n));
  w.endObject();
  w.endObject();
}

/// Every cell's metadata and feature counts; failures listed (and on stderr), exit 2 when nothing loaded.
int chartInfo(const std::vector<std::string>& paths) {
  if (paths.empty()) throw UsageError("chart info needs at least one PATH (a .000 cell or a folder)");
  const auto start = std::chrono::steady_clock::now();
  const charts::LoadResult r = charts::loadCharts(paths);
  const double wall = secondsSince(start);
  io::JsonWriter w;
  w.beginObject();
  w.key("load_time_s").value(wall, 6);
  w.key("cells").beginArray();
  for (const auto& c : r.cells) writeCellJson(w, *c);
  w.endArray();
  w.key("failures").beginArray();
  for (const auto& f : r.failures)
    w.beginObject().key("file").value(f.file).key("reason").value(f.reason).endObject();
  w.endArray();
  w.endObject();
  std::printf("%s\n", w.str().c_str());
  for (const auto& f : r.failures)
    std::fprintf(stderr, "reckoner-cli: error: %s: %s\n", f.file.c_str(), f.reason.c_str());
  return r.cells.empty() ? 2 : 0;
}

// ---- pick ----------------------------------------------------------------------------------------
struct PickArgs {
  std::vector<std::string> paths;
  std::optional<std::string> at;
  double scale = 10000.0;
  double tolerancePx = 8.0;
};

void writePickJson(io::JsonWriter& jw, double lat, double lon,
                   const std::vector<charts::PickedFeature>& picked) {
  jw.beginObject();
  jw.key("at").beginObject();
  jw.key("lat_deg").value(lat, 7);
  jw.key("lon_deg").value(lon, 7);
  jw.endObject();
  jw.key("features").beginArray();
  for (const auto& f : picked) {
    jw.beginObject();
    jw.key("cell").value(f.cell);
    jw.key("class").value(f.objectClass);
    jw.key("class_name").value(f.className);
    jw.key("primitive").value(f.primitive);
    jw.key("distance_px").value(f.distancePx, 3);
    jw.key("attributes").beginArray();
    for (const auto& at : f.attributes) {
      jw.beginObject();
      jw.key("acronym").value(at.acronym);
      jw.key("name").value(at.name);
      jw.key("value").value(at.value);
      jw.endObject();
    }
    jw.endArray();
    jw.endObject();
  }
  jw.endArray();
  jw.endObject();
}

/// The features at a point, in plain words (the window's pick report).
int chartPick(const PickArgs& a) {
  if (a.paths.empty()) throw UsageError("chart pick needs at least one PATH");
  if (!a.at) throw UsageError("--at is required");
  const auto [lat, lon] = parsePair("at", *a.at, ',');
  if (!(std::abs(lat) <= 85.0) || !(std::abs(lon) <= 180.0))
    throw UsageError("--at: latitude within +-85 and longitude within +-180 degrees");
  const charts::LoadResult r = loadReporting(a.paths);
  if (r.cells.empty()) return 2;
  const charts::Viewport view({lat, lon}, a.scale, 101, 101);
  io::JsonWriter jw;
  writePickJson(jw, lat, lon, charts::pickFeatures(r.cells, view, {50.5, 50.5}, a.tolerancePx));
  std::printf("%s\n", jw.str().c_str());
  return 0;
}

// ---- render --------------------------------------------------------------------------------------
struct RenderArgs {
  std::vector<std::string> paths;
  std::optional<std::string> center, size, out;
  std::optional<double> scale;
  charts::MarinerSettings mariner;
  int repeat = 1;
};

struct RenderTimes {
  double loadS = 0.0, prepareMs = 0.0, medianMs = 0.0;
  charts::RenderStats stats;
};

/// Renders repeat times with one renderer, as a chart view keeps one: the first render also projects
/// the cells to Mercator (reported apart), the others are full redraws from the prepared cells.
RenderTimes renderRepeated(QImage& image, const charts::LoadResult& r, const charts::Viewport& view,
                           const RenderArgs& a) {
  RenderTimes t;
  charts::ChartRenderer renderer;
  const auto p0 = std::chrono::steady_clock::now();
  for (const auto& cell : r.cells) renderer.prepare(cell);
  t.prepareMs = 1000.0 * secondsSince(p0);
  std::vector<double> times;
  for (int k = 0; k < a.repeat; ++k) {
    const auto s0 = std::chrono::steady_clock::now();
    t.stats = renderer.render(image, r.cells, view, a.mariner);
    times.push_back(1000.0 * secondsSince(s0));
  }
  std::sort(times.begin(), times.end());
  t.medianMs = times[times.size() / 2];
  return t;
}

void printRenderJson(const RenderArgs& a, const charts::LoadResult& r, const RenderTimes& t) {
  io::JsonWriter jw;
  jw.beginObject();
  jw.key("out").value(*a.out);
  jw.key("cells_loaded").value(static_cast<std::int64_t>(r.cells.size()));
  jw.key("cells_drawn").value(t.stats.cellsDrawn);
  jw.key("features_drawn").value(t.stats.featuresDrawn);
  jw.key("overscale").value(t.stats.overscale, 4);
  jw.key("load_time_s").value(t.loadS, 6);
  jw.key("prepare_ms").value(t.prepareMs, 5);
  jw.key("render_ms_median").value(t.medianMs, 5);
  jw.key("renders").value(a.repeat);
  jw.endObject();
  std::printf("%s\n", jw.str().c_str());
}

/// A PNG of the chart and JSON with the load and median render times.
int chartRender(const RenderArgs& a) {
  if (a.paths.empty()) throw UsageError("chart render needs at least one PATH");
  for (const auto& [given, name] : {std::pair{a.center.has_value(), "center"},
                                    {a.scale.has_value(), "scale"},
                                    {a.size.has_value(), "size"},
                                    {a.out.has_value(), "out"}})
    if (!given) throw UsageError(std::string("--") + name + " is required");
  const auto [lat, lon] = parsePair("center", *a.center, ',');
  const auto [w, h] = parsePair("size", *a.size, 'x');
  if (w < 16 || h < 16 || w > 16384 || h > 16384 || w != std::floor(w) || h != std::floor(h))
    throw UsageError("--size: width and height must be integers in [16, 16384]");
  if (!qEnvironmentVariableIsSet("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
  int qargc = 1;
  char name[] = "reckoner-cli";
  char* qargv[] = {name, nullptr};
  QGuiApplication app(qargc, qargv);  // fonts for the chart text
  const auto t0 = std::chrono::steady_clock::now();
  const charts::LoadResult r = loadReporting(a.paths);
  const double loadS = secondsSince(t0);
  if (r.cells.empty()) return 2;
  const charts::Viewport view({lat, lon}, *a.scale, static_cast<int>(w), static_cast<int>(h));
  QImage image(static_cast<int>(w), static_cast<int>(h), QImage::Format_ARGB32_Premultiplied);
  RenderTimes t = renderRepeated(image, r, view, a);
  t.loadS = loadS;
  if (!image.save(QString::fromStdString(*a.out), "PNG"))
    throw io::InputError(*a.out, 0, "", "cannot write the PNG");
  printRenderJson(a, r, t);
  return 0;
}

void addRenderOptions(CLI::App& app, RenderArgs& a) {
  addPaths(app, a.paths);
  addText(app, "center", a.center, "LAT,LON", "centre of the picture, degrees; required");
  addValue(
      app, "scale", "N", "scale denominator (1:N), 100 to 100000000; required",
      [&a](const std::string& t) { a.scale = static_cast<double>(parseCount("scale", t, 100, 100000000)); });
  addText(app, "size", a.size, "WxH", "picture size, pixels, 16 to 16384 each; required");
  addValue(app, "palette", "day|dusk|night", "colour palette (default day)", [&a](const std::string& t) {
    const auto p = charts::paletteFromName(t);
    if (!p) throw UsageError("--palette: expected day, dusk or night, got " + io::quoted(t));
    a.mariner.palette = *p;
  });
  addValue(app, "category", "base|standard|all", "display category (default standard)",
           [&a](const std::string& t) {
             const auto c = charts::categoryFromName(t);
             if (!c) throw UsageError("--category: expected base, standard or all, got " + io::quoted(t));
             a.mariner.category = *c;
           });
  addValue(app, "safety-contour", "M",
           "safety contour and safety depth, metres" +
               rangeText(0.0, 12000.0, numberText(a.mariner.safetyContourM)),
           [&a](const std::string& t) {
             a.mariner.safetyContourM = parseReal("safety-contour", t, 0.0, 12000.0);
             a.mariner.safetyDepthM = a.mariner.safetyContourM;
           });
  addText(app, "out", a.out, "FILE.png", "the picture, PNG; required");
  addInteger(app, "repeat", a.repeat, 1, 1000, "K", "renders timed (the median is reported)");
}

}  // namespace

void addChartCommands(CLI::App& root, Commands& out) {
  CLI::App* chart = root.add_subcommand("chart", "S-57 charts: info, render, pick (JSON on stdout)");
  chart->require_subcommand(1);

  auto paths = std::make_shared<std::vector<std::string>>();
  CLI::App* info = chart->add_subcommand("info", "every cell's metadata and feature counts, as JSON");
  addPaths(*info, *paths);
  addIgnoredQuiet(*info);
  out.push_back({info, [paths] { return chartInfo(*paths); }, ""});

  auto r = std::make_shared<RenderArgs>();
  CLI::App* render =
      chart->add_subcommand("render", "the chart drawn into a PNG; load and render times as JSON");
  addRenderOptions(*render, *r);
  addIgnoredQuiet(*render);
  out.push_back({render, [r] { return chartRender(*r); }, ""});

  auto pa = std::make_shared<PickArgs>();
  CLI::App* pick =
      chart->add_subcommand("pick", "the features at a point (the window's pick report), as JSON");
  addPaths(*pick, pa->paths);
  addText(*pick, "at", pa->at, "LAT,LON", "the point, degrees; required");
  addValue(*pick, "scale", "N", "scale denominator (1:N), 100 to 100000000 (default 10000)",
           [q = pa.get()](const std::string& t) {
             q->scale = static_cast<double>(parseCount("scale", t, 100, 100000000));
           });
  addValue(*pick, "tolerance", "PX", "pick radius, pixels, 1 to 200 (default 8)",
           [q = pa.get()](const std::string& t) {
             q->tolerancePx = static_cast<double>(parseCount("tolerance", t, 1, 200));
           });
  addIgnoredQuiet(*pick);
  out.push_back({pick, [pa] { return chartPick(*pa); }, ""});
}

}  // namespace reckoner::cli
