#include "charts/s57/iso8211.h"

#include <algorithm>
#include <charconv>
#include <cstring>

#include "io/error_line.h"

namespace reckoner::charts::iso8211 {
namespace {

bool isDigit(char c) {
  return c >= '0' && c <= '9';
}

constexpr std::size_t kNotANumber = ~std::size_t{0};

/// A fixed-width number of the leader or directory: optional leading spaces, then digits only;
/// kNotANumber otherwise. (The walker's hot path: a few per field.)
inline std::size_t number(std::string_view s) {
  const char* p = s.data();
  const char* const end = p + s.size();
  while (p != end && *p == ' ') ++p;
  if (p == end) return kNotANumber;
  std::size_t v = 0;
  for (; p != end; ++p) {
    const auto d = static_cast<unsigned char>(*p - '0');
    if (d > 9) return kNotANumber;
    v = v * 10 + d;
  }
  return v;
}

/// A tag of up to 8 bytes as one integer, for the lookup of its description.
inline std::uint64_t tagKey(std::string_view tag) {
  std::uint64_t k = 0;
  if (tag.size() == 4) {  // S-57's tags
    std::uint32_t four = 0;
    std::memcpy(&four, tag.data(), 4);
    return four | (std::uint64_t{4} << 56);
  }
  for (std::size_t i = 0; i < tag.size() && i < 8; ++i)
    k |= std::uint64_t{static_cast<unsigned char>(tag[i])} << (8 * i);
  return tag.size() < 8 ? k | (std::uint64_t{tag.size()} << 56) : k;
}

std::string at(std::size_t offset) {
  return "byte " + withSeparators(offset);
}

Problem problemAt(std::size_t offset, std::size_t record, std::string what) {
  return Problem{offset, record, false, std::move(what)};
}

/// Reads one subfield at `pos`: sets its bounds [start, end) and moves pos past it and its unit
/// terminator. False when the data ends inside a fixed-width subfield.
bool consume(const SubfieldFormat& f, std::string_view data, bool wide, std::size_t& pos, std::size_t* start,
             std::size_t* end) {
  if (start) *start = pos;
  if (f.width > 0) {
    if (f.width > data.size() - pos) return false;
    pos += f.width;
    if (end) *end = pos;
    return true;
  }
  // Variable: up to the unit terminator, or to the end of the field (some writers leave it out).
  if (wide) {
    std::size_t i = pos;
    while (i + 1 < data.size() && !(data[i] == kUnitTerminator && data[i + 1] == '\0')) i += 2;
    if (i + 1 < data.size()) {
      if (end) *end = i;
      pos = i + 2;
    } else {
      if (end) *end = data.size();
      pos = data.size();
    }
    return true;
  }
  const std::size_t ut = data.find(kUnitTerminator, pos);
  if (ut == std::string_view::npos) {
    if (end) *end = data.size();
    pos = data.size();
  } else {
    if (end) *end = ut;
    pos = ut + 1;
  }
  return true;
}

/// Why a field's bytes do not fit its description, or empty.
std::string checkFieldData(const Field& f) {
  const FieldDescription* d = f.description;
  if (!d || d->formats.empty()) return {};
  const std::size_t size = f.data.size();
  if (d->repeating && size == 0) return {};
  if (d->fixedWidth > 0 && !f.wide) {
    if (d->repeating ? size % d->fixedWidth == 0 : size == d->fixedWidth) return {};
    return "field " + io::quoted(f.tag) + " holds " + std::to_string(size) + " bytes, its format gives " +
           (d->repeating ? "a multiple of " : "") + std::to_string(d->fixedWidth);
  }
  std::size_t pos = 0;
  do {
    for (const SubfieldFormat& sf : d->formats) {
      if (!consume(sf, f.data, f.wide, pos, nullptr, nullptr))
        return "field " + io::quoted(f.tag) + " ends inside a subfield (" + std::to_string(size) + " bytes)";
    }
  } while (d->repeating && pos < size);
  if (pos != size)
    return "field " + io::quoted(f.tag) + " has " + std::to_string(size - pos) +
           " bytes after its last subfield";
  return {};
}

/// One record's leader and directory, read and checked.
struct Layout {
  std::size_t length = 0;  ///< of the whole record
  std::size_t base = 0;    ///< offset of the field area in the record
};

/// The DDR's descriptions with their tags as integers, for the lookup of each field's description.
struct Descriptions {
  std::vector<FieldDescription> list;
  std::vector<std::uint64_t> keys;  // tagKey() of each
  /// Records of a kind repeat their directory, so the description found for the same directory entry
  /// of the last record is tried first.
  [[nodiscard]] const FieldDescription* find(std::string_view tag, std::size_t entry) const {
    const std::uint64_t k = tagKey(tag);
    const bool exact = tag.size() <= 8;
    if (entry < kHints) {
      const std::size_t h = hints[entry];
      if (h < keys.size() && keys[h] == k && (exact || list[h].tag == tag)) return &list[h];
    }
    for (std::size_t i = 0; i < keys.size(); ++i)
      if (keys[i] == k && (exact || list[i].tag == tag)) {
        if (entry < kHints) hints[entry] = i;
        return &list[i];
      }
    return nullptr;
  }
  static constexpr std::size_t kHints = 16;
  mutable std::size_t hints[kHints] = {};
};

/// A record's leader, read and checked, and where the record lies in the file.
struct Leader {
  std::size_t offset = 0;  ///< of the record in the file
  std::size_t number = 0;  ///< 1-based record number (the DDR is 1)
  std::size_t length = 0;  ///< declared record length; 0: given by the directory alone
  std::size_t base = 0;    ///< base address of the field area
  std::size_t sizeLength = 0, sizePosition = 0, sizeTag = 0;  ///< the directory's entry map
};

/// Reads and checks the 24-byte leader of the record at `offset`: its length, identifier, base
/// address and entry map, and that the file holds the directory and the declared length. The
/// problem, if any.
std::optional<Problem> readLeader(std::string_view bytes, std::size_t offset, std::size_t number_, bool isDdr,
                                  Leader& out) {
  const std::size_t remaining = bytes.size() - offset;
  if (remaining < kLeaderSize)
    return Problem{bytes.size(), number_, true, "in its 24-byte leader, which starts at " + at(offset)};
  const std::string_view leader(bytes.data() + offset, kLeaderSize);
  const auto bad = [&](std::size_t where, std::string what) {
    return std::optional<Problem>(problemAt(where, number_, std::move(what)));
  };
  const std::size_t length = number(leader.substr(0, 5));
  if (length == kNotANumber)
    return bad(offset, std::string(isDdr ? "not an ISO 8211 file: " : "") + "record length " +
                           io::quoted(leader.substr(0, 5)) + " is not a number (leader " +
                           io::quoted(leader) + ")");
  const char identifier = leader[6];
  if (isDdr && identifier != 'L')
    return bad(offset + 6, "not an ISO 8211 file: the first record's leader identifier is " +
                               io::quoted(leader.substr(6, 1)) + ", not 'L' (leader " + io::quoted(leader) +
                               ")");
  if (!isDdr && identifier != 'D')
    return bad(offset + 6,
               identifier == 'R'
                   ? std::string("leader identifier 'R' (a reused leader), which S-57 does not use")
                   : "leader identifier " + io::quoted(leader.substr(6, 1)) + ", not 'D'");
  const std::size_t base = number(leader.substr(12, 5));
  const std::size_t sizeLength = number(leader.substr(20, 1));
  const std::size_t sizePosition = number(leader.substr(21, 1));
  const std::size_t sizeTag = number(leader.substr(23, 1));
  if (base == kNotANumber || sizeLength == kNotANumber || sizePosition == kNotANumber ||
      sizeTag == kNotANumber || sizeLength == 0 || sizePosition == 0 || sizeTag == 0)
    return bad(offset, "leader " + io::quoted(leader) +
                           " does not give the base address and entry map sizes as digits");
  if (base < kLeaderSize + 1 || (length != 0 && base > length))
    return bad(offset + 12, "base address of the field area " + std::to_string(base) +
                                " is outside the record (" + std::to_string(length) + " bytes)");
  if (length != 0 && length < kLeaderSize + 1)
    return bad(offset, "record length " + std::to_string(length) + " is shorter than its leader");
  if (base > remaining)
    return Problem{bytes.size(), number_, true,
                   "in its directory; the record starts at " + at(offset) + " and declares " +
                       withSeparators(length) + " bytes"};
  if (length > remaining)
    return Problem{bytes.size(), number_, true,
                   "which starts at " + at(offset) + " and declares " + withSeparators(length) + " bytes"};
  out = Leader{offset, number_, length, base, sizeLength, sizePosition, sizeTag};
  return std::nullopt;
}

/// Reads directory entry `e` (0-based) of `record` and the field it points to into `f`: the entry's
/// tag and digits, the field's place (at `next`, the end of the fields before it, within the `area`
/// bytes of the field area), its terminator and, in data records, its description and format; its
/// length (data and terminator) into `len`. `fileSize` is the whole file's. The problem, if any.
std::optional<Problem> readEntry(std::size_t fileSize, std::string_view record, const Leader& l,
                                 std::size_t e, std::size_t next, std::size_t area,
                                 const Descriptions* descriptions, Field& f, std::size_t& len) {
  const auto bad = [&](std::size_t where, std::string what) {
    return std::optional<Problem>(problemAt(where, l.number, std::move(what)));
  };
  const std::size_t offset = l.offset, base = l.base;
  const std::size_t entrySize = l.sizeTag + l.sizeLength + l.sizePosition;
  const std::size_t entryOffset = kLeaderSize + e * entrySize;
  const char* const entry = record.data() + entryOffset;
  const std::string_view tag(entry, l.sizeTag);
  len = number(std::string_view(entry + l.sizeTag, l.sizeLength));
  const std::size_t pos = number(std::string_view(entry + l.sizeTag + l.sizeLength, l.sizePosition));
  if (!descriptions)  // in data records, a tag the DDR describes is a good one
    for (const char c : tag)
      if (c <= ' ' || c >= '\x7f')
        return bad(offset + entryOffset,
                   "directory entry " + std::to_string(e + 1) + " has the tag " + io::quoted(tag));
  if (len == kNotANumber || pos == kNotANumber)
    return bad(offset + entryOffset, "directory entry " + std::to_string(e + 1) + " " +
                                         io::quoted(std::string_view(entry, entrySize)) +
                                         " does not give the field's length and position as digits");
  if (pos != next)
    return bad(offset + entryOffset, "field " + io::quoted(tag) + " is at position " + std::to_string(pos) +
                                         " of the field area, the fields before it end at " +
                                         std::to_string(next));
  if (len == 0) return bad(offset + entryOffset, "field " + io::quoted(tag) + " has length 0");
  if (len > area - next) {
    if (l.length == 0)  // the length comes from the directory alone: the file ends inside the field
      return Problem{fileSize, l.number, true,
                     "in field " + io::quoted(tag) + "; the record starts at " + at(offset)};
    return bad(offset + entryOffset, "field " + io::quoted(tag) + " (" + std::to_string(len) +
                                         " bytes at position " + std::to_string(pos) +
                                         ") runs past the end of its record");
  }
  const char* const raw = record.data() + base + next;
  f.tag = tag;
  if (raw[len - 1] == kFieldTerminator) {
    f.data = std::string_view(raw, len - 1);
  } else if (len >= 2 && raw[len - 1] == '\0' && raw[len - 2] == kFieldTerminator) {
    f.data = std::string_view(raw, len - 2);
    f.wide = true;
  } else {
    return bad(offset + base + next + len - 1,
               "field " + io::quoted(tag) + " does not end with a field terminator");
  }
  if (descriptions) {
    f.description = descriptions->find(tag, e);
    if (!f.description)
      return bad(offset + entryOffset, "field " + io::quoted(tag) + " is not described by the file's DDR");
    const FieldDescription& d = *f.description;
    const std::size_t size = f.data.size();
    const bool fits =
        d.fixedWidth > 0 && !f.wide && (d.repeating ? size % d.fixedWidth == 0 : size == d.fixedWidth);
    if (!fits && !d.formats.empty())  // the common case above is decided without a call
      if (std::string why = checkFieldData(f); !why.empty()) return bad(offset + base + next, std::move(why));
  }
  return std::nullopt;
}

/// Reads the record at `offset` into `fields` (data views into `bytes`). `descriptions` is null for
/// the DDR. Returns the problem, if any.
std::optional<Problem> readRecord(std::string_view bytes, std::size_t offset, std::size_t number_, bool isDdr,
                                  const Descriptions* descriptions, std::vector<Field>& fields,
                                  Layout& layout) {
  Leader l;
  if (auto p = readLeader(bytes, offset, number_, isDdr, l)) return p;
  const auto bad = [&](std::size_t where, std::string what) {
    return std::optional<Problem>(problemAt(where, number_, std::move(what)));
  };
  const std::size_t base = l.base, length = l.length;
  const std::string_view record(bytes.data() + offset, length == 0 ? bytes.size() - offset : length);
  if (record[base - 1] != kFieldTerminator)
    return bad(offset + base - 1, "the directory does not end with a field terminator");
  const std::size_t entrySize = l.sizeTag + l.sizeLength + l.sizePosition;
  const std::size_t directorySize = base - 1 - kLeaderSize;
  if (directorySize == 0 || directorySize % entrySize != 0)
    return bad(offset + kLeaderSize, "the directory's " + std::to_string(directorySize) +
                                         " bytes are not a whole number of " + std::to_string(entrySize) +
                                         "-byte entries");
  fields.clear();
  const std::size_t area = record.size() - base;  // bytes the field area may use
  std::size_t next = 0;                           // where the next field must start in the field area
  for (std::size_t e = 0; e < directorySize / entrySize; ++e) {
    Field f;
    std::size_t len = 0;
    if (auto p = readEntry(bytes.size(), record, l, e, next, area, descriptions, f, len)) return p;
    fields.push_back(f);
    next += len;
  }
  const std::size_t end = base + next;
  if (length != 0 && end != length)
    return bad(offset + end, "the fields end at byte " + std::to_string(end) + " of a record of " +
                                 std::to_string(length) + " bytes");
  layout.length = end;
  layout.base = base;
  return std::nullopt;
}

/// The DDR's field descriptions: field controls, name, array descriptor, format controls.
std::optional<Problem> describeFields(const std::vector<Field>& ddrFields, std::string_view leader,
                                      Descriptions& descriptions) {
  std::vector<FieldDescription>& out = descriptions.list;
  const std::size_t given = number(leader.substr(10, 2));
  const std::size_t controlLength = given == kNotANumber ? 9 : given;
  for (const Field& f : ddrFields) {
    if (f.tag == "0000") continue;  // the file control field
    if (std::any_of(out.begin(), out.end(), [&](const FieldDescription& d) { return d.tag == f.tag; }))
      continue;
    FieldDescription d;
    d.tag = std::string(f.tag);
    if (f.data.size() < controlLength)
      return problemAt(0, 1,
                       "the DDR's description of field " + io::quoted(f.tag) + " is shorter than its " +
                           std::to_string(controlLength) + " field control bytes");
    std::string_view rest = f.data.substr(controlLength);
    std::string_view parts[3];
    for (auto& part : parts) {
      const std::size_t ut = rest.find(kUnitTerminator);
      part = rest.substr(0, ut);
      rest = ut == std::string_view::npos ? std::string_view() : rest.substr(ut + 1);
    }
    std::string_view descriptor = parts[1];
    if (!descriptor.empty() && descriptor.front() == '*') {
      d.repeating = true;
      descriptor.remove_prefix(1);
    }
    while (!descriptor.empty()) {
      const std::size_t bang = descriptor.find('!');
      d.names.emplace_back(descriptor.substr(0, bang));
      descriptor = bang == std::string_view::npos ? std::string_view() : descriptor.substr(bang + 1);
    }
    const std::size_t wanted = std::max<std::size_t>(d.names.size(), 1);
    if (auto formats = parseFormatControls(parts[2], wanted); formats && formats->size() == wanted) {
      d.formats = std::move(*formats);
      if (d.names.empty()) d.names.emplace_back();
      std::size_t width = 0;
      bool fixed = true;
      for (const auto& sf : d.formats) {
        fixed = fixed && sf.width > 0;
        width += sf.width;
      }
      d.fixedWidth = fixed ? width : 0;
      std::size_t at = 0;
      for (const auto& sf : d.formats) {
        d.fixedOffsets.push_back(at);
        at = at == kNoSubfield || sf.width == 0 ? kNoSubfield : at + sf.width;
      }
    }
    descriptions.keys.push_back(tagKey(d.tag));
    out.push_back(std::move(d));
  }
  return std::nullopt;
}

/// Format list parser: items separated by commas, each [count](group) or [count]type[(width)].
class FormatParser {
 public:
  FormatParser(std::string_view s, std::size_t max) : s_(s), max_(max) {}

