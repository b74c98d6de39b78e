#include "skylit/core/text_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "skylit/core/error.h"
#include "skylit/core/huge_pages.h"

namespace skylit {

namespace {

[[noreturn]] void refuse(const std::filesystem::path& file, const std::string& what, const std::string& why,
                         const char* verb = "read") {
  throw InputError(file.string() + ":1: cannot " + verb + " the " + what + ": " + why);
}

// Opened first and checked through the descriptor, so the file checked is the file read.
// O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer.
struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

std::string read_text_file(const std::filesystem::path& file, const std::string& what, std::uintmax_t max_bytes) {
  const Descriptor in{::open(file.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK)};
  if (in.fd < 0) refuse(file, what, std::strerror(errno), "open");
  struct stat status {};
  if (::fstat(in.fd, &status) != 0) refuse(file, what, std::strerror(errno));
  if (!S_ISREG(status.st_mode)) refuse(file, what, "not a regular file");
  if (static_cast<std::uintmax_t>(status.st_size) > max_bytes)
    refuse(file, what, "larger than the limit of " + std::to_string(max_bytes >> 20) + " MiB");
  // A model's file may be 100 MB and more: its new pages are asked for in 2 MiB
  // (core/huge_pages.h) before they are first written.
  std::string text;
  text.reserve(static_cast<std::size_t>(status.st_size));
  advise_huge_pages(text.data(), text.capacity());
  text.resize(static_cast<std::size_t>(status.st_size));
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::read(in.fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) refuse(file, what, std::strerror(errno));
    if (n == 0) break;  // shrank while we read: take what is there
    done += static_cast<std::size_t>(n);
  }
  text.resize(done);
  return text;
}

void require_regular_file(const std::filesystem::path& file, const std::string& what) {
  std::error_code ec;
  const auto status = std::filesystem::status(file, ec);
  if (!std::filesystem::exists(status)) throw InputError(file.string() + ": " + what + " not found");
  if (!std::filesystem::is_regular_file(status)) throw InputError(file.string() + ": " + what + ": not a regular file");
}

std::string quote_excerpt(std::string_view text) {
  constexpr std::size_t kMaxShown = 20;
  std::string out = "'";
  for (const char ch : text.substr(0, kMaxShown)) out += (ch >= 32 && ch < 127) ? ch : '?';
  if (text.size() > kMaxShown) out += "...";
  return out + "'";
}

std::string quote_name(std::string_view name) {
  constexpr std::size_t kMaxShown = 120;
  std::size_t shown = std::min(name.size(), kMaxShown);
  // Back to a character's first byte (UTF-8 continuation bytes are 10xxxxxx).
  while (shown < name.size() && shown > 0 && (static_cast<unsigned char>(name[shown]) & 0xC0) == 0x80) --shown;
  std::string out = "'";
  for (const char ch : name.substr(0, shown)) {
    const auto byte = static_cast<unsigned char>(ch);
    out += byte < 32 || byte == 127 ? '?' : ch;
  }
  if (shown < name.size()) out += "...";
  return out + "'";
}

std::string first_few(const std::vector<std::string>& items, size_t named) {
  std::string list;
  for (size_t i = 0; i < std::min(items.size(), named); ++i) list += (i ? ", " : "") + items[i];
  if (items.size() > named) list += " and " + std::to_string(items.size() - named) + " more";
  return list;
}

}  // namespace skylit
