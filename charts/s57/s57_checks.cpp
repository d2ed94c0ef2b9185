#include "charts/s57/s57_checks.h"

#include <zlib.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdio>

#include "charts/s57/iso8211.h"
#include "io/error_line.h"

namespace reckoner::charts::s57 {
namespace {

using iso8211::withSeparators;

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\r')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

std::optional<std::int64_t> integer(std::string_view s) {
  s = trimmed(s);
  std::int64_t v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (s.empty() || ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return v;
}

bool equalNoCase(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::toupper(static_cast<unsigned char>(x)) == std::toupper(static_cast<unsigned char>(y));
         });
}

/// The fields of one CSV line (double quotes, "" inside them).
std::vector<std::string> csvFields(std::string_view line) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        out.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        out.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      out.emplace_back();
    } else if (c != '\r') {
      out.back() += c;
    }
  }
  return out;
}

std::string recordName(std::uint8_t rcnm) {
  switch (rcnm) {
    case 100:
      return "feature record";
    case 110:
      return "isolated node";
    case 120:
      return "connected node";
    case 130:
      return "edge";
    case 140:
      return "face";
    default:
      return "record of kind " + std::to_string(rcnm);
  }
}

std::uint64_t keyOf(const RecordVersion& r) {
  return (std::uint64_t{r.rcnm} << 32) | r.rcid;
}

std::string where(const RecordVersion& r) {
  return "record " + withSeparators(r.record) + " (byte " + withSeparators(r.offset) + ")";
}

}  // namespace

ObjectClassKinds ObjectClassKinds::fromCatalogue(std::string_view csv) {
  ObjectClassKinds out;
  std::size_t codeColumn = 0, classColumn = 0;
  bool header = true;
  while (!csv.empty()) {
    const std::size_t nl = csv.find('\n');
    const std::string_view line = csv.substr(0, nl);
    csv = nl == std::string_view::npos ? std::string_view() : csv.substr(nl + 1);
    const auto f = csvFields(line);
    if (header) {
      header = false;
      const auto col = [&](std::string_view name) {
        return static_cast<std::size_t>(std::find(f.begin(), f.end(), name) - f.begin());
      };
      codeColumn = col("Code");
      classColumn = col("Class");
      if (codeColumn >= f.size() || classColumn >= f.size()) return out;
      continue;
    }
    if (f.size() <= std::max(codeColumn, classColumn)) continue;
    const auto code = integer(f[codeColumn]);
    const std::string_view cls = trimmed(f[classColumn]);
    if (!code || cls.size() != 1) continue;
    FeatureKind k = FeatureKind::Geo;
    switch (std::toupper(static_cast<unsigned char>(cls[0]))) {
      case 'G':
        k = FeatureKind::Geo;
        break;
      case 'M':
        k = FeatureKind::Meta;
        break;
      case 'C':
        k = FeatureKind::Collection;
        break;
      case '$':
        k = FeatureKind::Cartographic;
        break;
      default:
        continue;
    }
    out.table_.emplace_back(*code, k);
  }
  std::sort(out.table_.begin(), out.table_.end());
  return out;
}

FeatureKind ObjectClassKinds::kind(std::int64_t objl) const {
  const auto it = std::lower_bound(table_.begin(), table_.end(), objl,
                                   [](const auto& e, std::int64_t code) { return e.first < code; });
  if (it != table_.end() && it->first == objl) return it->second;
  if (objl >= 300 && objl < 400) return FeatureKind::Meta;
  if (objl >= 400 && objl < 500) return FeatureKind::Collection;
  if (objl >= 500 && objl < 600) return FeatureKind::Cartographic;
  return FeatureKind::Geo;
}

