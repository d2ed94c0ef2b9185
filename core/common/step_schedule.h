#pragma once
// A value that changes at given times: an initial value and (time, value) changes in increasing time.
#include <algorithm>
#include <utility>
#include <vector>

#include "common/time.h"

namespace reckoner {

template <class T>
class StepSchedule {
 public:
  StepSchedule() = default;
  explicit StepSchedule(T initial) : initial_(std::move(initial)) {}

  /// Adds a change effective from timeUs on. Changes must be added in strictly increasing time;
  /// returns false (and ignores the change) otherwise.
  bool addChange(TimeUs timeUs, T value) {
    if (!changes_.empty() && timeUs <= changes_.back().first) return false;
    changes_.emplace_back(timeUs, std::move(value));
    return true;
  }

  /// An operator override: drops every change at or after timeUs, then adds (timeUs, value). Later
  /// scripted changes no longer apply; the schedule stays a faithful record of what happened.
  void overrideFrom(TimeUs timeUs, T value) {
    while (!changes_.empty() && changes_.back().first >= timeUs) changes_.pop_back();
    changes_.emplace_back(timeUs, std::move(value));
  }

  /// The value in force at timeUs (the last change at or before it).
  [[nodiscard]] const T& at(TimeUs timeUs) const {
    const auto it = std::upper_bound(changes_.begin(), changes_.end(), timeUs,
                                     [](TimeUs t, const auto& c) { return t < c.first; });
    return it == changes_.begin() ? initial_ : std::prev(it)->second;
  }

  [[nodiscard]] const T& initial() const { return initial_; }
  [[nodiscard]] const std::vector<std::pair<TimeUs, T>>& changes() const { return changes_; }

 private:
  T initial_{};
  std::vector<std::pair<TimeUs, T>> changes_;
};

}  // namespace reckoner
