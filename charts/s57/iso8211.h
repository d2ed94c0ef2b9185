#pragma once
// A reader of ISO/IEC 8211 record structure, of our own (GDAL's DDFModule is not a public header
// and its symbols are not exported on Debian 12). It checks what a damaged S-57 file breaks and
// GDAL does not look at: every record's leader (24 bytes: record length, leader identifier, base
// address of the field area, entry map sizes), its directory (tag, length, position of each field),
// that the fields tile the field area and each ends with a field terminator (0x1e), that each tag is
// described by the data descriptive record (DDR, the file's first record), and that each field's
// bytes fit the DDR's format controls (fixed widths, unit terminators 0x1f of variable subfields).
//
// A pure function on bytes: no files, no GDAL, no globals, so a libFuzzer target can wrap walk().
// On any input it terminates, never reads outside the bytes, and allocates at most in proportion to
// the input (every length is checked against what remains). It stops at the first problem and says
// where it is: the byte offset and the record number (the DDR is record 1).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace reckoner::charts::iso8211 {

inline constexpr char kFieldTerminator = '\x1e';
inline constexpr char kUnitTerminator = '\x1f';
inline constexpr std::size_t kLeaderSize = 24;

/// One subfield's format, from a DDR format control such as "(b11,b14,2b11,3A,2A(8),R(4))".
struct SubfieldFormat {
  char type = 'A';         ///< A, I, R, S, C (text), B (bit string), b (binary number)
  std::size_t width = 0;   ///< bytes; 0 = variable, ended by a unit terminator
  bool isSigned = false;   ///< b2x: two's complement integer
  bool isInteger = false;  ///< b1x, b2x: little-endian integer of `width` bytes
};

/// A field as the DDR describes it.
struct FieldDescription {
  std::string tag;
  std::vector<std::string> names;         ///< subfield names ("RCNM", "RCID", ...)
  std::vector<SubfieldFormat> formats;    ///< one per name, or empty when unusable
  bool repeating = false;                 ///< the array descriptor starts with '*'
  std::size_t fixedWidth = 0;             ///< bytes of one occurrence if all formats are fixed, else 0
  std::vector<std::size_t> fixedOffsets;  ///< per subfield: its offset when only fixed widths precede it,
                                          ///< else kNoSubfield
};

inline constexpr std::size_t kNoSubfield = ~std::size_t{0};

/// The index of a subfield in a description, or kNoSubfield.
std::size_t subfieldIndex(const FieldDescription& d, std::string_view name);

/// A field of a data record.
struct Field {
  std::string_view tag;
  std::string_view data;  ///< without its field terminator
  const FieldDescription* description = nullptr;
  bool wide = false;  ///< two-byte terminators (lexical level 2, UCS-2 text)
};

/// A data record (not the DDR) as the walker hands it over; valid during the visit only.
struct Record {
  std::size_t number = 0;  ///< 1-based; the DDR is record 1, so data records start at 2
  std::size_t offset = 0;  ///< byte offset of its leader in the file
  std::span<const Field> fields;

  /// The first field after the record identifier (0001): DSID, DSPM, VRID, FRID, CATD...
  [[nodiscard]] const Field* key() const;
  [[nodiscard]] const Field* find(std::string_view tag) const;
};

/// The first occurrence of a subfield: an integer (binary b1x/b2x, or I/R/A text holding one), or
/// the raw text bytes (A, I, R). nullopt when the field has no such subfield or it does not decode.
std::optional<std::int64_t> intSubfield(const Field& field, std::string_view name);
std::optional<std::string_view> textSubfield(const Field& field, std::string_view name);
/// The same by subfield index (subfieldIndex() of the field's description), for a loop over records.
std::optional<std::int64_t> intSubfield(const Field& field, std::size_t index);

struct Problem {
  std::size_t offset = 0;  ///< byte offset of the problem
  std::size_t record = 0;  ///< 1-based record number (the DDR is 1)
  bool truncated = false;  ///< the file ends inside record `record`
  std::string what;        ///< one line, without the file name; input bytes quoted
};

struct WalkResult {
  std::size_t records = 0;         ///< records read whole, the DDR included
  std::optional<Problem> problem;  ///< the first problem, if any
};

/// Visits each data record in order; the visitor returns false to stop (not a problem).
using RecordVisitor = std::function<bool(const Record&)>;

/// Walks an ISO 8211 file: the DDR, then every data record, checking the structure as it goes.
/// The file must end exactly at the end of a record.
WalkResult walk(std::string_view bytes, const RecordVisitor& visit);

/// Format controls "(...)" expanded to one format per subfield; nullopt when malformed or when
/// they expand to more than maxFormats subfields.
std::optional<std::vector<SubfieldFormat>> parseFormatControls(std::string_view controls,
                                                               std::size_t maxFormats = 1024);

/// A problem as text: "truncated at byte N, inside record K (...)" or "record K at byte N: ...".
std::string describe(const Problem& problem);

/// n with thousands separators: 4209 -> "4,209".
std::string withSeparators(std::uint64_t n);

}  // namespace reckoner::charts::iso8211
