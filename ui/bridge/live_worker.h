#pragma once
// The window's Live mode in its own thread (docs/gui.md, "Live"): a QObject living in a QThread that
// takes the lines of the window's connections (conn::ConnectionHub, owned by the GUI thread; take() is
// safe from any thread) and runs them through the live session (sim::LiveSession: the replay's reader,
// DRKF and track bank) and the watch (sim::LiveWatch: alerts, the AIS target table), and sends LiveFrame
// values to the GUI the way SimulationWorker does: at most one in flight, at most ~30 per second, the
// epochs in between folded into the frame's history. The frames carry no truth. A timer brings the
// AIS table and the alerts up to the clock once a second when no line arrives.
#include <QElapsedTimer>
#include <QObject>
#include <QTimer>
#include <memory>
#include <optional>
#include <span>

#include "connections/connection_hub.h"
#include "connections/nmea_destination.h"
#include "files/live_output.h"
#include "files/record_playback.h"
#include "files/recorded_actions.h"
#include "files/voyage_recorder.h"
#include "sim/live_session.h"
#include "sim/live_watch.h"
#include "sim/nmea_output.h"
#include "ui/bridge/frame_samples.h"
#include "ui/bridge/live_frame.h"
#include "ui/bridge/voyage_guard.h"

namespace reckoner::ui {

class LiveWorker : public QObject {
  Q_OBJECT
 public:
  explicit LiveWorker(QObject* parent = nullptr);
  ~LiveWorker() override;

  // Called in the worker's thread (queued from the controller).
  /// Starts a run on the hub's lines (the hub must outlive it: stop() first); a run in progress ends.
  /// Emits failed() when the options are unusable.
  void start(conn::ConnectionHub* hub, const sim::LiveOptions& options, const sim::LiveWatchSettings& watch,
             quint64 generation);
  /// Ends the run: the lines still queued are read, the session finished, a last frame sent.
  void stop();
  /// The voyage record of the live runs started from now on (files::VoyageRecorder; a new file, as
  /// `reckoner-cli live --record`): every line, the estimates, the alerts, the operator's actions and
  /// the charts shown. Empty: none. A file that cannot be made is reported (failed()) and the run goes
  /// on unrecorded.
  void setRecordPath(const QString& path);
  /// Plays a voyage record back (docs/gui.md, "Playback") instead of the connections: its batches
  /// through a session and watch made with the recorded settings (files::RecordPlayback), to a clock
  /// that starts paused at the record's first input; the frames are a live run's, with the playback's
  /// state. Emits failed() naming the file when it cannot be read.
  void startPlayback(const QString& path, quint64 generation);
  /// The playback clock's rate: 0 pauses, 1 the recorded pace, < 0 as fast as possible.
  void setPlaybackRate(double rate);
  /// The playback clock to utc (within the record): forward at full speed, back by playing again from
  /// the start (the first frame after says restarted). The rate is kept.
  void seekPlayback(qint64 utc);
  void frameConsumed();
  void acknowledgeAlert(reckoner::alerts::AlertId id);
  void silenceAlerts();
  /// The operator's CPA (m) and TCPA (s) limits for radar tracks and AIS targets.
  void setCpaLimits(double cpaM, double tcpaS);
  void setDrLimit(double metres);
  /// Operator activation of an AIS target (true) or back to sleeping.
  void activateAis(quint32 mmsi, bool on);
  void selectAis(quint32 mmsi);
  /// NMEA 0183 output of the live run (docs/outputs.md, "NMEA 0183 output"): own ship, tracks and
  /// alerts to udp://HOST:PORT, tcp://:PORT or a file, as `reckoner-cli live --nmea-out`; empty: none.
  /// Emits failed() naming the destination when it cannot be opened.
  void setNmeaOut(const QString& spec);
  /// The route monitored on the live estimate (none: none), now and in the runs started later; its
  /// XTE, RMB and APB go to the NMEA output.
  void setRoute(const std::optional<geo::Route>& route);
  /// The charts the window shows and the mariner's safety settings: the anti-grounding look-ahead.
  void setCharts(std::vector<charts::CellPtr> cells);
  void setSafety(const charts::SafetySettings& safety);
  /// Lines a batch takes from the hub at most (the rest wait for the next turn of the event loop, so
  /// commands and the frame acknowledgement are never held up by a flood).
  static constexpr std::size_t kBatchLines = 20'000;

 signals:
  void frameReady(const reckoner::ui::LiveFrame& frame);
  void failed(const QString& message);

 private:
  void consume();
  void tick();
  /// The watch after lines (or a tick: none): frames to the window, rows to the NMEA output and, with
  /// the lines, to the record.
  void absorb(std::optional<UtcUs> receivedUtc, std::span<const files::InputLine> lines = {});
  /// Starts the recorder for a run just started; reports and drops it when the file cannot be made.
  void startRecording(const sim::LiveOptions& options);
  void finishRecording();
  void recordAction(const char* action, const std::string& subject, const std::string& value);
  void recordCharts();
  void maybeEmit(bool force);
  /// The AIS table copied into the pending frame when it changed (at most 4 times a second unless forced).
  void refreshAis(bool force);
  /// The rows since the last call to the NMEA output (dropped without one: a watch does not grow).
  void sendNmea(const files::LiveBatch& out, const std::vector<sim::SimFrame>& frames);
  /// Playback: new session and watch with the record's settings (the start and a seek back).
  bool restartPlayback();
  /// Playback: the batches up to utc through the session (LiveRun::batch's order), for at most
  /// budgetNs of wall time and maxBatches; the clock to utc when all were fed, else to the last fed.
  void playTo(UtcUs utc, qint64 budgetNs, std::size_t maxBatches = SIZE_MAX);
  void playbackTick();
  void setPlaybackState();
  /// The route and the charts' answers given to the session now.
  void applyVoyage();

  conn::ConnectionHub* hub_ = nullptr;
  std::unique_ptr<sim::LiveSession> session_;
  std::unique_ptr<sim::LiveWatch> watch_;
  QTimer* timer_ = nullptr;
  QElapsedTimer wall_;
  qint64 lastEmitNs_ = 0, lastAisNs_ = 0;
  bool inFlight_ = false, dirty_ = false;
  quint64 sequence_ = 0, generation_ = 0;
  std::uint64_t lines_ = 0, aisVersion_ = 0;
  est::drkf::ProcessParams process_;
  LiveFrame pending_;
  FrameFolder folder_;
  QMetaObject::Connection linesConnection_;
  std::unique_ptr<conn::NmeaDestination> nmeaDest_;
  std::unique_ptr<sim::NmeaOutput> nmea_;
  std::optional<geo::Route> route_;
  VoyageGuard guard_;
  // Recording (null: none): the file for the next run, the recorder of this one, the rows a tick took
  // (recorded with the next batch), the cells shown (their loads and unloads are recorded).
  QString recordPath_;
  std::unique_ptr<files::VoyageRecorder> recorder_;
  files::LiveBatch unrecorded_;
  std::vector<charts::CellPtr> cells_, recordedCells_;
  QTimer* recordTimer_ = nullptr;
  // Playback (null: a live run on the hub).
  std::unique_ptr<files::RecordPlayback> playback_;
  QString playbackPath_;
  std::shared_ptr<const std::vector<files::RecordedAlert>> playbackAlerts_;
  std::optional<files::ActionReplayer> playbackActions_;  ///< the record's operator actions, applied again
  QTimer* playTimer_ = nullptr;
  double playbackRate_ = 0.0;
  UtcUs playbackClock_ = 0;
  qint64 lastPlayNs_ = 0;
};

}  // namespace reckoner::ui