  bool list(std::vector<SubfieldFormat>& out, int depth) {
    if (depth > 8 || !eat('(')) return false;
    for (;;) {
      std::size_t count = 1;
      if (pos_ < s_.size() && isDigit(s_[pos_])) {
        if (!digits(count) || count == 0) return false;
      }
      std::vector<SubfieldFormat> item;
      if (pos_ < s_.size() && s_[pos_] == '(') {
        if (!list(item, depth + 1)) return false;
      } else {
        SubfieldFormat f;
        if (!format(f)) return false;
        item.push_back(f);
      }
      if (item.empty() || count > (max_ - out.size()) / item.size()) return false;
      for (std::size_t k = 0; k < count; ++k) out.insert(out.end(), item.begin(), item.end());
      if (eat(',')) continue;
      return eat(')');
    }
  }
  [[nodiscard]] bool atEnd() const { return pos_ == s_.size(); }

 private:
  bool eat(char c) {
    if (pos_ < s_.size() && s_[pos_] == c) {
      ++pos_;
      return true;
    }
    return false;
  }
  bool digits(std::size_t& v) {
    const std::size_t start = pos_;
    v = 0;
    while (pos_ < s_.size() && isDigit(s_[pos_]) && pos_ - start < 6)
      v = v * 10 + static_cast<std::size_t>(s_[pos_++] - '0');
    return pos_ > start && !(pos_ < s_.size() && isDigit(s_[pos_]));
  }
  bool width(std::size_t& w) {
    if (!eat('(')) return true;  // variable
    return digits(w) && w > 0 && eat(')');
  }
  bool format(SubfieldFormat& f) {
    if (pos_ >= s_.size()) return false;
    f.type = s_[pos_++];
    switch (f.type) {
      case 'A':
      case 'I':
      case 'R':
      case 'S':
      case 'C':
        return width(f.width);
      case 'B': {
        std::size_t bits = 0;
        if (!eat('(') || !digits(bits) || !eat(')') || bits == 0 || bits % 8 != 0) return false;
        f.width = bits / 8;
        return true;
      }
      case 'b': {
        if (pos_ + 2 > s_.size() || !isDigit(s_[pos_]) || !isDigit(s_[pos_ + 1])) return false;
        const int kind = s_[pos_] - '0';
        const int bytes = s_[pos_ + 1] - '0';
        pos_ += 2;
        if (kind < 1 || kind > 5 || (bytes != 1 && bytes != 2 && bytes != 4 && bytes != 8)) return false;
        f.width = static_cast<std::size_t>(bytes);
        f.isInteger = kind == 1 || kind == 2;
        f.isSigned = kind == 2;
        return true;
      }
      default:
        return false;
    }
  }
  std::string_view s_;
  std::size_t max_;
  std::size_t pos_ = 0;
};

/// Bounds of subfield `index` in the first occurrence of the field, with its format.
bool locate(const Field& field, std::size_t index, std::string_view& value, const SubfieldFormat*& fmt) {
  const FieldDescription* d = field.description;
  if (!d || index >= d->formats.size()) return false;
  fmt = &d->formats[index];
  if (const std::size_t at = d->fixedOffsets[index]; at != kNoSubfield && fmt->width > 0 && !field.wide) {
    if (at + fmt->width > field.data.size()) return false;
    value = field.data.substr(at, fmt->width);
    return true;
  }
  std::size_t pos = 0;
  for (std::size_t i = 0; i <= index; ++i) {
    std::size_t start = 0, end = 0;
    if (!consume(d->formats[i], field.data, field.wide, pos, &start, &end)) return false;
    if (i == index) value = field.data.substr(start, end - start);
  }
  return true;
}

std::optional<std::int64_t> decodeInt(std::string_view v, const SubfieldFormat& f) {
  if (f.type == 'b') {
    if (!f.isInteger || v.size() != f.width) return std::nullopt;
    std::uint64_t u = 0;
    for (std::size_t i = v.size(); i-- > 0;) u = (u << 8) | static_cast<unsigned char>(v[i]);
    if (f.isSigned && v.size() < 8 && (u >> (8 * v.size() - 1)) != 0)
      u |= ~std::uint64_t{0} << (8 * v.size());
    return static_cast<std::int64_t>(u);
  }
  if (f.type == 'B') return std::nullopt;
  while (!v.empty() && v.front() == ' ') v.remove_prefix(1);
  while (!v.empty() && v.back() == ' ') v.remove_suffix(1);
  std::int64_t out = 0;
  const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), out);
  if (v.empty() || ec != std::errc() || end != v.data() + v.size()) return std::nullopt;
  return out;
}

}  // namespace