namespace {

/// Where RCNM, RCID, RVER, RUIN and OBJL are in the FRID or VRID fields of one file.
constexpr const char* kSubfields[5] = {"RCNM", "RCID", "RVER", "RUIN", "OBJL"};
struct Indices {
  const iso8211::FieldDescription* description = nullptr;
  std::size_t at[5] = {};
};

/// Reads the DSID record (the first data record): name, edition, update, and the DSSI's counts into
/// `out.declared`. "" or the problem.
std::string readDataSetIdentification(const iso8211::Record& r, DataSetSummary& out) {
  const iso8211::Field* key = r.key();
  if (!key || key->tag != "DSID")
    return "the first data record is not a data set identification (DSID): not an S-57 data set";
  out.name = std::string(iso8211::textSubfield(*key, "DSNM").value_or(""));
  out.edition = std::string(iso8211::textSubfield(*key, "EDTN").value_or(""));
  out.update = std::string(iso8211::textSubfield(*key, "UPDN").value_or(""));
  const iso8211::Field* dssi = r.find("DSSI");
  if (!dssi) return "the DSID record has no data set structure information (DSSI)";
  std::uint64_t* const targets[] = {&out.declared.meta,          &out.declared.cartographic,
                                    &out.declared.geo,           &out.declared.collection,
                                    &out.declared.isolatedNodes, &out.declared.connectedNodes,
                                    &out.declared.edges,         &out.declared.faces};
  const char* const names[] = {"NOMR", "NOCR", "NOGR", "NOLR", "NOIN", "NOCN", "NOED", "NOFA"};
  for (std::size_t i = 0; i < 8; ++i) {
    const auto v = iso8211::intSubfield(*dssi, names[i]);
    if (!v || *v < 0) return std::string("the DSSI field's ") + names[i] + " does not decode";
    *targets[i] = static_cast<std::uint64_t>(*v);
  }
  return {};
}

/// Counts a feature record by the kind of its object class into `held`.
void countFeature(FeatureKind kind, RecordCounts& held) {
  switch (kind) {
    case FeatureKind::Meta:
      ++held.meta;
      break;
    case FeatureKind::Cartographic:
      ++held.cartographic;
      break;
    case FeatureKind::Collection:
      ++held.collection;
      break;
    case FeatureKind::Geo:
      ++held.geo;
      break;
  }
}

/// Counts a vector record by its RCNM into `held`; false for an RCNM that is no vector record's.
bool countVector(std::int64_t rcnm, RecordCounts& held) {
  switch (rcnm) {
    case 110:
      ++held.isolatedNodes;
      return true;
    case 120:
      ++held.connectedNodes;
      return true;
    case 130:
      ++held.edges;
      return true;
    case 140:
      ++held.faces;
      return true;
    default:
      return false;
  }
}

/// Counts one feature (FRID) or vector (VRID) record whose key field is `key` into `out.held`, and
/// with `keepRecords` keeps its identity and version. "" or the problem.
std::string countRecord(const iso8211::Record& r, const iso8211::Field& key, bool feature, Indices& ix,
                        const ObjectClassKinds& kinds, bool keepRecords, DataSetSummary& out) {
  if (ix.description != key.description) {  // once per file and kind, not per record
    ix.description = key.description;
    for (std::size_t i = 0; i < 5; ++i) ix.at[i] = iso8211::subfieldIndex(*key.description, kSubfields[i]);
  }
  const auto rcnm = iso8211::intSubfield(key, ix.at[0]);
  if (!rcnm) return "its " + std::string(key.tag) + " field does not decode";
  RecordVersion v;
  if (keepRecords) {  // the identity and version only matter to updates
    const auto rcid = iso8211::intSubfield(key, ix.at[1]);
    const auto rver = iso8211::intSubfield(key, ix.at[2]);
    const auto ruin = iso8211::intSubfield(key, ix.at[3]);
    if (!rcid || !rver || !ruin || *rcid < 0 || *rcid > 0xFFFFFFFF || *rver < 0 || *rver > 0xFFFF)
      return "its " + std::string(key.tag) + " field does not decode";
    v.rcnm = static_cast<std::uint8_t>(*rcnm & 0xFF);
    v.rcid = static_cast<std::uint32_t>(*rcid);
    v.rver = static_cast<std::uint32_t>(*rver);
    v.ruin = static_cast<std::uint8_t>(*ruin & 0xFF);
    v.record = r.number;
    v.offset = r.offset;
  }
  if (feature) {
    const auto objl = iso8211::intSubfield(key, ix.at[4]);
    if (!objl) return "its FRID field has no object class (OBJL)";
    if (*rcnm != 100) return "a feature record with RCNM " + std::to_string(*rcnm) + ", not 100";
    countFeature(kinds.kind(*objl), out.held);
  } else if (!countVector(*rcnm, out.held)) {
    return "a vector record with RCNM " + std::to_string(*rcnm) + " (110, 120, 130 or 140 expected)";
  }
  if (keepRecords) out.records.push_back(v);
  return {};
}

}  // namespace

