#pragma once
// A strict RFC 8259 JSON reader that remembers the line and column of every value (so a scenario error
// can name the line), and a small streaming writer. No comments, no trailing commas, no duplicate keys.
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace reckoner::io {

class JsonValue {
 public:
  enum class Type { Null, Bool, Number, String, Array, Object };

  // Out of line (json.cpp), where JsonValue is complete: the members hold vectors of JsonValue itself,
  // whose special members need the complete type (clang rejects them defined inside the class).
  JsonValue();
  JsonValue(const JsonValue&);
  JsonValue(JsonValue&&) noexcept;
  JsonValue& operator=(const JsonValue&);
  JsonValue& operator=(JsonValue&&) noexcept;
  ~JsonValue();

  Type type = Type::Null;
  int line = 0;    ///< 1-based line of the value's first character
  int column = 0;  ///< 1-based column
  bool boolean = false;
  double number = 0.0;
  std::string string;
  std::vector<JsonValue> array;
  std::vector<std::pair<std::string, JsonValue>> object;  ///< in file order

  [[nodiscard]] bool isObject() const { return type == Type::Object; }
  [[nodiscard]] bool isArray() const { return type == Type::Array; }
  [[nodiscard]] bool isNumber() const { return type == Type::Number; }
  [[nodiscard]] bool isString() const { return type == Type::String; }
  [[nodiscard]] bool isBool() const { return type == Type::Bool; }
  /// Member of an object, or nullptr.
  [[nodiscard]] const JsonValue* find(std::string_view key) const;
};

const char* typeName(JsonValue::Type t);

class JsonParseError : public std::runtime_error {
 public:
  JsonParseError(int line, int column, const std::string& message)
      : std::runtime_error("line " + std::to_string(line) + ", column " + std::to_string(column) + ": " +
                           message),
        line_(line),
        column_(column) {}
  [[nodiscard]] int line() const { return line_; }
  [[nodiscard]] int column() const { return column_; }

 private:
  int line_;
  int column_;
};

/// Parses one JSON document (surrounding whitespace allowed). Throws JsonParseError.
JsonValue parseJson(std::string_view text);

/// Streaming writer with two-space indentation, or all on one line (JSON Lines) when compact. Numbers
/// are written with up to 10 significant digits unless a precision is given; non-finite numbers are
/// written as null.
class JsonWriter {
 public:
  JsonWriter() = default;
  explicit JsonWriter(bool compact) : compact_(compact) {}
  JsonWriter& beginObject();
  JsonWriter& endObject();
  JsonWriter& beginArray();
  JsonWriter& endArray();
  JsonWriter& key(std::string_view k);
  JsonWriter& value(double v, int significantDigits = 10);
  JsonWriter& value(std::int64_t v);
  JsonWriter& value(int v) { return value(static_cast<std::int64_t>(v)); }
  JsonWriter& value(std::uint64_t v);
  JsonWriter& value(bool v);
  JsonWriter& value(std::string_view v);
  JsonWriter& value(const char* v) { return value(std::string_view(v)); }
  JsonWriter& null();
  /// An array of numbers on one line.
  JsonWriter& numberArray(const std::vector<double>& values, int significantDigits = 10);
  [[nodiscard]] const std::string& str() const { return out_; }

 private:
  void beforeValue();
  void newline();
  std::string out_;
  std::vector<bool> hasItems_;  // per open container
  bool afterKey_ = false;
  bool compact_ = false;
};

/// JSON string literal (quoted, escaped).
std::string jsonQuote(std::string_view s);

}  // namespace reckoner::io
