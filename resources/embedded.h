#pragma once
// Files compiled into the programs: the scenarios of resources/scenarios/ by file stem.
#include <span>
#include <string_view>

namespace reckoner::resources {

struct EmbeddedFile {
  std::string_view name;  ///< file name without extension, e.g. "default", "table1-test1"
  std::string_view text;  ///< the file's bytes
};

/// All embedded scenarios, sorted by name.
std::span<const EmbeddedFile> scenarios();
/// The embedded scenario with that name, or nullptr.
const EmbeddedFile* findScenario(std::string_view name);

/// The portrayal files of resources/portrayal/ ("rules", "colours"), and one by name or nullptr.
std::span<const EmbeddedFile> portrayal();
const EmbeddedFile* findPortrayal(std::string_view name);

/// The embedded charts (S-57 cells by cell name; bytes, not text): the fictional "RK5SOUND".
std::span<const EmbeddedFile> charts();
const EmbeddedFile* findChart(std::string_view name);
inline constexpr std::string_view kDefaultChart = "RK5SOUND";

/// The scenario the main job runs.
inline constexpr std::string_view kDefaultScenario = "default";

}  // namespace reckoner::resources
