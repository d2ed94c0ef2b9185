#include "io/json.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <unordered_set>

#include "io/error_line.h"
#include "io/utf8.h"

namespace reckoner::io {

JsonValue::JsonValue() = default;
JsonValue::JsonValue(const JsonValue&) = default;
JsonValue::JsonValue(JsonValue&&) noexcept = default;
JsonValue& JsonValue::operator=(const JsonValue&) = default;
JsonValue& JsonValue::operator=(JsonValue&&) noexcept = default;
JsonValue::~JsonValue() = default;

const JsonValue* JsonValue::find(std::string_view key) const {
  for (const auto& [k, v] : object)
    if (k == key) return &v;
  return nullptr;
}

const char* typeName(JsonValue::Type t) {
  switch (t) {
    case JsonValue::Type::Null:
      return "null";
    case JsonValue::Type::Bool:
      return "a boolean";
    case JsonValue::Type::Number:
      return "a number";
    case JsonValue::Type::String:
      return "a string";
    case JsonValue::Type::Array:
      return "an array";
    case JsonValue::Type::Object:
      return "an object";
  }
  return "unknown";
}

namespace {

constexpr int kMaxDepth = 128;

class Parser {
 public:
  explicit Parser(std::string_view text) : s_(text) {}

  JsonValue document() {
    skipWs();
    JsonValue v = value(0);
    skipWs();
    if (pos_ != s_.size()) fail("unexpected characters after the JSON document");
    return v;
  }

 private:
  [[noreturn]] void fail(const std::string& msg) const { throw JsonParseError(line_, col_, msg); }

  [[nodiscard]] bool atEnd() const { return pos_ >= s_.size(); }
  [[nodiscard]] char peek() const { return atEnd() ? '\0' : s_[pos_]; }
  char get() {
    if (atEnd()) fail("unexpected end of input");
    const char c = s_[pos_++];
    if (c == '\n') {
      ++line_;
      col_ = 1;
    } else {
      ++col_;
    }
    return c;
  }
  void skipWs() {
    while (!atEnd() && (peek() == ' ' || peek() == '\t' || peek() == '\n' || peek() == '\r')) get();
  }
  void expectLiteral(std::string_view lit) {
    for (char c : lit)
      if (atEnd() || get() != c) fail("invalid literal (expected '" + std::string(lit) + "')");
  }

  JsonValue value(int depth) {
    if (depth > kMaxDepth) fail("nesting deeper than 128 levels");
    JsonValue v;
    v.line = line_;
    v.column = col_;
    if (atEnd()) fail("unexpected end of input, expected a value");
    switch (peek()) {
      case '{':
        object(v, depth);
        break;
      case '[':
        array(v, depth);
        break;
      case '"':
        v.type = JsonValue::Type::String;
        v.string = string();
        break;
      case 't':
        expectLiteral("true");
        v.type = JsonValue::Type::Bool;
        v.boolean = true;
        break;
      case 'f':
        expectLiteral("false");
        v.type = JsonValue::Type::Bool;
        break;
      case 'n':
        expectLiteral("null");
        break;
      default:
        if (peek() == '-' || (peek() >= '0' && peek() <= '9')) {
          v.type = JsonValue::Type::Number;
          v.number = number();
        } else {
          fail("unexpected character " + quoted(std::string_view(&s_[pos_], 1)) + ", expected a value");
        }
    }
    return v;
  }

  void object(JsonValue& v, int depth) {
    v.type = JsonValue::Type::Object;
    get();  // {
    skipWs();
    if (peek() == '}') {
      get();
      return;
    }
    std::unordered_set<std::string> keys;  // a hash set: a file of 100,000 keys is checked in O(n)
    while (true) {
      skipWs();
      if (peek() != '"') fail("expected a string key in object");
      const int keyLine = line_, keyCol = col_;
      std::string key = string();
      if (!keys.insert(key).second) throw JsonParseError(keyLine, keyCol, "duplicate key " + quoted(key, 80));
      skipWs();
      if (get() != ':') fail("expected ':' after object key");
      skipWs();
      JsonValue member = value(depth + 1);
      v.object.emplace_back(std::move(key), std::move(member));
      skipWs();
      const char c = get();
      if (c == '}') return;
      if (c != ',') fail("expected ',' or '}' in object");
    }
  }

