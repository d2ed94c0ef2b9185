#pragma once
// A simulated AIS transponder on a target (docs/ais.md, "Simulated transmitters"): what a class A
// (SOTDMA) or class B (CS) station, or a search and rescue device (AIS-SART, MOB, EPIRB-AIS), sends and
// when, as a receiver on own ship hears it.
//  - Reporting: class A every 10 s at 0-14 kn (3 1/3 s while changing course), 6 s at 14-23 kn (2 s
//    turning), 2 s above 23 kn (a simulated ship is under way, never at anchor: 180 s does not apply); class
//    B every 30 s above 2 kn, else 180 s (ITU-R M.1371-5 Annex 1 Tables 1 and 2). "Changing course": turning
//    faster than 5 degrees in 30 s.
//  - Static data: type 5 (class A) or type 24 parts A and B (class B) soon after the start and every
//    6 minutes, with the antenna's place on the hull (to bow, stern, port, starboard).
//  - A search and rescue device (IEC 61097-14): a burst of eight type 1 reports (status 14 active, 15 in
//    test; no heading, no ROT) once a minute, one second apart, and a type 14 "SART ACTIVE" ("MOB ...",
//    "EPIRB ...", "... TEST" in test) every static interval (4 minutes by default); no static data.
//  - Latency: the position is the transponder's last GNSS fix (whole UTC seconds), taken a random
//    latency (uniform in [latencyMinS, latencyMaxS]) before the transmission; the message's time stamp
//    is that fix's UTC second. The receiver hears it at the transmission time.
//  - Errors: the GNSS antenna's position has a Gauss-Markov error per axis (sd, correlation time), its
//    velocity a Gauss-Markov error (sd, short correlation time); SOG to 0.1 kn, COG to 0.1 degree and
//    the position to 1/10000 minute, as the message carries them; class A heading to the degree with
//    a white error; a fraction of the messages is lost (slot collisions, fading).
// The truth is the hull's centre (what the radar sees); the transponder reports its antenna, which is
// offset from the centre by the dimensions. Plain C++; the time base of the UTC second is the run's
// clock (t = 0 at a whole minute).
#include <cstdint>
#include <deque>
#include <string>
#include <vector>

#include "common/rng.h"
#include "common/time.h"
#include "geo/local_frame.h"
#include "io/ais.h"

namespace reckoner::sensors {

enum class AisStationClass : std::uint8_t { A, B, Sart };

struct AisTransmitterSpec {
  AisStationClass cls = AisStationClass::A;
  std::uint32_t mmsi = 0;  ///< 1 .. 999999999
  std::string shipName;    ///< up to 20 characters of the six-bit alphabet (empty: not sent)
  int shipType = 70;       ///< 1..99 (70: cargo)
  /// The GNSS antenna's distances to the bow, stern, port and starboard side, metres (all 0: the
  /// station does not send its dimensions).
  int toBowM = 0, toSternM = 0, toPortM = 0, toStarboardM = 0;
  double positionSdM = 4.0;             ///< per axis, Gauss-Markov
  double positionCorrelationS = 120.0;  ///< correlation time of the position error
  double velocitySdMps = 0.05;          ///< per axis, Gauss-Markov
  double velocityCorrelationS = 5.0;    ///< correlation time of the velocity error
  double headingSdDeg = 1.0;            ///< class A heading sensor, white
  double latencyMinS = 0.2, latencyMaxS = 1.5;
  double lossProbability = 0.05;  ///< of any message, [0, 1)
  double staticIntervalS = 360.0;
  /// A search and rescue device in test mode (navigational status 15, "... TEST").
  bool test = false;
  /// The spec with the class's defaults: class B a cheaper receiver (6 m, 0.1 m/s), no heading, up to
  /// 3 s of latency.
  static AisTransmitterSpec defaults(AisStationClass cls);
  /// Empty when valid, else the first problem (field names as in the scenario format).
  [[nodiscard]] std::string check() const;
};

/// What the hull does at an instant (grid frame): centre position, ground velocity, heading, turn rate.
struct AisHullState {
  TimeUs timeUs = 0;
  geo::GridPoint position;
  double vxMps = 0.0, vyMps = 0.0;
  double headingRad = 0.0;  ///< grid
  double turnRateRadPerS = 0.0;
};

/// One message as a receiver hears it.
struct AisReception {
  TimeUs rxUs = 0;
  io::AisMessage message;
  int sourceTarget = -1;  ///< the scenario's target id (scoring only, never given to the tracker)
  TimeUs fixUs = 0;       ///< the fix time of a position report (scoring only)
};

/// The antenna's offset from the hull's centre, forward and to starboard, metres (0 when unknown).
struct AntennaOffset {
  double forwardM = 0.0, starboardM = 0.0;
  bool known = false;
};
AntennaOffset antennaOffset(int toBowM, int toSternM, int toPortM, int toStarboardM);

class AisTransmitter {
 public:
  /// Throws std::invalid_argument when spec.check() fails. The first report comes at a random phase
  /// of the first interval after startUs.
  AisTransmitter(const AisTransmitterSpec& spec, int targetId, Rng rng, TimeUs startUs);

  /// Records the hull at a time (increasing; the engine's step ends) and appends every message sent in
  /// (last call, hull.timeUs] to out. frame converts grid to WGS 84.
  void advance(const AisHullState& hull, const geo::LocalFrame& frame, std::vector<AisReception>& out);
  [[nodiscard]] const AisTransmitterSpec& spec() const { return spec_; }
  /// The nominal interval at this hull state, seconds.
  [[nodiscard]] double intervalS(const AisHullState& hull) const;

 private:
  void positionReport(TimeUs txUs, const geo::LocalFrame& frame, std::vector<AisReception>& out);
  void staticReports(TimeUs txUs, std::vector<AisReception>& out);
  [[nodiscard]] const AisHullState& fixAt(TimeUs t) const;
  void advanceErrors(TimeUs t);

  AisTransmitterSpec spec_;
  int targetId_;
  Rng rng_;
  std::deque<AisHullState> history_;  ///< recent hull states (bounded: the latency window)
  TimeUs nextReportUs_ = 0, nextStaticUs_ = 0;
  int burstSent_ = 0;  ///< reports of the device's current burst sent
  TimeUs errorUs_ = -1;
  double errX_ = 0.0, errY_ = 0.0, errVx_ = 0.0, errVy_ = 0.0;
};

}  // namespace reckoner::sensors
