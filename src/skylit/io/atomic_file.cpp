// AtomicFile (atomic_file.h): temporary file beside the target, write, fsync, rename.
// POSIX calls rather than iostreams because we need O_EXCL (never clobber someone
// else's file that happens to have the temporary's name), errno for messages that say
// why, and fsync so a crash after the rename cannot leave an empty file behind.
#include "skylit/io/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <string>
#include <system_error>

#include "skylit/core/error.h"

namespace skylit {
namespace {

std::string quoted(const std::filesystem::path& p) {
  std::string s = p.string();  // see the temporary's name below for why not '"' + s + '"'
  s.insert(s.begin(), '"');
  s.push_back('"');
  return s;
}

[[noreturn]] void fail(const std::filesystem::path& target, const std::string& why) {
  throw InputError("cannot write " + quoted(target) + ": " + why);
}

std::filesystem::path folder_of(const std::filesystem::path& target) {
  return target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
}

// Writes all bytes to fd, retrying short writes and signals; returns errno or 0.
int write_all(int fd, std::span<const uint8_t> bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    done += static_cast<std::size_t>(n);
  }
  return 0;
}

// The temporaries of live AtomicFiles, for the signal handler: a fixed array of
// pointers, claimed and released atomically, so that the handler reads it without a
// lock (only async-signal-safe calls there: unlink, signal, raise).
std::atomic<const char*> g_temporaries[kMaxTemporaries];

int track(const char* path) {
  for (int i = 0; i < kMaxTemporaries; ++i) {
    const char* expected = nullptr;
    if (g_temporaries[i].compare_exchange_strong(expected, path)) return i;
  }
  return -1;
}

void untrack(int slot) {
  if (slot >= 0) g_temporaries[slot].store(nullptr);
}

extern "C" void remove_temporaries_and_die(int signal_number) {
  for (auto& temporary : g_temporaries)
    if (const char* path = temporary.load()) ::unlink(path);
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
}

}  // namespace

void remove_temporaries_on_signals() {
  for (const int s : {SIGINT, SIGTERM}) std::signal(s, remove_temporaries_and_die);
}

void check_not_an_input(const std::filesystem::path& target, const std::filesystem::path& input) {
  std::error_code ec, ec_target, ec_input;
  bool same = std::filesystem::equivalent(target, input, ec);  // false if either is missing
  if (!same) {
    const std::filesystem::path a = std::filesystem::weakly_canonical(target, ec_target);
    const std::filesystem::path b = std::filesystem::weakly_canonical(input, ec_input);
    same = !ec_target && !ec_input && a == b;
  }
  if (same) fail(target, "it is also an input of this command; choose another name");
}

void check_output_folder(const std::filesystem::path& target) {
  const std::filesystem::path folder = folder_of(target);
  std::error_code ec;
  if (!std::filesystem::is_directory(folder, ec)) fail(target, "folder " + quoted(folder) + " does not exist");
}

AtomicFile::AtomicFile(std::filesystem::path target) : target_(std::move(target)) {
  check_output_folder(target_);
  const std::filesystem::path folder = folder_of(target_);
  if (target_.filename().empty()) fail(target_, "the path names a folder, not a file");
  // pid and a per-process counter keep concurrent writers (threads or processes) apart.
  static std::atomic<unsigned> counter{0};
  // Appended piece by piece: "." + std::string trips GCC 12's false -Wrestrict warning.
  std::string name(1, '.');  // hidden, so a listing of the folder does not show it
  name += target_.filename().string();
  name += '.';
  name += std::to_string(::getpid());
  name += '-';
  name += std::to_string(counter++);
  name += ".tmp";
  temporary_ = folder / name;
  // Tracked before it exists: a signal between the two must not leave it behind.
  slot_ = track(temporary_.c_str());
  const int fd = ::open(temporary_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) {
    const int error = errno;
    untrack(slot_);
    slot_ = -1;
    fail(target_, "cannot create a file in folder " + quoted(folder) + ": " + std::strerror(error));
  }
  ::close(fd);
}

AtomicFile::~AtomicFile() {
  untrack(slot_);
  if (!committed_) ::unlink(temporary_.c_str());
}

void AtomicFile::write(std::span<const uint8_t> bytes) {
  const int fd = ::open(temporary_.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
  if (fd < 0) fail(target_, std::string("cannot reopen the temporary file: ") + std::strerror(errno));
  int error = write_all(fd, bytes);
  if (error == 0 && ::fsync(fd) != 0) error = errno;
  if (::close(fd) != 0 && error == 0) error = errno;
  if (error != 0) fail(target_, std::strerror(error));
}

void AtomicFile::publish() {
  // Untracked first: once renamed, the temporary's name is the target's no more, but a
  // signal between the two calls must not remove a file that is someone else's by then.
  untrack(slot_);
  slot_ = -1;
  if (std::rename(temporary_.c_str(), target_.c_str()) != 0) fail(target_, std::strerror(errno));
  committed_ = true;
}

}  // namespace skylit
