// CommittedAllocator (core/common/committed_allocator.h): the memory a container reserves with it is
// resident from the reserve on, every page of it, where std::allocator's is resident only as it is
// written; and the container works as with std::allocator.
#include <sys/mman.h>
#include <unistd.h>

#include <QTest>
#include <cstdint>
#include <vector>

#include "common/committed_allocator.h"

using namespace reckoner;

namespace {

/// The share of the pages of [p, p + bytes) that are resident (mincore).
double residentShare(const void* p, std::size_t bytes) {
  const auto page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
  const auto* bytesAt = static_cast<const unsigned char*>(p);
  const std::size_t offset = reinterpret_cast<std::uintptr_t>(p) % page;  // into its first page
  const std::size_t span = offset + bytes;
  const std::size_t pages = (span + page - 1) / page;
  std::vector<unsigned char> in(pages);
  // mincore takes a void* to the page (and writes nothing there)
  if (mincore(const_cast<unsigned char*>(bytesAt - offset), span, in.data()) != 0) return -1.0;
  std::size_t n = 0;
  for (const unsigned char c : in) n += (c & 1U) ? 1 : 0;
  return static_cast<double>(n) / static_cast<double>(pages);
}

struct Slot {
  double values[60];
  int id = 0;
};

}  // namespace

class TestCommittedAllocator : public QObject {
  Q_OBJECT
 private slots:
  void aReservedTableIsResidentAtOnce() {
    // 8 MiB: above glibc's mmap threshold, so both reserves get fresh pages from the kernel
    constexpr std::size_t kSlots = std::size_t{8} * 1024 * 1024 / sizeof(Slot);
    std::vector<Slot, CommittedAllocator<Slot>> committed;
    committed.reserve(kSlots);
    std::vector<Slot> plain;
    plain.reserve(kSlots);
    const double c = residentShare(committed.data(), kSlots * sizeof(Slot));
    const double p = residentShare(plain.data(), kSlots * sizeof(Slot));
    qInfo("resident after reserve: committed %.3f, std::allocator %.3f", c, p);
    QCOMPARE(c, 1.0);
    QVERIFY(p < 0.1);  // the comparison shows the test can tell the two apart
  }

  void theContainerBehavesAsWithStdAllocator() {
    std::vector<Slot, CommittedAllocator<Slot>> v;
    v.reserve(4);
    for (int i = 0; i < 100; ++i) v.push_back(Slot{{}, i});  // grows past the reserve
    std::erase_if(v, [](const Slot& s) { return s.id % 2 == 0; });
    QCOMPARE(v.size(), std::size_t{50});
    QCOMPARE(v.front().id, 1);
    QCOMPARE(v.back().id, 99);
    const auto copy = v;
    QCOMPARE(copy.size(), v.size());
    QCOMPARE(copy[10].id, 21);
  }
};

QTEST_APPLESS_MAIN(TestCommittedAllocator)
#include "tst_committed_allocator.moc"
