// Running ffmpeg (video_encoder.h): a child process with its arguments as given (no
// shell), so that no file name is ever read as a command.
#include "video_encoder.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <string_view>
#include <vector>

extern char** environ;

namespace skylit::cli {

std::optional<std::filesystem::path> find_ffmpeg() {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return std::nullopt;
  std::string_view folders(path);
  while (!folders.empty()) {
    const std::size_t colon = folders.find(':');
    const std::filesystem::path candidate = std::filesystem::path(folders.substr(0, colon)) / "ffmpeg";
    if (!candidate.parent_path().empty() && access(candidate.c_str(), X_OK) == 0) return candidate;
    folders = colon == std::string_view::npos ? std::string_view() : folders.substr(colon + 1);
  }
  return std::nullopt;
}

std::string encode_video(const std::filesystem::path& ffmpeg, const std::filesystem::path& frame_pattern,
                         double frames_per_second, const std::filesystem::path& video) {
  std::string temporary_name = ".";
  temporary_name += video.filename().string();
  // Appended piece by piece: `"." + std::string` trips GCC 12's false -Wrestrict (GCC bug 105329).
  temporary_name += '.';
  temporary_name += std::to_string(getpid());
  temporary_name += ".tmp.mp4";
  const std::filesystem::path temporary = video.parent_path() / temporary_name;
  char rate[32];
  std::snprintf(rate, sizeof rate, "%g", frames_per_second);
  // Bit-exact flags keep the encoder's version string out of the file, and x264's output
  // depends on its number of threads, which it would take from the cores this process
  // may use (mpirun binds ranks to cores): a fixed count makes the same frames give the
  // same bytes everywhere.
  std::vector<std::string> arguments = {ffmpeg.string(),
                                        "-nostdin",
                                        "-y",
                                        "-loglevel",
                                        "error",
                                        "-framerate",
                                        rate,
                                        "-start_number",
                                        "1",
                                        "-i",
                                        frame_pattern.string(),
                                        "-vf",
                                        "pad=ceil(iw/2)*2:ceil(ih/2)*2",
                                        "-c:v",
                                        "libx264",
                                        "-threads",
                                        "4",
                                        "-pix_fmt",
                                        "yuv420p",
                                        "-fflags",
                                        "+bitexact",
                                        "-flags:v",
                                        "+bitexact",
                                        "-movflags",
                                        "+faststart",
                                        temporary.string()};
  std::vector<char*> argv;
  for (std::string& a : arguments) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t child = 0;
  if (posix_spawn(&child, argv[0], nullptr, nullptr, argv.data(), environ) != 0) return "could not start ffmpeg";
  int status = 0;
  if (waitpid(child, &status, 0) < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    return "ffmpeg failed (status " + std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + ")";
  }
  std::error_code error;
  std::filesystem::rename(temporary, video, error);
  if (error) return "could not rename the video into place: " + error.message();
  return "";
}

}  // namespace skylit::cli
