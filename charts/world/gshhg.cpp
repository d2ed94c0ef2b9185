// GSHHG's binned shorelines decoded and assembled into areas per bin (gshhg.h; docs/charts.md).
#include "charts/world/gshhg.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "charts/s57/s57_loader.h"

namespace reckoner::charts::world {
namespace {

using Values = std::vector<std::int32_t>;

/// Relative coordinates run from 0 to 65535 across a bin, from its south-west corner.
constexpr std::int64_t kSpan = 65535;
/// Segment info: bits 0-2 exit side, 3-5 entry side, 6-8 level, 9 and up the point count. Sides
/// 0 south, 1 east, 2 north, 3 west; 4 means none (a closed ring inside the bin).
constexpr int kInside = 4;

const char* const kBinSize = "Bin_size_in_minutes";
const char* const kColumns = "N_bins_in_360_longitude_range";
const char* const kRows = "N_bins_in_180_degree_latitude_range";
const char* const kBinCount = "N_bins_in_file";
const char* const kSegmentCount = "N_segments_in_file";
const char* const kPointCount = "N_points_in_file";
const char* const kFirstSegment = "Id_of_first_segment_in_a_bin";
const char* const kSegmentsInBin = "N_segments_in_a_bin";
const char* const kNodeLevels = "Embedded_node_levels_in_a_bin";
const char* const kSegmentInfo = "Embedded_npts_levels_exit_entry_for_a_segment";
const char* const kFirstPoint = "Id_of_first_point_in_a_segment";
const char* const kAntarctica = "Embedded_ANT_flag";
const char* const kDx = "Relative_longitude_from_SW_corner_of_bin";
const char* const kDy = "Relative_latitude_from_SW_corner_of_bin";

[[noreturn]] void fail(const std::string& file, const std::string& variable, const std::string& why) {
  throw ChartLoadError(file, "variable '" + variable + "': " + why);
}

const Values& variable(const gdalio::IntegerVariables& v, const std::string& file, const char* name) {
  const auto it = v.find(name);
  if (it == v.end()) throw ChartLoadError(file, std::string("has no variable '") + name + "'");
  return it->second;
}

std::int32_t scalar(const gdalio::IntegerVariables& v, const std::string& file, const char* name) {
  const Values& a = variable(v, file, name);
  if (a.size() != 1) fail(file, name, "holds " + std::to_string(a.size()) + " values, 1 expected");
  return a[0];
}

void expectLength(const Values& a, std::size_t n, const std::string& file, const char* name, const char* by) {
  if (a.size() != n)
    fail(file, name,
         "holds " + std::to_string(a.size()) + " values, " + by + " says " + std::to_string(n) +
             " (damaged or truncated)");
}

/// The file's variables, checked against each other.
struct Layout {
  int binMinutes = 0, columns = 0, rows = 0;
  const Values *firstSegment = nullptr, *segmentsInBin = nullptr, *nodeLevels = nullptr;
  const Values *segmentInfo = nullptr, *firstPoint = nullptr, *antarctica = nullptr;
  const Values *dx = nullptr, *dy = nullptr;
};

Layout checkedLayout(const gdalio::IntegerVariables& v, const std::string& file) {
  Layout l;
  l.binMinutes = scalar(v, file, kBinSize);
  if (l.binMinutes <= 0 || 10800 % l.binMinutes != 0)
    fail(file, kBinSize, std::to_string(l.binMinutes) + " does not divide 180 degrees");
  l.columns = scalar(v, file, kColumns);
  l.rows = scalar(v, file, kRows);
  if (static_cast<std::int64_t>(l.columns) * l.binMinutes != 21600)
    fail(
        file, kColumns,
        std::to_string(l.columns) + " bins of " + std::to_string(l.binMinutes) + "' do not span 360 degrees");
  if (static_cast<std::int64_t>(l.rows) * l.binMinutes != 10800)
    fail(file, kRows,
         std::to_string(l.rows) + " bins of " + std::to_string(l.binMinutes) + "' do not span 180 degrees");
  const auto bins = static_cast<std::size_t>(l.columns) * static_cast<std::size_t>(l.rows);
  if (scalar(v, file, kBinCount) != static_cast<std::int32_t>(bins))
    fail(file, kBinCount, "is not " + std::to_string(l.columns) + " x " + std::to_string(l.rows));
  const std::int32_t segments = scalar(v, file, kSegmentCount), points = scalar(v, file, kPointCount);
  if (segments < 0) fail(file, kSegmentCount, "is negative");
  if (points < 0) fail(file, kPointCount, "is negative");
  l.firstSegment = &variable(v, file, kFirstSegment);
  l.segmentsInBin = &variable(v, file, kSegmentsInBin);
  l.nodeLevels = &variable(v, file, kNodeLevels);
  l.segmentInfo = &variable(v, file, kSegmentInfo);
  l.firstPoint = &variable(v, file, kFirstPoint);
  l.dx = &variable(v, file, kDx);
  l.dy = &variable(v, file, kDy);
  for (const auto& [a, name] : {std::pair{l.firstSegment, kFirstSegment},
                                {l.segmentsInBin, kSegmentsInBin},
                                {l.nodeLevels, kNodeLevels}})
    expectLength(*a, bins, file, name, kBinCount);
  for (const auto& [a, name] : {std::pair{l.segmentInfo, kSegmentInfo}, {l.firstPoint, kFirstPoint}})
    expectLength(*a, static_cast<std::size_t>(segments), file, name, kSegmentCount);
  if (const auto it = v.find(kAntarctica); it != v.end()) {
    l.antarctica = &it->second;
    expectLength(*l.antarctica, static_cast<std::size_t>(segments), file, kAntarctica, kSegmentCount);
  }
  expectLength(*l.dx, static_cast<std::size_t>(points), file, kDx, kPointCount);
  expectLength(*l.dy, static_cast<std::size_t>(points), file, kDy, kPointCount);
  return l;
}

/// A point of a bin in relative units (0 to 65535 east and north of the south-west corner).
struct Rel {
  std::int64_t x = 0, y = 0;
};

/// A segment of a bin, decoded and checked.
struct Segment {
  int level = 1;
  int entry = kInside, exit = kInside;
  std::vector<Rel> points;
  std::int64_t in = 0, out = 0;  // perimeter positions of the entry and the exit (crossing segments)
  bool used = false;
};

/// The position of a point on side `side` along the bin's perimeter, counter-clockwise from the
/// south-west corner: the south side from west to east, then the east side northwards, the north side
/// westwards and the west side southwards; in [0, 4 x 65535).
std::int64_t perimeter(int side, const Rel& p) {
  switch (side) {
    case 0:
      return p.x;
    case 1:
      return kSpan + p.y;
    case 2:
      return 2 * kSpan + (kSpan - p.x);
    default:
      return (3 * kSpan + (kSpan - p.y)) % (4 * kSpan);
  }
}

bool onSide(int side, const Rel& p) {
  switch (side) {
    case 0:
      return p.y == 0;
    case 1:
      return p.x == kSpan;
    case 2:
      return p.y == kSpan;
    default:
      return p.x == 0;
  }
}

/// The level GSHHG 2.3 gives a segment, as GMT draws by default (Antarctica's ice front as its
/// coast): flagged Antarctic segments and level 5 are land (1); level 6, the grounding line under
/// the ice shelves, is left out (0).
int effectiveLevel(int level, bool antarctic) {
  if (antarctic || level == 5) return 1;
  return level == 6 ? 0 : level;
}

std::string segmentText(std::size_t s, std::size_t bin) {
  return "segment " + std::to_string(s) + " (bin " + std::to_string(bin) + ")";
}

/// Segment `s` of bin `bin`: its packed info unpacked, its points read; std::nullopt when left out.
std::optional<Segment> segmentOf(const Layout& l, std::size_t s, std::size_t bin, const std::string& file) {
  const auto info = static_cast<std::uint32_t>((*l.segmentInfo)[s]);
  Segment g;
  g.exit = static_cast<int>(info & 7U);
  g.entry = static_cast<int>((info >> 3) & 7U);
  const int raw = static_cast<int>((info >> 6) & 7U);
  const std::size_t n = info >> 9;
  if (g.entry > kInside || g.exit > kInside || (g.entry == kInside) != (g.exit == kInside))
    fail(file, kSegmentInfo,
         segmentText(s, bin) + ": entry side " + std::to_string(g.entry) + ", exit side " +
             std::to_string(g.exit));
  if (raw < 1 || raw > 6) fail(file, kSegmentInfo, segmentText(s, bin) + ": level " + std::to_string(raw));
  if (n < 2) fail(file, kSegmentInfo, segmentText(s, bin) + ": " + std::to_string(n) + " point(s)");
  const std::int32_t first = (*l.firstPoint)[s];
  if (first < 0 || static_cast<std::size_t>(first) + n > l.dx->size())
    fail(file, kFirstPoint,
         segmentText(s, bin) + " runs from point " + std::to_string(first) + " for " + std::to_string(n) +
             ", the file holds " + std::to_string(l.dx->size()));
  g.level = effectiveLevel(raw, l.antarctica && (*l.antarctica)[s] != 0);
  if (g.level == 0) return std::nullopt;
  g.points.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    const auto at = static_cast<std::size_t>(first) + k;
    g.points.push_back({static_cast<std::uint16_t>((*l.dx)[at]), static_cast<std::uint16_t>((*l.dy)[at])});
  }
  if (g.entry != kInside) {
    if (!onSide(g.entry, g.points.front()) || !onSide(g.exit, g.points.back()))
      fail(file, kDx, segmentText(s, bin) + ": its ends are not on its entry and exit sides");
    g.in = perimeter(g.entry, g.points.front());
    g.out = perimeter(g.exit, g.points.back());
  }
  return g;
}

/// Appends the bin corners passed going counter-clockwise from perimeter position `from` by `by`.
void appendCorners(std::vector<Rel>& ring, std::int64_t from, std::int64_t by) {
  static constexpr Rel kCorners[4] = {{0, 0}, {kSpan, 0}, {kSpan, kSpan}, {0, kSpan}};
  for (std::int64_t k = from / kSpan + 1; k * kSpan <= from + by; ++k) ring.push_back(kCorners[k % 4]);
}

/// The land areas bounded by the crossing segments: from each segment's exit the bin's boundary is
/// followed counter-clockwise to the next entry, until the ring closes. GSHHG keeps land on the left
/// of every segment, so each ring is dry: level 1 next to the sea or a lake, 3 on an island in a lake.
std::vector<std::pair<int, std::vector<Rel>>> assembleCrossing(std::vector<Segment*>& crossing) {
  std::vector<std::pair<int, std::vector<Rel>>> rings;
  for (std::size_t start = 0; start < crossing.size(); ++start) {
    if (crossing[start]->used) continue;
    std::vector<Rel> ring;
    int lowest = 4;
    std::size_t cur = start;
    for (std::size_t step = 0; step <= crossing.size(); ++step) {
      Segment& g = *crossing[cur];
      g.used = true;
      ring.insert(ring.end(), g.points.begin(), g.points.end());
      lowest = std::min(lowest, g.level);
      std::size_t next = start;
      std::int64_t best = 4 * kSpan;
      for (std::size_t j = 0; j < crossing.size(); ++j) {
        if (crossing[j]->used && j != start) continue;
        const std::int64_t d = ((crossing[j]->in - g.out) % (4 * kSpan) + 4 * kSpan) % (4 * kSpan);
        if (d < best || (d == best && j != start)) {
          best = d;
          next = j;
        }
      }
      appendCorners(ring, g.out, best);
      if (next == start) break;
      cur = next;
    }
    rings.emplace_back(lowest <= 2 ? 1 : 3, std::move(ring));
  }
  return rings;
}

ShoreBin decodeBin(const Layout& l, std::size_t b, const std::string& file) {
  ShoreBin bin;
  const double size = l.binMinutes / 60.0;
  const auto columns = static_cast<std::size_t>(l.columns);
  const std::size_t row = b / columns, column = b % columns;  // the bins run west to east, north to south
  bin.westDeg = static_cast<double>(column) * size;
  bin.southDeg = 90.0 - static_cast<double>(row + 1) * size;
  const std::int64_t first = (*l.firstSegment)[b], end = first + (*l.segmentsInBin)[b];
  if (first < 0 || end < first || end > static_cast<std::int64_t>(l.segmentInfo->size()))
    fail(file, kFirstSegment,
         "bin " + std::to_string(b) + " holds segments " + std::to_string(first) + " to " +
             std::to_string(end) + ", the file holds " + std::to_string(l.segmentInfo->size()));
  std::vector<Segment> segments;
  for (auto s = static_cast<std::size_t>(first); s < static_cast<std::size_t>(end); ++s)
    if (auto g = segmentOf(l, s, b, file)) segments.push_back(std::move(*g));
  const auto toLatLon = [&](const std::vector<Rel>& pts) {
    std::vector<LatLon> out;
    out.reserve(pts.size());
    for (const Rel& p : pts)
      out.push_back({bin.southDeg + static_cast<double>(p.y) * size / kSpan,
                     bin.westDeg + static_cast<double>(p.x) * size / kSpan});
    return out;
  };
  std::vector<Segment*> crossing;
  for (Segment& g : segments)
    if (g.entry != kInside) crossing.push_back(&g);
  for (auto& [level, ring] : assembleCrossing(crossing)) bin.areas.push_back({level, toLatLon(ring)});
  if (crossing.empty()) {
    // No shoreline crosses the bin: its corners say whether it lies in the sea, on land or in a lake.
    const int corner = static_cast<int>((static_cast<std::uint32_t>((*l.nodeLevels)[b]) >> 9) & 7U);
    if (corner > 6)
      fail(file, kNodeLevels, "bin " + std::to_string(b) + ": corner level " + std::to_string(corner));
    const int level = effectiveLevel(corner, false);
    if (level % 2 == 1)
      bin.areas.push_back({level, toLatLon({{0, 0}, {kSpan, 0}, {kSpan, kSpan}, {0, kSpan}})});
  }
  for (const Segment& g : segments) {
    if (g.entry == kInside && g.points.size() >= 4)  // a closed ring repeats its first point
      bin.areas.push_back({g.level, toLatLon({g.points.begin(), g.points.end() - 1})});
    bin.lines.push_back({g.level, toLatLon(g.points)});
  }
  std::stable_sort(bin.areas.begin(), bin.areas.end(),
                   [](const ShoreArea& a, const ShoreArea& c) { return a.level < c.level; });
  return bin;
}

/// Odd-even test of a point against a ring (longitudes in the bin's own range).
bool inside(const std::vector<LatLon>& ring, double lonDeg, double latDeg) {
  bool in = false;
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const LatLon& a = ring[i];
    const LatLon& b = ring[j];
    if ((a.latDeg > latDeg) != (b.latDeg > latDeg) &&
        lonDeg < a.lonDeg + (latDeg - a.latDeg) * (b.lonDeg - a.lonDeg) / (b.latDeg - a.latDeg))
      in = !in;
  }
  return in;
}

}  // namespace

