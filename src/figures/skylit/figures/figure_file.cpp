// figure_extension (figure_file.h).
#include "skylit/figures/figure_file.h"

#include "skylit/core/error.h"
#include "skylit/core/file_names.h"

namespace skylit {

std::string figure_extension(const std::filesystem::path& path, std::initializer_list<std::string_view> allowed,
                             std::string_view what) {
  std::string ext = lower_case_extension(path);  // not const: returned, so moved
  std::string list;
  std::size_t i = 0;
  for (std::string_view a : allowed) {
    if (a == ext) return ext;
    list += (i == 0 ? "" : i + 1 == allowed.size() ? " or " : ", ") + std::string(a);
    ++i;
  }
  throw InputError("cannot write \"" + path.string() +
                   "\": " + (ext.empty() ? std::string("no file extension") : "unknown extension \"" + ext + "\"") +
                   "; " + std::string(what) + " is written as " + list);
}

}  // namespace skylit
