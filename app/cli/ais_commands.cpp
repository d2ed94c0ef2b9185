// ais decode FILE... [--json]: the AIS messages of NMEA files (docs/ais.md), one line each on stdout,
// JSON Lines with --json; lines that are not AIS or are rejected are counted in one summary line on
// stderr.
#include <cstdio>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "cli/cli_options.h"
#include "cli/commands.h"
#include "files/ais_output.h"
#include "io/ais.h"
#include "io/text_file.h"

namespace reckoner::cli {
namespace {

struct AisArgs {
  std::vector<std::string> files;
  bool json = false;
};

void printSummary(const io::AisCounters& c) {
  std::fprintf(
      stderr,
      "ais: %llu lines, %llu decoded, %llu not AIS, %llu bad checksum, %llu malformed, %llu bad "
      "armour, %llu bad fill bits, %llu too long, %llu orphan fragments, %llu partials expired, "
      "%llu partials evicted, %llu unsupported types, %llu too short\n",
      static_cast<unsigned long long>(c.lines), static_cast<unsigned long long>(c.decoded),
      static_cast<unsigned long long>(c.notAis), static_cast<unsigned long long>(c.badChecksum),
      static_cast<unsigned long long>(c.malformed), static_cast<unsigned long long>(c.badArmour),
      static_cast<unsigned long long>(c.badFill), static_cast<unsigned long long>(c.tooLong),
      static_cast<unsigned long long>(c.orphanFragments), static_cast<unsigned long long>(c.expiredPartials),
      static_cast<unsigned long long>(c.evictedPartials), static_cast<unsigned long long>(c.unsupportedType),
      static_cast<unsigned long long>(c.tooShort));
}

int aisDecode(const AisArgs& a) {
  if (a.files.empty()) throw UsageError("ais decode needs at least one FILE");
  std::vector<std::string> texts;
  for (const auto& file : a.files) texts.push_back(io::readTextFile(file));  // throws naming the file
  io::AisCounters total;
  for (const auto& text : texts) {
    io::AisDecoder decoder;  // fragments never join across files
    std::string_view rest = text;
    while (!rest.empty()) {
      const auto nl = rest.find('\n');
      const std::string_view line = rest.substr(0, nl);
      rest.remove_prefix(nl == std::string_view::npos ? rest.size() : nl + 1);
      if (const auto m = decoder.feed(line))
        std::puts(files::aisFieldsLine(files::aisFields(*m), a.json).c_str());
    }
    total += decoder.counters();
  }
  printSummary(total);
  return 0;
}

}  // namespace

void addAisCommands(CLI::App& root, Commands& out) {
  CLI::App* ais = root.add_subcommand("ais", "AIS messages from NMEA files (!AIVDM / !AIVDO)");
  ais->require_subcommand(1);
  auto a = std::make_shared<AisArgs>();
  CLI::App* decode = ais->add_subcommand(
      "decode",
      "Decode the AIS messages of FILEs (types 1-5, 18, 19, 21, 24, 27), one line each; a summary "
      "of skipped lines on stderr");
  addListArgument(*decode, "FILE", a->files, 1, "NMEA files with !AIVDM / !AIVDO sentences");
  addFlag(*decode, "json", a->json, "JSON Lines: one object per message, absent values left out");
  out.push_back({decode, [a] { return aisDecode(*a); }, ""});
}

}  // namespace reckoner::cli