char resolutionLetter(ShoreResolution r) {
  switch (r) {
    case ShoreResolution::Crude:
      return 'c';
    case ShoreResolution::Low:
      return 'l';
    case ShoreResolution::Intermediate:
      return 'i';
  }
  return 'c';
}

std::string_view resolutionName(ShoreResolution r) {
  switch (r) {
    case ShoreResolution::Crude:
      return "crude";
    case ShoreResolution::Low:
      return "low";
    case ShoreResolution::Intermediate:
      return "intermediate";
  }
  return "crude";
}

Shoreline::Shoreline(std::string file, ShoreResolution resolution, double binSizeDeg, int columns, int rows,
                     std::vector<ShoreBin> bins)
    : file_(std::move(file)),
      resolution_(resolution),
      binSizeDeg_(binSizeDeg),
      columns_(columns),
      rows_(rows),
      bins_(std::move(bins)) {}

const ShoreBin& Shoreline::binAt(const LatLon& p) const {
  double lon = std::fmod(p.lonDeg, 360.0);
  if (lon < 0) lon += 360.0;
  const int column = std::clamp(static_cast<int>(lon / binSizeDeg_), 0, columns_ - 1);
  const int row = std::clamp(static_cast<int>((90.0 - p.latDeg) / binSizeDeg_), 0, rows_ - 1);
  return bin(row, column);
}

