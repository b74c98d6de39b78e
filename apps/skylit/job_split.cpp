// Splitting a run's images over ranks and shards (job_split.h).
#include "job_split.h"

#include <charconv>

#include "process_group.h"
#include "skylit/core/error.h"
#include "skylit/io/atomic_file.h"
#include "skylit/io/image/xyz_file.h"

namespace skylit::cli {

namespace {

constexpr int kMaxShards = 100000;

int parse_int(std::string_view text) {
  int value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  return error == std::errc() && end == text.data() + text.size() ? value : -1;
}

}  // namespace

Shard parse_shard(const std::string& text) {
  const std::size_t slash = text.find('/');
  const int k = slash == std::string::npos ? -1 : parse_int(std::string_view(text).substr(0, slash));
  const int n = slash == std::string::npos ? -1 : parse_int(std::string_view(text).substr(slash + 1));
  if (k < 1 || n < 1 || k > n || n > kMaxShards)
    throw InputError("--shard " + text + ": expected K/N, shard K (from 1) of N shards, N at most " +
                     std::to_string(kMaxShards) + ", e.g. --shard 3/10");
  return {k - 1, n};
}

void add_split_options(CLI::App& command, std::string& shard, JobSplit& split, const std::string& items,
                       const std::string& shard_files) {
  command.add_option("--shard", shard,
                     "K/N: render only " + items +
                         " K, K+N, K+2N, ... (counting from 1) and write each as the exact "
                         "image " +
                         shard_files + ", for array jobs; then --merge (docs/cluster.md)");
  command.add_flag("--merge", split.merge,
                   "Render nothing: read every one of the " + items +
                       " written by the shards and write the outputs, the same bytes as one process");
}

void check_split_options(const JobSplit& split) {
  if (split.shard && split.merge) throw InputError("--shard and --merge: give one (the merge reads every shard)");
}

int JobSplit::renderer_of(std::size_t item) const {
  if (merge) return -1;
  std::size_t within = item;
  if (shard) {
    if (item % static_cast<std::size_t>(shard->count) != static_cast<std::size_t>(shard->index)) return -1;
    within = item / static_cast<std::size_t>(shard->count);
  }
  return static_cast<int>(within % static_cast<std::size_t>(process_count()));
}

std::optional<std::vector<XyzImage>> gather_job_images(
    std::size_t count, const JobSplit& split, const std::function<XyzImage(std::size_t)>& render,
    const std::function<std::filesystem::path(std::size_t)>& shard_file) {
  std::vector<XyzImage> images(count);
  std::vector<int> owner(count);
  for (std::size_t i = 0; i < count; ++i) {
    owner[i] = split.renderer_of(i);
    if (owner[i] == process_rank()) images[i] = render(i);
  }
  if (split.merge) {
    for (std::size_t i = 0; i < count; ++i) {
      const std::filesystem::path file = shard_file(i);
      if (!std::filesystem::exists(file))
        throw InputError("--merge: \"" + file.string() + "\" is missing: image " + std::to_string(i + 1) +
                         " comes from shard K/N with K − 1 = " + std::to_string(i) + " mod N; has it run?");
      images[i] = read_xyz_file(file);
    }
    return images;
  }
  if (split.shard) {
    // Each rank writes the images it rendered; the merge finds them by name.
    for (std::size_t i = 0; i < count; ++i)
      if (owner[i] == process_rank()) AtomicFile(shard_file(i)).commit(encode_xyz_file(images[i]));
    return std::nullopt;
  }
  gather_on_first_process(images, owner);
  if (!is_first_process()) return std::nullopt;
  return images;
}

}  // namespace skylit::cli
