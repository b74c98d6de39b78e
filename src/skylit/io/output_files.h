// A program's outputs written all or nothing (issue 19, item 12): made before the work,
// each path is checked not to be one of the work's inputs (item 13) and gets its
// temporary file, which proves its folder exists and is writable; after the work each
// output's bytes go to its temporary, and only when all are written are they renamed
// into place. Temporaries left unrenamed are removed (also on SIGINT and SIGTERM once
// remove_temporaries_on_signals() ran, atomic_file.h).
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <vector>

namespace skylit {

class AtomicFile;

class OutputFiles {
 public:
  OutputFiles(const std::vector<std::filesystem::path>& paths, const std::vector<std::filesystem::path>& inputs);
  ~OutputFiles();
  OutputFiles(const OutputFiles&) = delete;
  OutputFiles& operator=(const OutputFiles&) = delete;

  std::size_t size() const { return files_.size(); }
  // The bytes of output i (in the order of the paths given); each is written once.
  void write(std::size_t i, std::span<const uint8_t> bytes);
  // Renames every written output into place; std::logic_error if one was not written.
  void publish();

 private:
  std::vector<std::unique_ptr<AtomicFile>> files_;
  std::vector<bool> written_;
};

}  // namespace skylit
