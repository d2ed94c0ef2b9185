// Both programs' --version (docs/packaging.md, "Version"): the version the build wrote from git
// describe, valid as a Debian version, printed without a display. reckoner --help too: the man page
// is made from it at build time, on machines with no display.
#include <QProcess>
#include <QProcessEnvironment>
#include <QRegularExpression>
#include <QTest>

#include "reckoner_version.h"

class TestVersion : public QObject {
  Q_OBJECT

  struct Result {
    int code;
    QString out, err;
  };

  /// The program run with no display of any kind: no X, no Wayland, no Qt platform chosen.
  static Result headless(const QString& program, const QStringList& args) {
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    for (const char* v : {"DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM"})
      env.remove(QString::fromLatin1(v));
    QProcess p;
    p.setProcessEnvironment(env);
    p.start(program, args);
    if (!p.waitForFinished(60000)) return {-1, {}, QStringLiteral("did not finish")};
    return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -2,
            QString::fromUtf8(p.readAllStandardOutput()), QString::fromUtf8(p.readAllStandardError())};
  }

 private slots:
  void theVersionIsADebianVersionFromGitDescribe() {
    const QString version = QStringLiteral(RECKONER_VERSION);
    // Debian policy 5.6.12: an upstream version starts with a digit; no hyphen without a revision.
    QVERIFY2(QRegularExpression(QStringLiteral("^[0-9][A-Za-z0-9.+~]*$")).match(version).hasMatch(),
             qPrintable(version));
    const QString describe = QStringLiteral(RECKONER_GIT_DESCRIBE);
    if (describe.isEmpty()) QSKIP("not built from a git work tree: the version is PROJECT_VERSION");
    // The describe's hash (no tag: the describe is the hash) is in the version, and so is "dirty".
    const QRegularExpressionMatch hash =
        QRegularExpression(QStringLiteral("(?:^|-g)([0-9a-f]{7,})(?:-dirty)?$")).match(describe);
    if (hash.hasMatch())
      QVERIFY2(version.contains(".g" + hash.captured(1)), qPrintable(version + " " + describe));
    QCOMPARE(version.endsWith(QStringLiteral(".dirty")), describe.endsWith(QStringLiteral("-dirty")));
  }

  void theWindowPrintsItsVersionWithoutADisplay() {
    const Result r = headless(QStringLiteral(RECKONER_GUI), {QStringLiteral("--version")});
    QVERIFY2(r.code == 0, qPrintable(r.err));
    QCOMPARE(r.out, QStringLiteral("reckoner " RECKONER_VERSION "\n"));
  }

  void theWindowPrintsItsHelpWithoutADisplay() {
    const Result r = headless(QStringLiteral(RECKONER_GUI), {QStringLiteral("--help")});
    QVERIFY2(r.code == 0, qPrintable(r.err));
    for (const char* option : {"--scenario <FILE>", "--enc <PATH>", "--fresh", "--run", "--version"})
      QVERIFY2(r.out.contains(QString::fromLatin1(option)), qPrintable(r.out));
  }

  void theCliPrintsItsVersion() {
    const Result r = headless(QStringLiteral(RECKONER_CLI), {QStringLiteral("--version")});
    QCOMPARE(r.code, 0);
    // GNU style (help2man reads the first line): the program's version, then its libraries'.
    QVERIFY2(r.out.startsWith(QStringLiteral("reckoner-cli " RECKONER_VERSION "\nEigen ")),
             qPrintable(r.out));
    QVERIFY(r.err.isEmpty());
  }
};

QTEST_GUILESS_MAIN(TestVersion)
#include "tst_version.moc"
