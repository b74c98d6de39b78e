// All-or-nothing output sets (output_files.h).
#include "skylit/io/output_files.h"

#include <stdexcept>

#include "skylit/io/atomic_file.h"

namespace skylit {

OutputFiles::OutputFiles(const std::vector<std::filesystem::path>& paths,
                         const std::vector<std::filesystem::path>& inputs) {
  // Every name is checked before any temporary exists, so a refused name leaves nothing.
  for (const std::filesystem::path& path : paths)
    for (const std::filesystem::path& input : inputs) check_not_an_input(path, input);
  for (const std::filesystem::path& path : paths) files_.push_back(std::make_unique<AtomicFile>(path));
  written_.assign(files_.size(), false);
}

OutputFiles::~OutputFiles() = default;

void OutputFiles::write(std::size_t i, std::span<const uint8_t> bytes) {
  if (i >= files_.size() || written_[i]) throw std::logic_error("OutputFiles::write: each output is written once");
  files_[i]->write(bytes);
  written_[i] = true;
}

void OutputFiles::publish() {
  for (bool written : written_)
    if (!written) throw std::logic_error("OutputFiles::publish: an output was not written");
  for (const auto& file : files_) file->publish();
}

}  // namespace skylit
