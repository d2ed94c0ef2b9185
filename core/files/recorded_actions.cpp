#include "files/recorded_actions.h"

#include <algorithm>
#include <cstdlib>
#include <optional>
#include <string>

#include "alerts/alert.h"

namespace reckoner::files {
namespace {

/// The number after `key=` in "k1=v1;k2=v2", all of it a number.
std::optional<double> valueOf(const std::string& text, const std::string& key) {
  const std::string k = key + '=';
  std::size_t at = 0;
  while (at < text.size()) {
    const std::size_t end = std::min(text.find(';', at), text.size());
    if (text.compare(at, k.size(), k) == 0) {
      const std::string v = text.substr(at + k.size(), end - at - k.size());
      char* stop = nullptr;
      const double d = std::strtod(v.c_str(), &stop);
      if (v.empty() || *stop != '\0') return std::nullopt;
      return d;
    }
    at = end + 1;
  }
  return std::nullopt;
}

std::optional<std::uint32_t> mmsiOf(const std::string& subject) {
  if (subject.rfind("mmsi:", 0) != 0) return std::nullopt;
  const std::string v = subject.substr(5);
  char* stop = nullptr;
  const unsigned long m = std::strtoul(v.c_str(), &stop, 10);
  if (v.empty() || *stop != '\0' || m > 999'999'999UL) return std::nullopt;
  return static_cast<std::uint32_t>(m);
}

std::optional<alerts::AlertId> alertOf(const std::string& subject) {
  if (subject.rfind("alert:", 0) != 0) return std::nullopt;
  const std::size_t colon = subject.rfind(':');
  if (colon <= 5) return std::nullopt;
  const std::string name = subject.substr(6, colon - 6), source = subject.substr(colon + 1);
  char* stop = nullptr;
  const long s = std::strtol(source.c_str(), &stop, 10);
  if (source.empty() || *stop != '\0') return std::nullopt;
  for (int k = 0; k < alerts::kAlertKindCount; ++k)
    if (name == alerts::traitsOf(static_cast<alerts::AlertKind>(k)).name)
      return alerts::AlertId{static_cast<alerts::AlertKind>(k), static_cast<int>(s)};
  return std::nullopt;
}

}  // namespace

bool applyOperatorAction(const OperatorAction& a, sim::LiveWatch& watch) {
  try {
    if (a.action == "acknowledge") {
      const auto id = alertOf(a.subject);
      if (!id) return false;
      watch.acknowledge(*id);
      return true;
    }
    if (a.action == "silence_all") {
      watch.silenceAll();
      return true;
    }
    if (a.action == "cpa_limits") {
      const auto cpa = valueOf(a.value, "cpa_m"), tcpa = valueOf(a.value, "tcpa_s");
      if (!cpa || !tcpa) return false;
      watch.setCpaLimits(*cpa, *tcpa);
      return true;
    }
    if (a.action == "dr_limit") {
      const auto m = valueOf(a.value, "m");
      if (!m) return false;
      watch.setDrLimit(*m);
      return true;
    }
    if (a.action == "ais_activate" || a.action == "ais_sleep" || a.action == "ais_select") {
      const auto mmsi = mmsiOf(a.subject);
      if (!mmsi) return false;
      if (a.action == "ais_select")
        watch.select(*mmsi);
      else
        watch.activate(*mmsi, a.action == "ais_activate");
      return true;
    }
  } catch (const std::exception&) {  // a limit the watch refuses: as in the run, where it was refused
    return false;
  }
  return false;
}

ActionReplayer::ActionReplayer(std::vector<OperatorAction> actions) : actions_(std::move(actions)) {
  std::stable_sort(actions_.begin(), actions_.end(), [](const OperatorAction& x, const OperatorAction& y) {
    return x.afterBatch < y.afterBatch;
  });
}

void ActionReplayer::afterBatch(std::int64_t batch, sim::LiveWatch& watch) {
  for (; next_ < actions_.size() && actions_[next_].afterBatch <= batch; ++next_)
    (applyOperatorAction(actions_[next_], watch) ? applied_ : skipped_) += 1;
}

}  // namespace reckoner::files
