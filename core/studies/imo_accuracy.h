#pragma once
// The ARPA accuracy test of IMO MSC.192(79) (A.823(19) Annex 3 scenarios): over Monte Carlo runs,
// the 95th percentile of each tracked quantity's error at 1 and 3 minutes after acquisition against
// the standard's limits. docs/ttkf.md has the table and how it is measured.
#include <cstdint>
#include <string>
#include <vector>

#include "sim/scenario.h"

namespace reckoner::studies {

enum class ImoQuantity : std::uint8_t { RelativeCourse, RelativeSpeed, Cpa, Tcpa, TrueCourse, TrueSpeed };
inline constexpr int kImoQuantityCount = 6;
const char* imoQuantityName(ImoQuantity q);
const char* imoQuantityUnit(ImoQuantity q);

struct ImoCell {
  bool required = false;  ///< the standard sets a limit at this time
  double p95 = 0.0;       ///< 95th percentile of the absolute error (unit: imoQuantityUnit)
  double limit = 0.0;     ///< the limit, percentages already converted with the true value
  bool pass = false;
};

struct ImoRow {
  ImoQuantity quantity;
  ImoCell at1Min;
  ImoCell at3Min;
};

struct ImoResult {
  std::string scenario;
  int runs = 0;
  int tracked = 0;  ///< runs in which the target had a track at 3 minutes
  double trueRelativeSpeedKn = 0.0;
  double trueSpeedKn = 0.0;
  std::vector<ImoRow> rows;
  bool pass = false;
};

/// Runs the scenario `runs` times (seeds seed, seed + 1, ...) and scores its first target. Throws
/// std::invalid_argument if the scenario has no target or no radar.
ImoResult evaluateImo(const sim::Scenario& scenario, int runs, int threads, std::uint64_t seed);

}  // namespace reckoner::studies
