#pragma once
// What the campaign tests on independent data share (tests/app/tst_independent_*.cpp): running the
// generator and reckoner-cli as a user would, reading their CSV files, nearest-rank percentiles. Nothing
// here comes from core/: the scoring stays independent of the code it scores.
#include <QString>
#include <QStringList>

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace reckoner::test {

/// The compiled-in path of a tool, unless the environment variable `env` names another.
QString toolPath(const char* compiled, const char* env);

/// Runs program under limitChildren(cpuSeconds) and waits for it; false with err set (the command and
/// the start of its stderr) unless it exits 0.
bool runTool(const QString& program, const QStringList& args, QString& err, int cpuSeconds = 300);

/// The fields of one line split at sep, CR and LF dropped.
std::vector<std::string> splitFields(const std::string& line, char sep);

/// A CSV file with a header row; rows whose field count differs from the header's are dropped.
struct Csv {
  std::map<std::string, std::size_t> column;
  std::vector<std::vector<std::string>> rows;
  /// Throws std::runtime_error for a column the header lacks.
  const std::string& get(const std::vector<std::string>& row, const char* name) const;
  double number(const std::vector<std::string>& row, const char* name) const;
};
/// Throws std::runtime_error when the file cannot be read.
Csv readCsv(const QString& path);

/// Nearest-rank 95th percentile; infinity for no values.
double percentile95(std::vector<double> v);

}  // namespace reckoner::test