int Shoreline::levelAt(const LatLon& p) const {
  const ShoreBin& b = binAt(p);
  double lon = std::fmod(p.lonDeg, 360.0);
  if (lon < 0) lon += 360.0;
  int level = 0;
  for (const ShoreArea& a : b.areas)
    if (inside(a.ring, lon, p.latDeg)) level = a.level;
  return level;
}

std::size_t Shoreline::vertexCount() const {
  std::size_t n = 0;
  for (const ShoreBin& b : bins_) {
    for (const ShoreArea& a : b.areas) n += a.ring.size();
    for (const ShoreLine& s : b.lines) n += s.points.size();
  }
  return n;
}

const std::vector<std::string>& gshhgRequiredVariables() {
  static const std::vector<std::string> names{
      kBinSize,       kColumns,    kRows,        kBinCount,   kSegmentCount, kPointCount, kFirstSegment,
      kSegmentsInBin, kNodeLevels, kSegmentInfo, kFirstPoint, kDx,           kDy};
  return names;
}

const std::vector<std::string>& gshhgOptionalVariables() {
  static const std::vector<std::string> names{kAntarctica};
  return names;
}

Shoreline decodeGshhg(const gdalio::IntegerVariables& variables, const std::string& file,
                      ShoreResolution resolution) {
  const Layout l = checkedLayout(variables, file);
  std::vector<ShoreBin> bins;
  bins.reserve(l.firstSegment->size());
  for (std::size_t b = 0; b < l.firstSegment->size(); ++b) bins.push_back(decodeBin(l, b, file));
  return {file, resolution, l.binMinutes / 60.0, l.columns, l.rows, std::move(bins)};
}

Shoreline loadGshhg(const std::string& path, ShoreResolution resolution) {
  return decodeGshhg(gdalio::readIntegerVariables(path, gshhgRequiredVariables(), gshhgOptionalVariables()),
                     path, resolution);
}

}  // namespace reckoner::charts::world
