// Writes the seed corpus of fuzz_ais (tests/fuzz/corpus/ais/) from this project's own AIS encoder
// (tests/support/ais_corpus.h): each message alone, all of them in one stream, fragments out of order
// and interleaved on two channels, and tag-blocked lines. Run: build/fuzz/tests/fuzz/ais_seeds DIR
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "support/ais_corpus.h"

namespace ais = reckoner::test::ais;

namespace {
bool write(const std::string& dir, const std::string& name, const std::vector<std::string>& lines) {
  std::ofstream out(dir + "/" + name, std::ios::binary);
  for (const auto& l : lines) out << l << "\r\n";
  return static_cast<bool>(out);
}
}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: ais_seeds DIR\n");
    return 2;
  }
  const std::string dir = argv[1];
  const auto corpus = ais::corpus();
  bool ok = write(dir, "all", corpus);
  for (std::size_t i = 0; i < corpus.size(); ++i)
    ok = write(dir, "msg" + std::to_string(i), {corpus[i]}) && ok;
  auto a = ais::fragments(ais::staticVoyage(), 1, 30, 'A');
  auto b = ais::fragments(ais::staticVoyage(), 1, 25, 'B');
  std::vector<std::string> mixed;
  for (std::size_t i = 0; i < std::max(a.size(), b.size()); ++i) {
    if (i < b.size()) mixed.push_back(b[b.size() - 1 - i]);
    if (i < a.size()) mixed.push_back(a[i]);
  }
  ok = write(dir, "interleaved", mixed) && ok;
  std::vector<std::string> tagged;
  tagged.reserve(corpus.size());
  for (const auto& l : corpus) tagged.push_back("\\s:r3669961,c:1241544035*7F\\" + l);
  ok = write(dir, "tagged", tagged) && ok;
  if (!ok) std::fprintf(stderr, "ais_seeds: cannot write into %s\n", dir.c_str());
  return ok ? 0 : 1;
}
