// The window side of the live connections (docs/connections.md, "The window"): the connections
// dialog's table on a real hub with a UDP source on loopback, the form's inline spec errors, the
// settings round trip, the data monitor's filters, pause and bound, the status-bar indicator, and the
// three widgets rendered to PNG files to look at.
#include <QApplication>
#include <QComboBox>
#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QDir>
#include <QFile>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QTableView>
#include <QTemporaryDir>
#include <QTimer>
#include <QUdpSocket>
#include <QtTest>
#include <functional>

#include "connection_test_helpers.h"
#include "ui/panels/connection_indicator.h"
#include "ui/panels/connections_dialog.h"
#include "ui/panels/data_monitor.h"

using namespace reckoner::ui;
using conn_test::sentence;

namespace {

constexpr int kWaitMs = 30'000;  // generous: the machine is shared

/// Sends each line as its own datagram to 127.0.0.1:port.
void sendUdp(quint16 port, const std::vector<std::string>& lines) {
  QUdpSocket s;
  for (const auto& l : lines)
    s.writeDatagram(QByteArray::fromStdString(l + "\r\n"), QHostAddress::LocalHost, port);
}

QString cell(const QAbstractItemModel& m, int row, int column) {
  return m.index(row, column).data().toString();
}

QString screenshotDir() {
  QString dir = QCoreApplication::applicationDirPath() + "/screenshots";
  QDir().mkpath(dir);
  return dir;
}

/// Calls f with the modal form once it is up (the dialog's exec() runs its own loop), polling the
/// event loop; gives up after many tries (no form: no exec() to end either).
void whenFormIsUp(const std::function<void(ConnectionForm&)>& f, int tries = 3000) {
  QTimer::singleShot(10, qApp, [f, tries] {
    if (auto* form = qobject_cast<ConnectionForm*>(QApplication::activeModalWidget())) {
      f(*form);
    } else if (tries > 0) {
      whenFormIsUp(f, tries - 1);
    }
  });
}

QPushButton* buttonOf(QWidget& w, const QString& text) {
  for (auto* b : w.findChildren<QPushButton*>())
    if (b->text() == text) return b;
  return nullptr;
}

}  // namespace

class TstConnectionsDialog : public QObject {
  Q_OBJECT
 private slots:
  void dialogShowsALiveUdpSource() {
    // GIVEN a hub with a UDP source on a free loopback port, and the dialog on it
    const quint16 port = conn_test::freeUdpPort();
    conn::ConnectionHub hub(conn_test::fastRetry());
    hub.add(conn::parseSource("udp://127.0.0.1:" + std::to_string(port) + "?name=gps"));
    hub.start();
    ConnectionsDialog dialog(hub);
    ConnectionTableModel& model = *dialog.model();
    QCOMPARE(model.rowCount(), 1);
    QCOMPARE(cell(model, 0, ConnectionTableModel::Name), QStringLiteral("gps"));
    QCOMPARE(cell(model, 0, ConnectionTableModel::Spec),
             QStringLiteral("udp://127.0.0.1:%1?name=gps").arg(port));
    QCOMPARE(cell(model, 0, ConnectionTableModel::RoleColumn), QStringLiteral("nmea"));
    // WHEN sentences arrive (sent again until the dialog's own 1 s timer shows them: the first
    // datagrams may come before the socket is bound)
    const auto lines = conn_test::sentences(5);
    QTRY_VERIFY_WITH_TIMEOUT(
        (sendUdp(port, lines), cell(model, 0, ConnectionTableModel::Lines).toULongLong() >= 5), kWaitMs);
    // THEN the row shows it connected, its lines, no errors, and seen just now
    QCOMPARE(cell(model, 0, ConnectionTableModel::StateColumn), QStringLiteral("connected"));
    QCOMPARE(cell(model, 0, ConnectionTableModel::Errors), QStringLiteral("0"));
    QVERIFY(cell(model, 0, ConnectionTableModel::LastSeen).toDouble() < 5.0);
    QCOMPARE(model.index(0, ConnectionTableModel::Enabled).data(Qt::CheckStateRole).toInt(),
             static_cast<int>(Qt::Checked));

    // WHEN a sentence with a wrong checksum arrives THEN it is counted as an error
    std::string bad = sentence("GPZDA,120000.00,03,12,2026,00,00");
    bad.back() = bad.back() == '0' ? '1' : '0';
    QTRY_VERIFY_WITH_TIMEOUT(
        (sendUdp(port, {bad}), cell(model, 0, ConnectionTableModel::Errors).toInt() >= 1), kWaitMs);

    // WHEN the enabled box is unticked THEN the hub disables the source
    QVERIFY(model.setData(model.index(0, ConnectionTableModel::Enabled), Qt::Unchecked, Qt::CheckStateRole));
    QTRY_COMPARE_WITH_TIMEOUT(conn_test::statusOf(hub, "gps").state, conn::State::Disabled, kWaitMs);
    QCOMPARE(model.index(0, ConnectionTableModel::Enabled).data(Qt::CheckStateRole).toInt(),
             static_cast<int>(Qt::Unchecked));
    QVERIFY(!hub.sources().front().enabled);
    QVERIFY(model.setData(model.index(0, ConnectionTableModel::Enabled), Qt::Checked, Qt::CheckStateRole));
    QTRY_VERIFY_WITH_TIMEOUT((sendUdp(port, lines), model.refresh(),
                              cell(model, 0, ConnectionTableModel::StateColumn) == "connected"),
                             kWaitMs);
  }

