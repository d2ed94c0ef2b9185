#pragma once
// Checks of S-57 files that GDAL does not make, as pure functions on bytes (no GDAL, no files), on top
// of the ISO 8211 walker (iso8211.h). docs/charts.md, "Damaged cells", lists them and their texts:
//  - a data set file (base cell .000 or update .001...) holds as many records of each kind as its
//    DSID record's DSSI field says (S-57 3.1 Part 3, 7.3.1.2: NOMR meta, NOCR cartographic, NOGR geo,
//    NOLR collection feature records; NOIN isolated node, NOCN connected node, NOED edge, NOFA face
//    vector records);
//  - an update names the cell (DSID DSNM), its edition (EDTN) and its place in the sequence (UPDN),
//    and each of its records inserts a record the cell does not hold yet, or deletes or modifies one
//    it holds at the version just before (RVER);
//  - a file's CRC-32 agrees with the exchange set's catalogue (CATALOG.031, CATD records: FILE, CRCS).
// Every returned text is one line without the file name (the caller prefixes it); "" means no problem.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

namespace reckoner::charts::s57 {

/// The four kinds of feature record (S-57 Part 2, 2.1): the DSSI counts them apart.
enum class FeatureKind : std::uint8_t { Geo, Meta, Collection, Cartographic };

/// Which kind each object class code (FRID OBJL) is.
class ObjectClassKinds {
 public:
  /// S-57 Appendix A's code ranges only: 300-399 meta, 400-499 collection, 500-599 cartographic,
  /// the rest geo.
  ObjectClassKinds() = default;
  /// From the text of GDAL's s57objectclasses.csv ("Code" and "Class" columns: G, M, C, $), which
  /// also knows the national and additional-military-layer codes; the ranges for codes it lacks.
  static ObjectClassKinds fromCatalogue(std::string_view csv);
  [[nodiscard]] FeatureKind kind(std::int64_t objl) const;
  [[nodiscard]] std::size_t size() const { return table_.size(); }

 private:
  std::vector<std::pair<std::int64_t, FeatureKind>> table_;  // sorted by code
};

/// Numbers of records by kind: what a DSSI field declares, or what a file holds.
struct RecordCounts {
  std::uint64_t meta = 0, cartographic = 0, geo = 0, collection = 0;          // FRID records
  std::uint64_t isolatedNodes = 0, connectedNodes = 0, edges = 0, faces = 0;  // VRID 110-140
  [[nodiscard]] std::uint64_t features() const { return meta + cartographic + geo + collection; }
  [[nodiscard]] std::uint64_t vectors() const { return isolatedNodes + connectedNodes + edges + faces; }
  bool operator==(const RecordCounts&) const = default;
};

/// A feature or vector record's identity, version and update instruction.
struct RecordVersion {
  std::uint8_t rcnm = 0;  ///< 100 feature; 110, 120, 130, 140 vector
  std::uint32_t rcid = 0;
  std::uint32_t rver = 0;
  std::uint8_t ruin = 0;   ///< 1 insert, 2 delete, 3 modify
  std::size_t record = 0;  ///< record number in its file (the DDR is 1)
  std::size_t offset = 0;  ///< byte offset of the record
};

/// What a data set file's records say about it.
struct DataSetSummary {
  std::string name;                    ///< DSID DSNM as written ("US5WA22M.000", "US5WA22M.001")
  std::string edition;                 ///< DSID EDTN
  std::string update;                  ///< DSID UPDN
  RecordCounts declared;               ///< DSID's DSSI field
  RecordCounts held;                   ///< counted
  std::vector<RecordVersion> records;  ///< every FRID and VRID record, in file order (if kept)
};

/// Walks a base cell or an update file and fills `out`: "" or the first problem (structure, no DSID
/// as the first data record, a DSSI or record identifier that does not decode, an unknown RCNM).
/// `keepRecords` false leaves out.records empty (a cell without updates needs no index).
std::string summarise(std::string_view bytes, const ObjectClassKinds& kinds, DataSetSummary& out,
                      bool keepRecords = true);

/// "" or "holds 2,104 feature records, its DSID says 4,208 (truncated or damaged)" (or the first
/// kind that differs).
std::string checkCounts(const DataSetSummary& s);

/// The name of the cell a data set belongs to: DSNM without its extension ("US5WA22M").
std::string cellNameOf(const DataSetSummary& s);

/// Why `update`, found as update file number `number`, is not the next update of the cell `base`
/// (its DSNM, EDTN, UPDN and DSSI counts); "" if it is. `cancels` is set for an update that cancels
/// the cell (EDTN 0, S-57 Appendix B.1, 5.7): the producer has withdrawn it.
std::string checkUpdate(const DataSetSummary& base, const DataSetSummary& update, int number,
                        bool* cancels = nullptr);

/// The versions of the cell's records that its updates name, as the updates change them. Only those
/// records are indexed, so a big cell with a small update costs little.
class RecordIndex {
 public:
  RecordIndex(const DataSetSummary& base, const std::vector<const DataSetSummary*>& updates);
  /// Checks each record of an update against the cell and applies it: an insert (RUIN 1) must be new,
  /// a delete (2) or modify (3) must find the record at version RVER - 1. "" or the first problem.
  std::string apply(const DataSetSummary& update);

 private:
  std::unordered_map<std::uint64_t, std::int64_t> versions_;  // -1: the cell does not hold it
};

/// A CATD record of CATALOG.031: the file's path relative to the exchange set ("US5BOSCC\US5BOSCC.000")
/// and its CRC (CRCS, hexadecimal text; none when the catalogue gives none).
struct CatalogueEntry {
  std::string file;
  std::optional<std::uint32_t> crc;
};

/// Reads the CATD records of a catalogue: "" or the problem (structure, a FILE missing, a CRCS that
/// is not hexadecimal).
std::string readCatalogue(std::string_view bytes, std::vector<CatalogueEntry>& out);

/// The entry of `file`: the same file name (ignoring case), preferring the entry whose folders agree
/// with the most folders above `file`. Null when the catalogue does not list it.
const CatalogueEntry* findEntry(const std::vector<CatalogueEntry>& entries,
                                const std::filesystem::path& file);

/// IEEE 802.3 CRC-32 (S-57 Part 3, Annex B; zlib's crc32).
std::uint32_t crc32(std::string_view bytes);

/// "" or "CRC 1A2B3C4D, CATALOG.031 says 5E6F7081 (damaged copy)". An entry without a CRC checks
/// nothing.
std::string checkCrc(std::string_view bytes, const CatalogueEntry& entry);

/// A name from a file for a message: as it is when it is letters, digits, '_', '-' and '.',
/// io::quoted() otherwise.
std::string shown(std::string_view name);

}  // namespace reckoner::charts::s57