const Field* Record::key() const {
  for (const Field& f : fields)
    if (f.tag != "0001") return &f;
  return nullptr;
}

const Field* Record::find(std::string_view tag) const {
  for (const Field& f : fields)
    if (f.tag == tag) return &f;
  return nullptr;
}

std::size_t subfieldIndex(const FieldDescription& d, std::string_view name) {
  for (std::size_t i = 0; i < d.names.size() && i < d.formats.size(); ++i)
    if (d.names[i] == name) return i;
  return kNoSubfield;
}

std::optional<std::int64_t> intSubfield(const Field& field, std::size_t index) {
  // The common case first: an unsigned binary subfield at a fixed offset (RCNM, RCID, OBJL...).
  if (const FieldDescription* d = field.description; d && index < d->formats.size() && !field.wide) {
    const SubfieldFormat& f = d->formats[index];
    const std::size_t at = d->fixedOffsets[index];
    if (f.type == 'b' && f.isInteger && !f.isSigned && at != kNoSubfield && f.width <= 4 &&
        at + f.width <= field.data.size()) {
      const auto* p = reinterpret_cast<const unsigned char*>(field.data.data() + at);
      std::uint32_t u = 0;
      for (std::size_t i = f.width; i-- > 0;) u = (u << 8) | p[i];
      return std::int64_t{u};
    }
  }
  std::string_view v;
  const SubfieldFormat* f = nullptr;
  if (!locate(field, index, v, f)) return std::nullopt;
  return decodeInt(v, *f);
}

