#pragma once
// alerts.csv (docs/outputs.md, "Live input"): one row per alert log entry (alerts::AlertLogEntry), as a
// live run writes them: the UTC of the change, the run's seconds, the event, priority, kind, source and
// the alert's text.
#include <string>

#include "alerts/alert.h"
#include "common/time.h"

namespace reckoner::files {

std::string alertCsvHeader();
/// The entry's time is on the alert manager's clock, whose zero is zeroUtc.
std::string alertCsvLine(const alerts::AlertLogEntry& e, UtcUs zeroUtc);

}  // namespace reckoner::files
