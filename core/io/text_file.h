#pragma once
// Whole text files in and out. Reading refuses what is not a regular file (a directory, a FIFO, a
// device: opening a FIFO would wait for a writer for ever) and files beyond kMaxTextFileBytes, each
// with one io::InputError naming the path.
#include <cstdint>
#include <string>

namespace reckoner::io {

/// Largest file readTextFile() reads (4 GiB): a month of NMEA at 10 sentences per second is ~1.5 GB.
inline constexpr std::uint64_t kMaxTextFileBytes = 4ull << 30;

/// Reads a whole regular file. Throws InputError naming the file when it is missing, not a regular
/// file, too large or unreadable.
std::string readTextFile(const std::string& path);

/// Writes text to path (truncating). Throws InputError naming the file when it cannot.
void writeTextFile(const std::string& path, const std::string& text);

/// The C library's text for an errno value, as std::strerror gives it but safe from any thread
/// (strerror_r; std::strerror may share one buffer between threads).
std::string errnoText(int error);

}  // namespace reckoner::io