  void addEditRemoveThroughTheModel() {
    // GIVEN an empty hub and its table
    conn::ConnectionHub hub(conn_test::fastRetry());
    ConnectionTableModel model(hub);
    QSignalSpy changed(&model, &ConnectionTableModel::sourcesChanged);
    // WHEN a bad spec is added THEN the error names the field, and nothing is added
    QString error = model.addSource("udp://:0", {}, conn::Role::Nmea, 0);
    QVERIFY2(error.contains("port") && error.contains("udp://:0"), qPrintable(error));
    error = model.addSource("ftp://host:1", {}, conn::Role::Nmea, 0);
    QVERIFY2(error.contains("kind") && error.contains("ftp"), qPrintable(error));
    error = model.addSource("udp://:10110?bogus=1", {}, conn::Role::Nmea, 0);
    QVERIFY2(error.contains("bogus"), qPrintable(error));
    QCOMPARE(model.rowCount(), 0);
    QCOMPARE(changed.count(), 0);
    // WHEN good specs are added (the form's name, role and priority over the spec) THEN they show
    QCOMPARE(model.addSource("udp://127.0.0.1:10110", "gps", conn::Role::Nmea, 5), QString());
    QCOMPARE(model.addSource("tcp://127.0.0.1:4001", {}, conn::Role::Radar, -3), QString());
    QCOMPARE(model.rowCount(), 2);
    QCOMPARE(model.configAt(0).priority, 5);
    QCOMPARE(cell(model, 1, ConnectionTableModel::Name), QStringLiteral("tcp:127.0.0.1:4001"));
    QCOMPARE(cell(model, 1, ConnectionTableModel::RoleColumn), QStringLiteral("radar"));
    QCOMPARE(changed.count(), 2);
    // WHEN a name is taken THEN the error says so
    error = model.addSource("udp://127.0.0.1:10111", "gps", conn::Role::Nmea, 0);
    QVERIFY2(error.contains("gps") && error.contains("taken"), qPrintable(error));
    QCOMPARE(model.rowCount(), 2);
    // WHEN a source is edited with a bad spec THEN it stays as it was; with a good one it is replaced
    error = model.editSource(0, "udp://127.0.0.1:99999", "gps", conn::Role::Nmea, 5);
    QVERIFY2(error.contains("port"), qPrintable(error));
    QCOMPARE(model.configAt(0).port, 10110);
    error = model.editSource(0, "udp://127.0.0.1:10112?reject=GSV", "gps", conn::Role::Nmea, 7);
    QCOMPARE(error, QString());
    QCOMPARE(model.rowCount(), 2);
    const auto it = std::find_if(model.configs().begin(), model.configs().end(),
                                 [](const conn::SourceConfig& c) { return c.name == "gps"; });
    QVERIFY(it != model.configs().end());
    QCOMPARE(it->port, 10112);
    QCOMPARE(it->priority, 7);
    QCOMPARE(it->filter.rejectTypes, std::vector<std::string>{"GSV"});
    // WHEN a source is removed THEN the hub has it no more
    QVERIFY(model.removeSource(0));
    QCOMPARE(model.rowCount(), 1);
    QCOMPARE(hub.sources().size(), std::size_t{1});
    QVERIFY(!model.removeSource(5));
  }

