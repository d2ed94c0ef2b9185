#include "support/campaign_tools.h"

#include <QFile>
#include <QProcess>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "support/resource_limits.h"

namespace reckoner::test {

QString toolPath(const char* compiled, const char* env) {
  const QByteArray e = qgetenv(env);
  return e.isEmpty() ? QString(compiled) : QString::fromLocal8Bit(e);
}

bool runTool(const QString& program, const QStringList& args, QString& err, int cpuSeconds) {
  QProcess p;
  limitChildren(p, cpuSeconds);
  p.start(program, args);
  if (!p.waitForFinished(-1) || p.exitStatus() != QProcess::NormalExit || p.exitCode() != 0) {
    err = program + " " + args.join(' ') + ": " + QString::fromUtf8(p.readAllStandardError()).left(400);
    return false;
  }
  return true;
}

std::vector<std::string> splitFields(const std::string& line, char sep) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : line) {
    if (c == sep) {
      out.push_back(cur);
      cur.clear();
    } else if (c != '\r' && c != '\n') {
      cur += c;
    }
  }
  out.push_back(cur);
  return out;
}

const std::string& Csv::get(const std::vector<std::string>& row, const char* name) const {
  const auto c = column.find(name);
  if (c == column.end()) throw std::runtime_error(std::string("no column ") + name);
  return row[c->second];
}

double Csv::number(const std::vector<std::string>& row, const char* name) const {
  return std::stod(get(row, name));
}

Csv readCsv(const QString& path) {
  QFile f(path);
  if (!f.open(QIODevice::ReadOnly)) throw std::runtime_error("cannot read " + path.toStdString());
  Csv csv;
  const std::vector<std::string> header = splitFields(f.readLine().toStdString(), ',');
  for (std::size_t i = 0; i < header.size(); ++i) csv.column[header[i]] = i;
  while (!f.atEnd()) {
    std::vector<std::string> v = splitFields(f.readLine().toStdString(), ',');
    if (v.size() == header.size()) csv.rows.push_back(std::move(v));
  }
  return csv;
}

double percentile95(std::vector<double> v) {
  if (v.empty()) return std::numeric_limits<double>::infinity();
  std::sort(v.begin(), v.end());
  const auto rank = static_cast<std::size_t>(std::ceil(0.95 * static_cast<double>(v.size())));
  return v[std::max<std::size_t>(rank, 1) - 1];  // nearest rank
}

}  // namespace reckoner::test
