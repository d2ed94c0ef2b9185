#pragma once
// One ARPA track of the bank (track_manager.h): its status, its filter, and the record the tracker's
// components read and write (the sweep history for the initiator and the deleter, the last radar
// update, input estimation's window, the tags of the plots used).
#include <array>
#include <cstdint>

#include "estimation/divergence_guard.h"
#include "tracking/input_window.h"
#include "tracking/track_filter.h"

namespace reckoner::track {

enum class TrackStatus : std::uint8_t { Tentative, Confirmed, Lost };
const char* trackStatusName(TrackStatus s);

struct Track {
  Track(int trackId, TrackFilter f) : id(trackId), filter(std::move(f)) {}
  int id = 0;
  TrackStatus status = TrackStatus::Tentative;
  TrackFilter filter;
  bool manual = false;
  bool dangerous = false;
  TimeUs initiatedUs = 0;
  TimeUs lastPlotUs = 0;
  TimeUs lostUs = 0;
  std::uint32_t history = 0;  ///< bit k: seen in the k-th most recent completed sweep
  int sweeps = 0;             ///< completed sweeps since initiation
  bool seenThisSweep = false;
  int radarUpdates = 0;
  est::UpdateReport<2> lastRadar;
  InputWindow<est::ttkf::kStateDim> inputWindow{1};  ///< input estimation (when enabled)
  TimeUs lastRadarUs = -1;                           ///< time of the last applied radar update
  bool manoeuvring = false;          ///< the manoeuvre flag: input estimation's (ekf-ie) or the IMM's
  est::ttkf::Belief lastUpdate;      ///< right after the last radar update: a lost track is shown here
  std::array<int, 10> recentTags{};  ///< tags of the last plots used (ring)
  int tagCount = 0;
  /// The filter's divergence guard (TrackManager judges every radar update and AIS report with it).
  est::DivergenceGuard guard;

  /// The most frequent tag among the last plots used (-1 if none): the true target in simulation.
  [[nodiscard]] int tag() const;
  [[nodiscard]] bool active() const { return status != TrackStatus::Lost; }
};

}  // namespace reckoner::track