  void array(JsonValue& v, int depth) {
    v.type = JsonValue::Type::Array;
    get();  // [
    skipWs();
    if (peek() == ']') {
      get();
      return;
    }
    while (true) {
      skipWs();
      v.array.push_back(value(depth + 1));
      skipWs();
      const char c = get();
      if (c == ']') return;
      if (c != ',') fail("expected ',' or ']' in array");
    }
  }

  unsigned hex4() {
    unsigned u = 0;
    for (int i = 0; i < 4; ++i) {
      const char c = get();
      u <<= 4;
      if (c >= '0' && c <= '9')
        u |= static_cast<unsigned>(c - '0');
      else if (c >= 'a' && c <= 'f')
        u |= static_cast<unsigned>(c - 'a' + 10);
      else if (c >= 'A' && c <= 'F')
        u |= static_cast<unsigned>(c - 'A' + 10);
      else
        fail("invalid \\u escape");
    }
    return u;
  }

  static void appendUtf8(std::string& out, unsigned cp) {
    if (cp < 0x80) {
      out += static_cast<char>(cp);
    } else if (cp < 0x800) {
      out += static_cast<char>(0xC0 | (cp >> 6));
      out += static_cast<char>(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
      out += static_cast<char>(0xE0 | (cp >> 12));
      out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (cp & 0x3F));
    } else {
      out += static_cast<char>(0xF0 | (cp >> 18));
      out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
      out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (cp & 0x3F));
    }
  }

  std::string string() {
    get();  // "
    std::string out;
    while (true) {
      if (atEnd()) fail("unterminated string");
      const char c = get();
      if (c == '"') return out;
      if (static_cast<unsigned char>(c) < 0x20) fail("control character in string (escape it)");
      if (static_cast<unsigned char>(c) >= 0x80) {
        // JSON text is UTF-8 (RFC 8259 section 8.1): a byte that does not start a well-formed sequence
        // is an error, not a character.
        const std::size_t n = utf8SequenceLength(s_, pos_ - 1);
        if (n == 0) fail("invalid UTF-8 in string (byte " + quoted(std::string_view(&s_[pos_ - 1], 1)) + ")");
        out.append(s_.substr(pos_ - 1, n));
        pos_ += n - 1;  // one character, one column: get() counted its first byte
        continue;
      }
      if (c != '\\') {
        out += c;
        continue;
      }
      const char e = get();
      switch (e) {
        case '"':
          out += '"';
          break;
        case '\\':
          out += '\\';
          break;
        case '/':
          out += '/';
          break;
        case 'b':
          out += '\b';
          break;
        case 'f':
          out += '\f';
          break;
        case 'n':
          out += '\n';
          break;
        case 'r':
          out += '\r';
          break;
        case 't':
          out += '\t';
          break;
        case 'u': {
          unsigned cp = hex4();
          if (cp >= 0xD800 && cp <= 0xDBFF) {
            if (get() != '\\' || get() != 'u') fail("unpaired UTF-16 surrogate in \\u escape");
            const unsigned lo = hex4();
            if (lo < 0xDC00 || lo > 0xDFFF) fail("invalid UTF-16 low surrogate in \\u escape");
            cp = 0x10000 + ((cp - 0xD800) << 10) + (lo - 0xDC00);
          } else if (cp >= 0xDC00 && cp <= 0xDFFF) {
            fail("unpaired UTF-16 surrogate in \\u escape");
          }
          appendUtf8(out, cp);
          break;
        }
        default:
          fail("invalid escape " + quoted(std::string("\\") + e));
      }
    }
  }

