#pragma once
// Time and memory limits for tests that feed hostile input: a run that would hang or grow without
// bound fails inside the limit instead of taking the machine. The limits are on CPU time and address
// space (RLIMIT_CPU, RLIMIT_AS), so a loaded machine does not make them flaky. Under AddressSanitizer,
// whose shadow memory reserves terabytes of address space, memory is limited by ASan's own
// hard_rss_limit_mb instead.
#include <cstddef>

class QProcess;

namespace reckoner::test {

/// Default limits of a hostile-input run: 60 CPU seconds, 2 GiB.
inline constexpr int kHostileCpuSeconds = 60;
inline constexpr std::size_t kHostileMemoryBytes = std::size_t{2} << 30;

/// True when this binary was built with AddressSanitizer.
bool underAddressSanitizer();

/// How much slower code runs here than in Release: 30 under AddressSanitizer (Debug, -O0: Eigen's
/// small-matrix code is 30 to 100 times slower), else 1. CPU limits are multiplied by it.
int slowdown();

/// Caps this process: CPU seconds (times slowdown()) and address space (not under ASan).
void limitThisProcess(int cpuSeconds, std::size_t memoryBytes);

/// Makes every child that p starts run under these limits (RLIMIT_CPU times slowdown(), and RLIMIT_AS
/// or ASan's RSS limit). Call before p.start().
void limitChildren(QProcess& p, int cpuSeconds = kHostileCpuSeconds,
                   std::size_t memoryBytes = kHostileMemoryBytes);

}  // namespace reckoner::test
