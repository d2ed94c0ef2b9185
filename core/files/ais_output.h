#pragma once
// AIS messages as text (docs/ais.md): the named fields of `reckoner-cli ais decode` (key=value or JSON
// Lines) and the rows of a live run's ais.csv (docs/outputs.md). One list of fields for both, so the
// two never disagree on a name, a unit or a precision.
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "common/time.h"
#include "io/ais.h"

namespace reckoner::files {

/// A message's present fields in output order: name and value as JSON (numbers bare, text quoted).
/// Absent ("not available") values are left out.
using AisFields = std::vector<std::pair<std::string, std::string>>;
AisFields aisFields(const io::AisMessage& m);

/// One line (without newline): `name=value ...`, or a JSON object when json.
std::string aisFieldsLine(const AisFields& f, bool json);

/// ais.csv: utc, source, then the decode fields as columns (empty when absent); text fields quoted
/// as CSV quotes them.
std::string aisCsvHeader();
std::string aisCsvLine(UtcUs receivedUtc, std::string_view source, const io::AisMessage& m);

}  // namespace reckoner::files
