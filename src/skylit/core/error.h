// Errors a user can cause (bad file, bad value, missing mesh) are InputError: the
// program prints its one-line message and exits with status 2. Anything else that is
// thrown is an internal error (status 1).
#pragma once

#include <stdexcept>
#include <string>

namespace skylit {

class InputError : public std::runtime_error {
 public:
  // The message names the file and the place (line:column or JSON path) itself.
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace skylit
