#pragma once
// The GUI thread's timings of a MainWindow (frame arrivals, repaints, plot refreshes) as benchmark
// counters: p50, p99, max, the number of events and the largest of each kind.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <vector>

#include "ui/main_window.h"

namespace reckoner::bench {

inline void guiTimingCounters(const ui::MainWindow& w, benchmark::State& state) {
  using Kind = ui::MainWindow::GuiTiming::Kind;
  std::vector<double> ms;
  std::array<double, 3> maxOf{};
  for (const auto& g : w.guiTimings()) {
    ms.push_back(g.ms);
    auto& m = maxOf[static_cast<std::size_t>(g.kind)];
    m = std::max(m, g.ms);
  }
  std::sort(ms.begin(), ms.end());
  const auto pct = [&ms](double p) {
    return ms.empty()
               ? 0.0
               : ms[std::min(ms.size() - 1, static_cast<std::size_t>(p * static_cast<double>(ms.size())))];
  };
  state.counters["gui_p50_ms"] = pct(0.50);
  state.counters["gui_p99_ms"] = pct(0.99);
  state.counters["gui_max_ms"] = ms.empty() ? 0.0 : ms.back();
  state.counters["gui_events"] = static_cast<double>(ms.size());
  state.counters["max_frame_ms"] = maxOf[static_cast<std::size_t>(Kind::Frame)];
  state.counters["max_repaint_ms"] = maxOf[static_cast<std::size_t>(Kind::Repaint)];
  state.counters["max_plots_ms"] = maxOf[static_cast<std::size_t>(Kind::Plots)];
}

}  // namespace reckoner::bench