  double number() {
    const std::size_t start = pos_;
    if (peek() == '-') get();
    if (peek() == '0') {
      get();
    } else if (peek() >= '1' && peek() <= '9') {
      while (peek() >= '0' && peek() <= '9') get();
    } else {
      fail("invalid number");
    }
    if (peek() == '.') {
      get();
      if (!(peek() >= '0' && peek() <= '9')) fail("invalid number: digit expected after '.'");
      while (peek() >= '0' && peek() <= '9') get();
    }
    if (peek() == 'e' || peek() == 'E') {
      get();
      if (peek() == '+' || peek() == '-') get();
      if (!(peek() >= '0' && peek() <= '9')) fail("invalid number: digit expected in exponent");
      while (peek() >= '0' && peek() <= '9') get();
    }
    double d = 0.0;
    const auto r = std::from_chars(s_.data() + start, s_.data() + pos_, d);
    if (r.ec == std::errc::result_out_of_range || !std::isfinite(d)) fail("number out of range");
    if (r.ec != std::errc()) fail("invalid number");
    return d;
  }

  std::string_view s_;
  std::size_t pos_ = 0;
  int line_ = 1;
  int col_ = 1;
};

}  // namespace

JsonValue parseJson(std::string_view text) {
  return Parser(text).document();
}

std::string jsonQuote(std::string_view text) {
  // JSON is UTF-8: a string from outside (a file name, a scenario name) with bytes that are not UTF-8
  // is written with U+FFFD in their place, never as invalid JSON.
  const std::string s = validUtf8(text);
  std::string out = "\"";
  for (const char c : s) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\r':
        out += "\\r";
        break;
      case '\t':
        out += "\\t";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
          out += buf;
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

void JsonWriter::newline() {
  if (compact_) return;
  out_ += '\n';
  out_.append(2 * hasItems_.size(), ' ');
}

void JsonWriter::beforeValue() {
  if (afterKey_) {
    afterKey_ = false;
    return;
  }
  if (!hasItems_.empty()) {
    if (hasItems_.back()) out_ += ',';
    hasItems_.back() = true;
    newline();
  }
}

JsonWriter& JsonWriter::beginObject() {
  beforeValue();
  out_ += '{';
  hasItems_.push_back(false);
  return *this;
}

JsonWriter& JsonWriter::endObject() {
  const bool items = hasItems_.back();
  hasItems_.pop_back();
  if (items) newline();
  out_ += '}';
  if (hasItems_.empty() && !compact_) out_ += '\n';
  return *this;
}

JsonWriter& JsonWriter::beginArray() {
  beforeValue();
  out_ += '[';
  hasItems_.push_back(false);
  return *this;
}

JsonWriter& JsonWriter::endArray() {
  const bool items = hasItems_.back();
  hasItems_.pop_back();
  if (items) newline();
  out_ += ']';
  return *this;
}

JsonWriter& JsonWriter::key(std::string_view k) {
  beforeValue();
  out_ += jsonQuote(k);
  out_ += compact_ ? ":" : ": ";
  afterKey_ = true;
  return *this;
}

static std::string formatNumber(double v, int digits) {
  if (!std::isfinite(v)) return "null";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

JsonWriter& JsonWriter::value(double v, int significantDigits) {
  beforeValue();
  out_ += formatNumber(v, significantDigits);
  return *this;
}

JsonWriter& JsonWriter::value(std::int64_t v) {
  beforeValue();
  out_ += std::to_string(v);
  return *this;
}

JsonWriter& JsonWriter::value(std::uint64_t v) {
  beforeValue();
  out_ += std::to_string(v);
  return *this;
}

JsonWriter& JsonWriter::value(bool v) {
  beforeValue();
  out_ += v ? "true" : "false";
  return *this;
}

JsonWriter& JsonWriter::value(std::string_view v) {
  beforeValue();
  out_ += jsonQuote(v);
  return *this;
}

JsonWriter& JsonWriter::null() {
  beforeValue();
  out_ += "null";
  return *this;
}

JsonWriter& JsonWriter::numberArray(const std::vector<double>& values, int significantDigits) {
  beforeValue();
  out_ += '[';
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i) out_ += ", ";
    out_ += formatNumber(values[i], significantDigits);
  }
  out_ += ']';
  return *this;
}

}  // namespace reckoner::io
