// Reading a whole (small) text file a user names: photometric files, spectrum tables.
#pragma once

#include <filesystem>
#include <string>

namespace skylit {

// The file's bytes. Throws InputError "<file>:1: cannot read the <what>" if it cannot
// be opened or read (missing, a directory, no permission).
std::string read_text_file(const std::filesystem::path& file, const std::string& what);

}  // namespace skylit
