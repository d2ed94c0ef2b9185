#pragma once
// RK_COMPARE_NEAR(actual, expected, tol): the near-comparison of every test. On failure it prints both
// expressions, both values, their difference and the tolerance, which QVERIFY(std::abs(a - b) < tol)
// cannot. A NaN or infinite value on either side fails, as does a negative or non-finite tolerance.
// QEXPECT_FAIL applies to it as to QVERIFY. A NearContext in scope adds what QVERIFY2's message used to
// carry (a loop index, a scenario name) to the failure.
#include <QString>
#include <QTest>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace reckoner::test {

/// While alive, a failing RK_COMPARE_NEAR on this thread also prints `what` (say "F(2,3)" in a loop over
/// a matrix). Contexts nest, the outermost printed first. Only RK_COMPARE_NEAR reads them.
class NearContext {
 public:
  explicit NearContext(const QString& what) : what_(what.toStdString()) { live().push_back(this); }
  ~NearContext() { live().pop_back(); }
  NearContext(const NearContext&) = delete;
  NearContext& operator=(const NearContext&) = delete;

  /// "\n   Context: a; b" for the contexts alive now, "" when there is none.
  static std::string describe() {
    std::string text;
    for (const NearContext* c : live()) {
      text += text.empty() ? "\n   Context: " : "; ";
      text += c->what_;
    }
    return text;
  }

 private:
  static std::vector<const NearContext*>& live() {
    static thread_local std::vector<const NearContext*> contexts;
    return contexts;
  }
  std::string what_;
};

/// True when |actual - expected| <= tol with all three finite; otherwise reports through QTest::qVerify
/// (so the failure names the file and line of the macro) and returns false.
inline bool compareNear(double actual, double expected, double tol, const char* actualExpr,
                        const char* expectedExpr, const char* tolExpr, const char* file, int line) {
  const double diff = actual - expected;
  const bool ok = std::isfinite(actual) && std::isfinite(expected) && std::isfinite(tol) && tol >= 0.0 &&
                  std::abs(diff) <= tol;
  if (ok) return QTest::qVerify(true, "RK_COMPARE_NEAR", "", file, line);
  char statement[512];
  std::snprintf(statement, sizeof statement, "RK_COMPARE_NEAR(%s, %s, %s)", actualExpr, expectedExpr,
                tolExpr);
  char description[512];
  if (!std::isfinite(tol) || tol < 0.0)
    std::snprintf(description, sizeof description, "tolerance %.17g is not a finite non-negative number",
                  tol);
  else
    std::snprintf(description, sizeof description,
                  "\n   Actual   (%s): %.17g\n   Expected (%s): %.17g\n   |difference| %.6g > tolerance %.6g",
                  actualExpr, actual, expectedExpr, expected, std::abs(diff), tol);
  std::string withContext = description;
  withContext += NearContext::describe();
  return QTest::qVerify(false, statement, withContext.c_str(), file, line);
}

}  // namespace reckoner::test

#define RK_COMPARE_NEAR(actual, expected, tol)                                                       \
  do {                                                                                               \
    if (!::reckoner::test::compareNear(static_cast<double>(actual), static_cast<double>(expected),   \
                                       static_cast<double>(tol), #actual, #expected, #tol, __FILE__, \
                                       __LINE__))                                                    \
      return;                                                                                        \
  } while (false)
