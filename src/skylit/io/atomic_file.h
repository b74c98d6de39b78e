// Writing a file so that readers only ever see the old file or the complete new one:
// the bytes go to a temporary file in the target's own folder (so the final rename
// stays on one file system and is atomic, POSIX rename(2)), are flushed to disk, and
// the temporary is renamed over the target. If anything fails, or the AtomicFile is
// destroyed uncommitted (an exception on the way), the temporary is removed.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string_view>

namespace skylit {

// InputError naming the target if its folder does not exist (the check AtomicFile makes
// when it starts), for checking every output before the work that will fill it.
void check_output_folder(const std::filesystem::path& target);

// InputError "cannot write <target>: it is also an input" if `target` names the same file
// as `input` (the same inode, or the same path once resolved): `skylit render scene.pfm
// -o scene.pfm` must not overwrite what it reads (issue 19, item 13).
void check_not_an_input(const std::filesystem::path& target, const std::filesystem::path& input);

// Installs handlers for SIGINT and SIGTERM that remove every temporary file of a live
// AtomicFile, then end the process as the signal would have (issue 19, item 14). For
// programs: a library does not take signals on its own. Up to kMaxTemporaries files are
// tracked at once (beyond that, a temporary is removed only by its destructor).
void remove_temporaries_on_signals();
inline constexpr int kMaxTemporaries = 256;

class AtomicFile {
 public:
  // Creates the temporary ".<name>.<pid>-<n>.tmp" beside `target`. InputError naming
  // the target if its folder is missing or not writable.
  explicit AtomicFile(std::filesystem::path target);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  const std::filesystem::path& target() const { return target_; }
  const std::filesystem::path& temporary() const { return temporary_; }

  // Writes all of `bytes` to the temporary, flushes it to disk and renames it into
  // place. InputError naming the target if any step fails (e.g. disk full).
  void commit(std::span<const uint8_t> bytes) {
    write(bytes);
    publish();
  }
  void commit(std::string_view text) { commit(std::span(reinterpret_cast<const uint8_t*>(text.data()), text.size())); }
  // commit() in two steps, for a set of files written all or nothing: write each, and
  // publish them only when every write succeeded.
  void write(std::span<const uint8_t> bytes);
  void publish();

 private:
  std::filesystem::path target_, temporary_;
  int slot_ = -1;  // in the list the signal handler removes
  bool committed_ = false;
};

}  // namespace skylit
