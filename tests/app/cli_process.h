#pragma once
// reckoner-cli run as a user runs it, for the tests of the command line: its exit code, stdout and
// stderr. RECKONER_CLI is the program's path (a compile definition of each test).
#include <QProcess>
#include <QString>
#include <QStringList>

namespace reckoner::test {

struct CliResult {
  int code;
  QString out, err;
};

/// Runs reckoner-cli with `args` to its end (the 120 s limit only stops a hung run).
inline CliResult runCli(const QStringList& args) {
  QProcess p;
  p.start(QStringLiteral(RECKONER_CLI), args);
  p.waitForFinished(120000);
  return {p.exitCode(), QString::fromUtf8(p.readAllStandardOutput()),
          QString::fromUtf8(p.readAllStandardError())};
}

}  // namespace reckoner::test
