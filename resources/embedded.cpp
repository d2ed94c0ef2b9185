#include "resources/embedded.h"

namespace reckoner::resources {

const EmbeddedFile* findScenario(std::string_view name) {
  for (const auto& f : scenarios())
    if (f.name == name) return &f;
  return nullptr;
}

const EmbeddedFile* findPortrayal(std::string_view name) {
  for (const auto& f : portrayal())
    if (f.name == name) return &f;
  return nullptr;
}

const EmbeddedFile* findChart(std::string_view name) {
  for (const auto& f : charts())
    if (f.name == name) return &f;
  return nullptr;
}

}  // namespace reckoner::resources