std::optional<std::int64_t> intSubfield(const Field& field, std::string_view name) {
  return field.description ? intSubfield(field, subfieldIndex(*field.description, name)) : std::nullopt;
}

std::optional<std::string_view> textSubfield(const Field& field, std::string_view name) {
  std::string_view v;
  const SubfieldFormat* f = nullptr;
  if (!field.description || !locate(field, subfieldIndex(*field.description, name), v, f) || f->type == 'b' ||
      f->type == 'B')
    return std::nullopt;
  return v;
}

std::optional<std::vector<SubfieldFormat>> parseFormatControls(std::string_view controls,
                                                               std::size_t maxFormats) {
  while (!controls.empty() && controls.back() == ' ') controls.remove_suffix(1);
  FormatParser p(controls, maxFormats);
  std::vector<SubfieldFormat> out;
  if (!p.list(out, 0) || !p.atEnd()) return std::nullopt;
  return out;
}

WalkResult walk(std::string_view bytes, const RecordVisitor& visit) {
  WalkResult r;
  if (bytes.empty()) {
    r.problem = problemAt(0, 1, "the file is empty");
    return r;
  }
  std::vector<Field> fields;
  Descriptions descriptions;
  Layout layout;
  if (auto p = readRecord(bytes, 0, 1, true, nullptr, fields, layout)) {
    r.problem = std::move(p);
    return r;
  }
  if (auto p = describeFields(fields, bytes.substr(0, kLeaderSize), descriptions)) {
    r.problem = std::move(p);
    return r;
  }
  r.records = 1;
  std::size_t offset = layout.length;
  while (offset < bytes.size()) {
    const std::size_t number_ = r.records + 1;
    if (auto p = readRecord(bytes, offset, number_, false, &descriptions, fields, layout)) {
      r.problem = std::move(p);
      return r;
    }
    r.records = number_;
    if (visit && !visit(Record{number_, offset, fields})) return r;
    offset += layout.length;
  }
  return r;
}

std::string describe(const Problem& p) {
  if (p.truncated)
    return "truncated at byte " + withSeparators(p.offset) + ", inside record " + withSeparators(p.record) +
           (p.what.empty() ? "" : " (" + p.what + ")");
  return "record " + withSeparators(p.record) + " at byte " + withSeparators(p.offset) + ": " + p.what;
}

std::string withSeparators(std::uint64_t n) {
  std::string digits = std::to_string(n);
  std::string out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

}  // namespace reckoner::charts::iso8211
