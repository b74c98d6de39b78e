// Shared by the browser tests (report_browser_test.cpp, animate_viewer_browser_test.cpp):
// where Chromium is, and running one of tests/browser/'s page scripts in it, which prints
// one JSON line of what the page showed.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "../test_support.h"

namespace skylit::testing {

// $SKYLIT_CHROMIUM, else `chromium` on the PATH, else Debian's /usr/bin/chromium.
inline std::filesystem::path find_chromium() {
  if (const char* given = std::getenv("SKYLIT_CHROMIUM")) return given;
  if (const char* path = std::getenv("PATH")) {
    std::stringstream folders(path);
    std::string folder;
    while (std::getline(folders, folder, ':'))
      if (!folder.empty() && std::filesystem::exists(std::filesystem::path(folder) / "chromium"))
        return std::filesystem::path(folder) / "chromium";
  }
  return "/usr/bin/chromium";
}

// Runs tests/browser/SCRIPT in CHROMIUM on PAGE with the further ARGUMENTS (already
// quoted); playwright-core is installed into the build folder's browser-test-deps at the
// first run (there whatever folder the tests run from: run from the sources, they had
// left a copy there). The command's result, and its JSON line parsed when it succeeded.
struct PageResult {
  CommandResult command;
  nlohmann::json json;
};

inline PageResult run_page_script(const std::string& script, const std::filesystem::path& chromium,
                                  const std::filesystem::path& page, const std::string& arguments = "") {
  PageResult result;
  result.command = run_command(quoted(std::filesystem::path(SKYLIT_SOURCE_DIR) / "tests/browser/run-in-chromium.sh") +
                               " " + quoted(std::filesystem::path(SKYLIT_BINARY_DIR) / "browser-test-deps") + " " +
                               script + " " + quoted(chromium) + " " + quoted(page) + " " + arguments);
  const std::size_t brace = result.command.output.find('{');
  if (result.command.exit_status == 0 && brace != std::string::npos)
    result.json = nlohmann::json::parse(result.command.output.substr(brace), nullptr, false);
  return result;
}

}  // namespace skylit::testing