  void formShowsTheSpecErrorInline() {
    // GIVEN the Add form
    ConnectionForm form;
    auto* ok = form.findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok);
    // WHEN a bad spec is typed THEN its error names the field and OK is off
    form.specEdit()->setText("udp://:0");
    QVERIFY2(form.errorText().contains("port"), qPrintable(form.errorText()));
    QVERIFY(!ok->isEnabled());
    form.specEdit()->setText("serial://");
    QVERIFY2(form.errorText().contains("device"), qPrintable(form.errorText()));
    form.specEdit()->setText("udp://:70000");
    form.show();
    QVERIFY(QTest::qWaitForWindowExposed(&form));
    QVERIFY(form.grab().save(screenshotDir() + "/connection_form_error.png"));
    // WHEN the spec is good THEN no error, OK on, and its own options fill the fields
    form.specEdit()->setText("udp://:10110?role=radar&priority=4&name=arpa");
    QCOMPARE(form.errorText(), QString());
    QVERIFY(ok->isEnabled());
    QCOMPARE(form.role(), conn::Role::Radar);
    QCOMPARE(form.priority(), 4);
    QCOMPARE(form.name(), QStringLiteral("arpa"));
    // WHEN a source is edited THEN the form's spec leaves out what the fields hold
    form.setSource(conn::parseSource("tcp://host:10110?name=ais&priority=2&accept=VDM&enabled=0"));
    QCOMPARE(form.spec(), QStringLiteral("tcp://host:10110?accept=VDM"));
    QCOMPARE(form.name(), QStringLiteral("ais"));
    QCOMPARE(form.priority(), 2);
    const auto back = sourceFromForm(form.spec(), form.name(), form.role(), form.priority(), nullptr);
    QVERIFY(back.has_value());
    QCOMPARE(back->name, std::string("ais"));
    QCOMPARE(back->filter.acceptTypes, std::vector<std::string>{"VDM"});
  }

  void buttonsAddEditRemoveAndSave() {
    // GIVEN the dialog on an empty hub, saving into an INI file
    conn::ConnectionHub hub;
    QTemporaryDir dir;
    QSettings settings(dir.filePath("reckoner.ini"), QSettings::IniFormat);
    ConnectionsDialog dialog(hub, &settings);
    dialog.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dialog));
    QPushButton* add = buttonOf(dialog, "Add...");
    QPushButton* edit = buttonOf(dialog, "Edit...");
    QPushButton* remove = buttonOf(dialog, "Remove");
    QVERIFY(add && edit && remove);
    QVERIFY(!edit->isEnabled() && !remove->isEnabled());
    // WHEN Add is clicked, a bad spec typed, then a good one, then OK
    QString shownError;
    bool okWhileBad = true;
    whenFormIsUp([&](ConnectionForm& form) {
      QPushButton* ok = form.findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok);
      form.specEdit()->setText("udp://127.0.0.1:0");
      shownError = form.errorText();
      okWhileBad = ok->isEnabled();
      form.specEdit()->setText("udp://127.0.0.1:10110?reject=GSV");
      QTest::keyClicks(form.nameEdit(), "gps");
      ok->click();
      if (form.isVisible()) form.reject();  // OK refused: end exec() all the same, the test fails below
    });
    add->click();  // returns when the form is closed
    // THEN the form showed the error with OK off, and the source is in the hub and in the settings
    QVERIFY2(shownError.contains("port"), qPrintable(shownError));
    QVERIFY(!okWhileBad);
    QCOMPARE(dialog.model()->rowCount(), 1);
    QCOMPARE(hub.sources().front().name, std::string("gps"));
    QCOMPARE(loadConnections(settings).front(), hub.sources().front());
    // WHEN the row is selected and Edit changes the priority THEN the hub and settings have it
    dialog.table()->selectRow(0);
    QVERIFY(edit->isEnabled() && remove->isEnabled());
    QString editSpec;  // (nothing in the lambda may return early: the form must be closed)
    whenFormIsUp([&](ConnectionForm& form) {
      editSpec = form.spec();
      form.findChild<QSpinBox*>()->setValue(9);
      form.findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok)->click();
      if (form.isVisible()) form.reject();
    });
    edit->click();
    QCOMPARE(editSpec, QStringLiteral("udp://127.0.0.1:10110?reject=GSV"));
    QCOMPARE(hub.sources().front().priority, 9);
    QCOMPARE(loadConnections(settings).front().priority, 9);
    // WHEN Remove is clicked THEN the hub and the settings are empty
    dialog.table()->selectRow(0);
    remove->click();
    QCOMPARE(dialog.model()->rowCount(), 0);
    QVERIFY(hub.sources().empty());
    QVERIFY(loadConnections(settings).empty());
  }

  void settingsRoundTrip() {
    // GIVEN sources of every kind with options
    const std::vector<std::string> specs = {
        "udp://:10110",
        "udp://239.192.0.1:60001?name=lan&iface=lo",
        "tcp://127.0.0.1:10110?name=ais&role=nmea&priority=-5&accept=VDM,VDO&reject-talkers=GP",
        "serial:///dev/ttyUSB0:38400?enabled=0",
        "gpsd://localhost:2947?talkers=GP,GN&reject=GSV",
        "file:///tmp/rec.nmea?rate=x10",
        "tcp://127.0.0.1:4001?name=radar&role=radar&priority=3"};
    std::vector<conn::SourceConfig> sources;
    sources.reserve(std::size(specs));
    for (const auto& s : specs) sources.push_back(conn::parseSource(s));
    QTemporaryDir dir;
    const QString path = dir.filePath("reckoner.ini");
    {
      QSettings settings(path, QSettings::IniFormat);
      saveConnections(settings, sources);
    }
    // WHEN they are loaded back THEN they are equal, in order, without errors
    {
      QSettings settings(path, QSettings::IniFormat);
      QStringList errors;
      const auto loaded = loadConnections(settings, &errors);
      QVERIFY2(errors.isEmpty(), qPrintable(errors.join('\n')));
      QCOMPARE(loaded.size(), sources.size());
      for (std::size_t i = 0; i < sources.size(); ++i) QVERIFY2(loaded[i] == sources[i], specs[i].c_str());
      // WHEN fewer are saved THEN no old entry is left behind
      saveConnections(settings, {sources[0]});
    }
    {
      QSettings settings(path, QSettings::IniFormat);
      QCOMPARE(loadConnections(settings).size(), std::size_t{1});
      // WHEN an entry is bad (edited by hand) THEN it is skipped, its error names the file and field
      settings.beginWriteArray("connections/sources", 3);
      settings.setArrayIndex(1);
      settings.setValue("spec", "udp://:70000");
      settings.setArrayIndex(2);
      settings.setValue("spec", "udp://:10110");  // the name of entry 1 again
      settings.endArray();
    }
    QSettings settings(path, QSettings::IniFormat);
    QStringList errors;
    const auto loaded = loadConnections(settings, &errors);
    QCOMPARE(loaded.size(), std::size_t{1});
    QCOMPARE(errors.size(), 2);
    QVERIFY2(errors[0].contains(path) && errors[0].contains("port") && errors[0].contains("sources/2"),
             qPrintable(errors[0]));
    QVERIFY2(errors[1].contains("name") && errors[1].contains("taken"), qPrintable(errors[1]));
  }

  void dataMonitorFiltersPausesAndIsBounded() {
    // GIVEN two UDP sources and the data monitor
    const quint16 portA = conn_test::freeUdpPort();
    const quint16 portB = conn_test::freeUdpPort();
    conn::ConnectionHub hub(conn_test::fastRetry());
    hub.add(conn::parseSource("udp://127.0.0.1:" + std::to_string(portA) + "?name=gps"));
    hub.add(conn::parseSource("udp://127.0.0.1:" + std::to_string(portB) + "?name=gyro&reject=ROT"));
    hub.start();
    DataMonitor monitor(hub);
    QCOMPARE(monitor.sourceCombo()->count(), 3);  // all, gps, gyro
    const std::string rmc = sentence("GPRMC,120000.00,A,5400.000,N,01000.000,E,5.0,90.0,031226,,,A");
    const std::string hdt = sentence("HEHDT,90.0,T");
    const std::string rot = sentence("HEROT,0.5,A");
    // WHEN the text filter is RMC and both sources send
    monitor.setTextFilter("RMC");
    const auto rows = [&] { return monitor.model()->rowCount(); };
    QTRY_VERIFY_WITH_TIMEOUT((sendUdp(portA, {rmc, hdt}), sendUdp(portB, {hdt, rot}), rows() >= 3), kWaitMs);
    // THEN only RMC lines show, from gps, delivered, with a receive time
    for (int r = 0; r < rows(); ++r) {
      const auto& l = monitor.model()->lineAt(r);
      QCOMPARE(l.line, rmc);
      QCOMPARE(l.source, std::string("gps"));
      QCOMPARE(cell(*monitor.model(), r, MonitorModel::VerdictColumn), QStringLiteral("delivered"));
      QCOMPARE(cell(*monitor.model(), r, MonitorModel::Time).size(), 12);  // HH:MM:SS.mmm
    }
    // WHEN the filter is the gyro source and no text THEN its lines show with their verdicts only
    monitor.setTextFilter({});
    monitor.setSourceFilter("gyro");
    QTRY_VERIFY_WITH_TIMEOUT((sendUdp(portB, {hdt, rot}), rows() >= 4), kWaitMs);
    bool sawFiltered = false;
    for (int r = 0; r < rows(); ++r) {
      const auto& l = monitor.model()->lineAt(r);
      QCOMPARE(l.source, std::string("gyro"));
      if (l.line == rot) {
        QCOMPARE(l.verdict, conn::Verdict::Filtered);
        sawFiltered = true;
      }
    }
    QVERIFY(sawFiltered);
    // WHEN paused THEN new lines do not show; resumed THEN they do
    monitor.pauseButton()->click();
    QVERIFY(monitor.paused());
    const std::uint64_t lastShown = monitor.model()->lineAt(rows() - 1).index;
    const std::uint64_t before = hub.monitor({"gyro", {}, 0}, 1).back().index;
    QTRY_VERIFY_WITH_TIMEOUT((sendUdp(portB, {hdt}), hub.monitor({"gyro", {}, 0}, 1).back().index > before),
                             kWaitMs);
    monitor.refresh();
    QCOMPARE(monitor.model()->lineAt(rows() - 1).index, lastShown);
    monitor.pauseButton()->click();
    QVERIFY(!monitor.paused());
    QVERIFY(monitor.model()->lineAt(rows() - 1).index > lastShown);
    // WHEN bounded to 5 lines and more arrive THEN at most 5 show, the newest last
    monitor.setMaxLines(5);
    QVERIFY(rows() <= 5);
    // (sent once: QTRY evaluates its condition again after it held, so the condition has no sending
    // in it; the source is bound and heard by now)
    const auto burst = conn_test::sentences(20);
    sendUdp(portB, burst);
    QTRY_VERIFY_WITH_TIMEOUT(
        (monitor.refresh(), rows() == 5 && monitor.model()->lineAt(4).line == burst.back()), kWaitMs);
    for (int r = 1; r < rows(); ++r)
      QVERIFY(monitor.model()->lineAt(r).index > monitor.model()->lineAt(r - 1).index);
  }

  void aRealRecordingThroughTheWindow() {
    // GIVEN a real recording (B&G Zeus2 9, gpsd's regression log; ../shared, not in this repository)
    // played by a file source at 2,000 lines/s, the dialog and the data monitor on it
    const QString path = QStringLiteral(RECKONER_SHARED_DIR "/data/nmea/gpsd-bundg_zeus_9.log");
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) QSKIP(qPrintable("no " + path));
    std::uint64_t nonEmpty = 0, hdg = 0;
    while (!file.atEnd()) {
      const QByteArray line = file.readLine().trimmed();
      if (line.isEmpty()) continue;
      ++nonEmpty;
      if (line.contains("HDG")) ++hdg;
    }
    conn::ConnectionHub hub;
    hub.add(conn::parseSource("file://" + path.toStdString() + "?name=zeus&rate=2000"));
    hub.start();
    ConnectionsDialog dialog(hub);
    DataMonitor monitor(hub);
    monitor.setMaxLines(100'000);
    monitor.setTextFilter("HDG");
    // WHEN it has played to its end
    QTRY_COMPARE_WITH_TIMEOUT(cell(*dialog.model(), 0, ConnectionTableModel::StateColumn),
                              QStringLiteral("finished"), 60'000);
    dialog.model()->refresh();
    monitor.refresh();
    // THEN every line of the file is accounted for in the row, and the monitor shows heading lines only
    const conn::SourceStatus& st = *dialog.model()->statusAt(0);
    QCOMPARE(st.lines + st.errors() + st.filtered, nonEmpty);
    QCOMPARE(cell(*dialog.model(), 0, ConnectionTableModel::Lines).toULongLong(), st.lines);
    const int rows = monitor.model()->rowCount();
    QVERIFY(rows > 0);
    QVERIFY(static_cast<std::uint64_t>(rows) <= hdg);  // the hub's ring keeps the newest 2,000 lines
    for (int r = 0; r < rows; ++r) QVERIFY(monitor.model()->lineAt(r).line.find("HDG") != std::string::npos);
    qInfo("zeus: %llu lines in the file, %llu delivered, %llu errors, %d HDG rows in the monitor",
          static_cast<unsigned long long>(nonEmpty), static_cast<unsigned long long>(st.lines),
          static_cast<unsigned long long>(st.errors()), rows);
  }

  void indicatorLights() {
    const reckoner::UtcUs now = 1'700'000'000'000'000;
    conn::SourceStatus s;
    s.state = conn::State::Connected;
    QCOMPARE(indicatorLight(s, now), IndicatorLight::Amber);  // bound, nothing heard yet
    s.lastSeenUtc = now - 1'000'000;
    QCOMPARE(indicatorLight(s, now), IndicatorLight::Green);
    s.lastSeenUtc = now - 6'000'000;
    QCOMPARE(indicatorLight(s, now), IndicatorLight::Amber);  // silent for over 5 s
    s.state = conn::State::Connecting;
    QCOMPARE(indicatorLight(s, now), IndicatorLight::Amber);
    s.state = conn::State::WaitingRetry;
    QCOMPARE(indicatorLight(s, now), IndicatorLight::Amber);
    s.state = conn::State::Error;
    QCOMPARE(indicatorLight(s, now), IndicatorLight::Red);
    s.state = conn::State::Disabled;
    QCOMPARE(indicatorLight(s, now), IndicatorLight::Grey);
    s.state = conn::State::Finished;
    QCOMPARE(indicatorLight(s, now), IndicatorLight::Grey);
  }

  void widgetsOnALiveHubRenderToPng() {
    // GIVEN a hub with a live UDP source, a TCP source nobody listens to, and a disabled one
    const quint16 port = conn_test::freeUdpPort();
    conn::ConnectionHub hub(conn_test::fastRetry());
    hub.add(conn::parseSource("udp://127.0.0.1:" + std::to_string(port) + "?name=gps&priority=2"));
    hub.add(conn::parseSource("tcp://127.0.0.1:" + std::to_string(conn_test::freeTcpPort()) + "?name=ais"));
    hub.add(conn::parseSource("serial:///dev/ttyUSB0:38400?name=gyro&enabled=0"));
    hub.start();
    ConnectionsDialog dialog(hub);
    DataMonitor monitor(hub);
    monitor.resize(900, 300);
    ConnectionIndicator indicator(hub);
    const auto lines = conn_test::sentences(10);
    // WHEN the UDP source is heard and the TCP one has failed to connect
    QTRY_VERIFY_WITH_TIMEOUT(
        (sendUdp(port, lines), indicator.refresh(),
         !indicator.entries().empty() && indicator.entries()[0].light == IndicatorLight::Green &&
             indicator.entries()[1].light == IndicatorLight::Amber),
        kWaitMs);
    // THEN the indicator lights green, amber and grey, and every widget renders
    QCOMPARE(indicator.entries().size(), std::size_t{3});
    QCOMPARE(indicator.entries()[2].light, IndicatorLight::Grey);
    QVERIFY(indicator.entries()[0].text.startsWith("gps "));
    QVERIFY(indicator.entries()[0].text.endsWith("/s"));
    // (a rate is over the last second or more: sent until one shows)
    QTRY_VERIFY_WITH_TIMEOUT((sendUdp(port, lines), dialog.model()->refresh(),
                              dialog.model()->statusAt(0)->sentencesPerSecond > 0.0),
                             kWaitMs);
    QVERIFY(cell(*dialog.model(), 0, ConnectionTableModel::Rate).toDouble() > 0.0);
    indicator.refresh();
    monitor.refresh();
    QVERIFY(monitor.model()->rowCount() >= 10);
    dialog.show();
    monitor.show();
    indicator.adjustSize();
    indicator.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dialog));
    const QString dir = screenshotDir();
    QVERIFY(dialog.grab().save(dir + "/connections_dialog.png"));
    QVERIFY(monitor.grab().save(dir + "/data_monitor.png"));
    QVERIFY(indicator.grab().save(dir + "/connection_indicator.png"));
    // Every column of the table is wide enough for its header (nothing clipped).
    const QTableView* table = dialog.table();
    for (int c = 0; c < ConnectionTableModel::ColumnCount; ++c) {
      const QString header = dialog.model()->headerData(c, Qt::Horizontal, Qt::DisplayRole).toString();
      QVERIFY2(table->columnWidth(c) >= table->fontMetrics().horizontalAdvance(header), qPrintable(header));
    }
  }
};

QTEST_MAIN(TstConnectionsDialog)
#include "tst_connections_dialog.moc"
