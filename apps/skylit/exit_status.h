// How the program's outcomes become exit statuses: 0 done; 2 a problem with the
// input, reported as one line naming the file and the place; 1 an internal error.
#pragma once

#include <cstdio>
#include <exception>

#include "skylit/core/error.h"

namespace skylit::cli {

inline constexpr int kExitInputError = 2;
inline constexpr int kExitInternalError = 1;

template <typename Command>
int run_with_exit_status(Command&& command, std::FILE* errors = stderr) {
  try {
    return command();
  } catch (const InputError& e) {
    std::fprintf(errors, "skylit: %s\n", e.what());
    return kExitInputError;
  } catch (const std::exception& e) {
    std::fprintf(errors, "skylit: internal error: %s\n", e.what());
    return kExitInternalError;
  }
}

}  // namespace skylit::cli
