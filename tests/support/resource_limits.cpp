#include "support/resource_limits.h"

#include <sys/resource.h>

#include <QProcess>
#include <QProcessEnvironment>

namespace reckoner::test {

bool underAddressSanitizer() {
#if defined(__SANITIZE_ADDRESS__)
  return true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
  return true;
#else
  return false;
#endif
#else
  return false;
#endif
}

int slowdown() {
  return underAddressSanitizer() ? 30 : 1;
}

namespace {
void applyLimits(int cpuSeconds, std::size_t memoryBytes, bool memory) {
  const rlimit cpu{static_cast<rlim_t>(cpuSeconds), static_cast<rlim_t>(cpuSeconds) + 5};
  setrlimit(RLIMIT_CPU, &cpu);
  if (memory) {
    const rlimit as{static_cast<rlim_t>(memoryBytes), static_cast<rlim_t>(memoryBytes)};
    setrlimit(RLIMIT_AS, &as);
  }
}
}  // namespace

void limitThisProcess(int cpuSeconds, std::size_t memoryBytes) {
  applyLimits(cpuSeconds * slowdown(), memoryBytes, !underAddressSanitizer());
}

void limitChildren(QProcess& p, int cpuSeconds, std::size_t memoryBytes) {
  const bool asan = underAddressSanitizer();
  if (asan) {
    QProcessEnvironment env =
        p.processEnvironment().isEmpty() ? QProcessEnvironment::systemEnvironment() : p.processEnvironment();
    QString opts = env.value("ASAN_OPTIONS");
    if (!opts.isEmpty()) opts += ':';
    opts += QString("hard_rss_limit_mb=%1").arg(memoryBytes >> 20);
    env.insert("ASAN_OPTIONS", opts);
    p.setProcessEnvironment(env);
  }
  // Runs in the child between fork and exec: only async-signal-safe calls (setrlimit is).
  const int cpu = cpuSeconds * slowdown();
  p.setChildProcessModifier([cpu, memoryBytes, asan] { applyLimits(cpu, memoryBytes, !asan); });
}

}  // namespace reckoner::test
