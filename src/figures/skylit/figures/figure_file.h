// Internal to io/: the file-name check shared by the figure writers (plots, contact
// sheets, rasters), done before any work or temporary file, so that a wrong name fails
// fast with the one-line InputError the program reports.
#pragma once

#include <filesystem>
#include <initializer_list>
#include <string>
#include <string_view>

namespace skylit {

// The path's extension in lower case (".png") if it is one of `allowed`; otherwise
// InputError naming the path, e.g. `cannot write "a.pdf": unknown extension ".pdf"; a
// plot is written as .svg or .png` with `what` = "a plot".
std::string figure_extension(const std::filesystem::path& path, std::initializer_list<std::string_view> allowed,
                             std::string_view what);

}  // namespace skylit
