#pragma once
// Files compiled into the programs: the scenarios of resources/scenarios/ by file stem.
#include <span>
#include <string_view>

namespace reckoner::resources {

struct EmbeddedFile {
  std::string_view name;  ///< file name without extension, e.g. "default", "table1-test1"
  std::string_view text;
};

/// All embedded scenarios, sorted by name.
std::span<const EmbeddedFile> scenarios();
/// The embedded scenario with that name, or nullptr.
const EmbeddedFile* findScenario(std::string_view name);

/// The portrayal files of resources/portrayal/ ("rules", "colours"), and one by name or nullptr.
std::span<const EmbeddedFile> portrayal();
const EmbeddedFile* findPortrayal(std::string_view name);

/// The scenario the main job runs.
inline constexpr std::string_view kDefaultScenario = "default";

}  // namespace reckoner::resources