std::string summarise(std::string_view bytes, const ObjectClassKinds& kinds, DataSetSummary& out,
                      bool keepRecords) {
  out = DataSetSummary{};
  std::string problem;
  bool first = true;
  Indices frid, vrid;
  const auto fail = [&](const iso8211::Record& r, const std::string& what) {
    problem = "record " + withSeparators(r.number) + " at byte " + withSeparators(r.offset) + ": " + what;
    return false;
  };
  const iso8211::WalkResult walked = iso8211::walk(bytes, [&](const iso8211::Record& r) {
    if (first) {
      first = false;
      const std::string why = readDataSetIdentification(r, out);
      return why.empty() || fail(r, why);
    }
    const iso8211::Field* key = r.key();
    if (!key) return true;
    const bool feature = key->tag == "FRID";
    if (!feature && key->tag != "VRID") return true;  // DSPM and other data set records
    const std::string why = countRecord(r, *key, feature, feature ? frid : vrid, kinds, keepRecords, out);
    return why.empty() || fail(r, why);
  });
  if (walked.problem) return iso8211::describe(*walked.problem);
  if (!problem.empty()) return problem;
  if (first) return "holds no data records: not an S-57 data set";
  return {};
}

std::string checkCounts(const DataSetSummary& s) {
  const RecordCounts& h = s.held;
  const RecordCounts& d = s.declared;
  if (h.features() != d.features())
    return "holds " + withSeparators(h.features()) + " feature records, its DSID says " +
           withSeparators(d.features()) + " (truncated or damaged)";
  if (h.vectors() != d.vectors())
    return "holds " + withSeparators(h.vectors()) + " vector records, its DSID says " +
           withSeparators(d.vectors()) + " (truncated or damaged)";
  const struct {
    std::uint64_t held, declared;
    const char* what;
  } kinds[] = {{h.meta, d.meta, "meta feature"},
               {h.cartographic, d.cartographic, "cartographic feature"},
               {h.geo, d.geo, "geo feature"},
               {h.collection, d.collection, "collection feature"},
               {h.isolatedNodes, d.isolatedNodes, "isolated node"},
               {h.connectedNodes, d.connectedNodes, "connected node"},
               {h.edges, d.edges, "edge"},
               {h.faces, d.faces, "face"}};
  for (const auto& k : kinds)
    if (k.held != k.declared)
      return "holds " + withSeparators(k.held) + " " + k.what + " records, its DSID says " +
             withSeparators(k.declared) + " (damaged)";
  return {};
}

std::string cellNameOf(const DataSetSummary& s) {
  const std::string_view n = trimmed(s.name);
  return std::string(n.substr(0, n.rfind('.')));
}

std::string checkUpdate(const DataSetSummary& base, const DataSetSummary& update, int number, bool* cancels) {
  if (cancels) *cancels = false;
  const std::string cell = cellNameOf(base);
  const std::string of = cellNameOf(update);
  if (of.empty()) return "its DSID names no data set (DSNM is empty)";
  if (!equalNoCase(of, cell)) return "is an update of " + shown(of) + ", not of " + shown(cell);
  const std::string_view edition = trimmed(update.edition);
  if (edition == "0") {
    if (cancels) *cancels = true;
    return "cancels the cell (its DSID gives edition 0): the producer has withdrawn " + shown(cell);
  }
  const auto e = integer(edition), be = integer(base.edition);
  if (e && be ? *e != *be : edition != trimmed(base.edition))
    return "is for edition " + shown(edition) + " of " + shown(cell) + ", the cell is edition " +
           shown(trimmed(base.edition));
  const auto n = integer(update.update);
  if (!n) return "its update number (DSID UPDN) " + io::quoted(update.update) + " is not a number";
  if (*n != number)
    return "says it is update " + std::to_string(*n) + " (DSID UPDN), its file name says " +
           std::to_string(number);
  return checkCounts(update);
}

RecordIndex::RecordIndex(const DataSetSummary& base, const std::vector<const DataSetSummary*>& updates) {
  for (const DataSetSummary* u : updates)
    for (const RecordVersion& r : u->records) versions_.emplace(keyOf(r), -1);
  for (const RecordVersion& r : base.records)
    if (const auto it = versions_.find(keyOf(r)); it != versions_.end()) it->second = r.rver;
}

