#include "io/text_file.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "io/input_error.h"

namespace reckoner::io {
namespace {
// GNU strerror_r returns the text (not always in buf); the XSI one returns 0 and fills buf.
[[maybe_unused]] std::string strerrorResult(const char* text, const char*) {
  return text;
}
[[maybe_unused]] std::string strerrorResult(int rc, const char* buf) {
  return rc == 0 ? buf : "Unknown error";
}

std::string kindOf(mode_t m) {
  if (S_ISDIR(m)) return "a directory";
  if (S_ISFIFO(m)) return "a FIFO (named pipe)";
  if (S_ISSOCK(m)) return "a socket";
  if (S_ISCHR(m)) return "a character device";
  if (S_ISBLK(m)) return "a block device";
  return "not a regular file";
}
}  // namespace

std::string readTextFile(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0)
    throw InputError(path, 0, "", std::string("cannot open: ") + errnoText(errno));
  if (!S_ISREG(st.st_mode)) throw InputError(path, 0, "", "is " + kindOf(st.st_mode) + ", not a file");
  if (static_cast<std::uint64_t>(st.st_size) > kMaxTextFileBytes)
    throw InputError(path, 0, "",
                     "is " + std::to_string(st.st_size) + " bytes; the limit is " +
                         std::to_string(kMaxTextFileBytes) + " bytes");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "", std::string("cannot open: ") + errnoText(errno));
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) throw InputError(path, 0, "", "read error");
  return ss.str();
}

void writeTextFile(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw InputError(path, 0, "", std::string("cannot write: ") + errnoText(errno));
  out << text;
  out.flush();
  if (!out) throw InputError(path, 0, "", "write failed");
}

std::string errnoText(int error) {
  char buf[256] = "";
  return strerrorResult(strerror_r(error, buf, sizeof buf), buf);
}

}  // namespace reckoner::io
