// reckoner: the ECDIS window.
//   reckoner [--scenario FILE|builtin:NAME] [--enc CELL.000|FOLDER|builtin:default] [--fresh]
// Without arguments it reopens the last session's scenario and chart, or on a first run the embedded
// default chart (RK5SOUND) with the default scenario. --fresh ignores the remembered session.
#include <QApplication>
#include <QCommandLineParser>

#include "ui/main_window.h"

int main(int argc, char** argv) {
  QApplication app(argc, argv);
  QApplication::setOrganizationName(QStringLiteral("Reckoner"));
  QApplication::setApplicationName(QStringLiteral("reckoner"));
  QApplication::setApplicationVersion(QStringLiteral(RECKONER_VERSION));

  QCommandLineParser parser;
  parser.setApplicationDescription(QStringLiteral("Reckoner: dead-reckoning and target-tracking ECDIS"));
  parser.addHelpOption();
  parser.addVersionOption();
  const QCommandLineOption scenario(QStringLiteral("scenario"),
                                    QStringLiteral("Scenario file (JSON) or builtin:NAME."),
                                    QStringLiteral("FILE"));
  const QCommandLineOption enc(QStringLiteral("enc"),
                               QStringLiteral("ENC cell (.000), folder of cells, or builtin:default."),
                               QStringLiteral("PATH"));
  const QCommandLineOption fresh(QStringLiteral("fresh"),
                                 QStringLiteral("Ignore the remembered session (first-run defaults)."));
  const QCommandLineOption run(QStringLiteral("run"),
                               QStringLiteral("Start the simulation at once (at the remembered rate)."));
  parser.addOptions({scenario, enc, fresh, run});
  parser.process(app);

  reckoner::ui::MainWindowOptions options;
  options.scenarioPath = parser.value(scenario).toStdString();
  options.encPath = parser.value(enc).toStdString();
  options.restoreSession = !parser.isSet(fresh);
  reckoner::ui::MainWindow window(options);
  window.show();
  if (parser.isSet(run)) window.setRate(10.0);
  return QApplication::exec();
}