std::string RecordIndex::apply(const DataSetSummary& update) {
  const std::string why = " (an update of another cell, or out of sequence)";
  for (const RecordVersion& r : update.records) {
    std::int64_t& held = versions_.try_emplace(keyOf(r), -1).first->second;
    const std::string what = recordName(r.rcnm) + " " + std::to_string(r.rcid);
    switch (r.ruin) {
      case 1:
        if (held >= 0)
          return where(r).append(" inserts ").append(what).append(", which the cell already holds") + why;
        held = r.rver;
        break;
      case 2:
      case 3: {
        const char* verb = r.ruin == 2 ? " deletes " : " modifies ";
        if (held < 0)
          return where(r).append(verb).append(what).append(", which the cell does not hold") + why;
        if (held + 1 != r.rver)
          return where(r)
                     .append(verb)
                     .append(what)
                     .append(" to version ")
                     .append(std::to_string(r.rver))
                     .append(", the cell holds version ")
                     .append(std::to_string(held)) +
                 why;
        held = r.ruin == 2 ? -1 : r.rver;
        break;
      }
      default:
        return where(r) + ": " + what + " has the update instruction (RUIN) " + std::to_string(r.ruin) +
               " (1, 2 or 3 expected)";
    }
  }
  return {};
}

std::string readCatalogue(std::string_view bytes, std::vector<CatalogueEntry>& out) {
  out.clear();
  std::string problem;
  const iso8211::WalkResult walked = iso8211::walk(bytes, [&](const iso8211::Record& r) {
    const iso8211::Field* catd = r.find("CATD");
    if (!catd) return true;
    const auto file = iso8211::textSubfield(*catd, "FILE");
    if (!file) {
      problem = "record " + withSeparators(r.number) + " at byte " + withSeparators(r.offset) +
                ": its CATD field has no FILE";
      return false;
    }
    CatalogueEntry e;
    e.file = std::string(trimmed(*file));
    const std::string_view crc = trimmed(iso8211::textSubfield(*catd, "CRCS").value_or(""));
    if (!crc.empty()) {
      std::uint32_t v = 0;
      const auto [end, ec] = std::from_chars(crc.data(), crc.data() + crc.size(), v, 16);
      if (crc.size() > 8 || ec != std::errc() || end != crc.data() + crc.size()) {
        problem = "record " + withSeparators(r.number) + " at byte " + withSeparators(r.offset) +
                  ": the CRC of " + shown(e.file) + " is " + io::quoted(crc) + ", not 8 hexadecimal digits";
        return false;
      }
      e.crc = v;
    }
    out.push_back(std::move(e));
    return true;
  });
  if (walked.problem) return iso8211::describe(*walked.problem);
  if (!problem.empty()) return problem;
  if (out.empty()) return "lists no files (no CATD records)";
  return {};
}

const CatalogueEntry* findEntry(const std::vector<CatalogueEntry>& entries,
                                const std::filesystem::path& file) {
  std::vector<std::string> mine;  // file name first, then the folders above it
  for (auto p = file; !p.filename().empty() && mine.size() < 16; p = p.parent_path())
    mine.push_back(p.filename().string());
  if (mine.empty()) return nullptr;
  const CatalogueEntry* best = nullptr;
  std::size_t bestAgreement = 0;
  for (const CatalogueEntry& e : entries) {
    std::vector<std::string_view> theirs;  // the same order
    std::string_view rest = e.file;
    while (!rest.empty()) {
      const std::size_t sep = rest.find_last_of("\\/");
      theirs.push_back(sep == std::string_view::npos ? rest : rest.substr(sep + 1));
      rest = sep == std::string_view::npos ? std::string_view() : rest.substr(0, sep);
    }
    if (theirs.empty() || !equalNoCase(theirs[0], mine[0])) continue;
    std::size_t agreement = 1;
    while (agreement < theirs.size() && agreement < mine.size() &&
           equalNoCase(theirs[agreement], mine[agreement]))
      ++agreement;
    if (!best || agreement > bestAgreement) {
      best = &e;
      bestAgreement = agreement;
    }
  }
  return best;
}

std::uint32_t crc32(std::string_view bytes) {
  uLong crc = ::crc32_z(0L, Z_NULL, 0);
  crc = ::crc32_z(crc, reinterpret_cast<const Bytef*>(bytes.data()), bytes.size());
  return static_cast<std::uint32_t>(crc);
}

std::string checkCrc(std::string_view bytes, const CatalogueEntry& entry) {
  if (!entry.crc) return {};
  const std::uint32_t actual = crc32(bytes);
  if (actual == *entry.crc) return {};
  char buf[64];
  std::snprintf(buf, sizeof buf, "CRC %08X, CATALOG.031 says %08X (damaged copy)",
                static_cast<unsigned>(actual), static_cast<unsigned>(*entry.crc));
  return buf;
}

std::string shown(std::string_view name) {
  const bool plain = !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
  });
  return plain ? std::string(name) : io::quoted(name);
}

}  // namespace reckoner::charts::s57
