// reckoner: the ECDIS window.
//   reckoner [--scenario FILE|builtin:NAME] [--enc CELL.000|FOLDER|builtin:default] [--fresh] [--run]
//   reckoner --help | --version      (answered without a display: no window system is needed)
// Without arguments it reopens the last session's scenario and chart, or on a first run the embedded
// default chart (RK5SOUND) with the default scenario. --fresh ignores the remembered session.
#include <QApplication>
#include <QCommandLineParser>
#include <QCoreApplication>
#include <QIcon>
#include <QStringList>

#include "common/allocator_settings.h"
#include "reckoner_version.h"
#include "ui/main_window.h"

namespace {

struct Options {
  QCommandLineOption scenario{QStringLiteral("scenario"),
                              QStringLiteral("Scenario file (JSON) or builtin:NAME."),
                              QStringLiteral("FILE")};
  QCommandLineOption enc{QStringLiteral("enc"),
                         QStringLiteral("ENC cell (.000), folder of cells, or builtin:default."),
                         QStringLiteral("PATH")};
  QCommandLineOption fresh{QStringLiteral("fresh"),
                           QStringLiteral("Ignore the remembered session (first-run defaults).")};
  QCommandLineOption run{QStringLiteral("run"),
                         QStringLiteral("Start the simulation at once (at the remembered rate).")};
};

void describe(QCommandLineParser& parser, const Options& o) {
  parser.setApplicationDescription(QStringLiteral("Reckoner: dead-reckoning and target-tracking ECDIS"));
  parser.addHelpOption();
  parser.addVersionOption();
  parser.addOptions({o.scenario, o.enc, o.fresh, o.run});
}

/// True when the command line parses and asks only for --help or --version: then no window system is
/// needed (QApplication would abort without a display). A line that does not parse here (Qt's own
/// options such as -platform) goes to QApplication, which takes those out first.
bool asksOnlyForHelpOrVersion(int argc, char** argv, const Options& o) {
  QStringList args;
  for (int i = 0; i < argc; ++i) args << QString::fromLocal8Bit(argv[i]);
  QCommandLineParser parser;
  describe(parser, o);
  if (!parser.parse(args)) return false;
  return parser.isSet(QStringLiteral("help")) || parser.isSet(QStringLiteral("help-all")) ||
         parser.isSet(QStringLiteral("version"));
}

}  // namespace

int main(int argc, char** argv) {
  reckoner::applyAllocatorSettings();
  QCoreApplication::setOrganizationName(QStringLiteral("Reckoner"));
  QCoreApplication::setApplicationName(QStringLiteral("reckoner"));
  QCoreApplication::setApplicationVersion(QStringLiteral(RECKONER_VERSION));
  const Options o;
  QCommandLineParser parser;
  describe(parser, o);
  if (asksOnlyForHelpOrVersion(argc, argv, o)) {
    const QCoreApplication app(argc, argv);
    parser.process(app);  // prints the help or the version and exits
    return 0;
  }

  const QApplication app(argc, argv);
  parser.process(app);
  // The installed desktop entry and icon (resources/package/): the icon from the theme when installed.
  QGuiApplication::setDesktopFileName(QStringLiteral("reckoner"));
  QApplication::setWindowIcon(QIcon::fromTheme(QStringLiteral("reckoner")));
  reckoner::ui::MainWindowOptions options;
  options.scenarioPath = parser.value(o.scenario).toStdString();
  options.encPath = parser.value(o.enc).toStdString();
  options.restoreSession = !parser.isSet(o.fresh);
  reckoner::ui::MainWindow window(options);
  window.show();
  if (parser.isSet(o.run)) window.setRate(10.0);
  return QApplication::exec();
}
