// Reading a whole (small) text file a user names: scene files, photometric files,
// spectrum tables, regions; and quoting a piece of such a file in an error message.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace skylit {

// The largest text file a user may name, bytes: 64 MiB, hundreds of times any real
// scene, IES or EULUMDAT file or spectrum table. A larger one is refused before it
// is read, so /dev/zero or a mistaken video file cannot fill the memory (issue 19,
// item 9). docs/scene-format.md states it.
inline constexpr std::uintmax_t kMaxTextFileBytes = 64u << 20;

// The file's bytes. Throws InputError "<file>:1: cannot read the <what>: <why>" if it
// is missing, not a regular file (a folder, a device such as /dev/zero, a FIFO, which
// would block), larger than max_bytes, or cannot be read.
std::string read_text_file(const std::filesystem::path& file, const std::string& what,
                           std::uintmax_t max_bytes = kMaxTextFileBytes);

// The text without a UTF-8 byte order mark at its start (Windows editors write one; it
// is not part of the first line).
inline std::string_view without_byte_order_mark(std::string_view text) {
  return text.starts_with("\xEF\xBB\xBF") ? text.substr(3) : text;
}

// Throws InputError "<file>: <what>: not a regular file" (or "not found") unless `file`
// is a regular file, for the readers that hand a path to a library.
void require_regular_file(const std::filesystem::path& file, const std::string& what);

// A piece of a user's file for an error message: at most 20 bytes, printable ASCII only
// (others as '?'), in single quotes, "..." when cut. Messages never quote more, so a
// file named by mistake (/etc/passwd) is not copied to the terminal (item 16).
std::string quote_excerpt(std::string_view text);

// A name a user's file gives (a texture's file name, a material's) for a message: whole
// up to 120 bytes, so that two long names that share their start stay told apart, in
// single quotes; control characters as '?', UTF-8 kept (cut only between characters).
std::string quote_name(std::string_view name);

// The first `named` of `items` joined by ", ", then " and N more" for the rest: one
// warning line for what a model may have hundreds of.
std::string first_few(const std::vector<std::string>& items, size_t named);

}  // namespace skylit
