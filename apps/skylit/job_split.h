// How a run of many images (sweep cells, animation frames) is split (docs/cluster.md):
// over MPI ranks (process_group.h), over the shards of an array job (--shard K/N, each
// writing its images as exact XYZ files), or not at all; and `--merge`, which reads every
// shard's files back so that the outputs are written as one process would write them.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "skylit/spectrum/xyz_image.h"

namespace skylit::cli {

struct Shard {
  int index = 0;  // 0-based: K − 1
  int count = 1;  // N
};

// "K/N" with 1 ≤ K ≤ N ≤ 100000; InputError naming --shard otherwise.
Shard parse_shard(const std::string& text);

struct JobSplit {
  std::optional<Shard> shard;  // --shard: render this shard's items and write them as .xyz
  bool merge = false;          // --merge: render nothing, read every item's .xyz

  // The process (MPI rank) that renders item i in this run, or -1 when none does (it
  // belongs to another shard, or --merge reads it).
  int renderer_of(std::size_t item) const;
};

// The images of all `count` items on the first process, ready for the outputs; or
// nothing, when this run is a shard (its images are then written to shard_file(i)) or a
// rank other than the first. `render(i)` renders item i; `shard_file(i)` is where item
// i's exact image goes between a shard and the merge. A merge missing a shard's file
// is an InputError naming it and its shard.
std::optional<std::vector<XyzImage>> gather_job_images(
    std::size_t count, const JobSplit& split, const std::function<XyzImage(std::size_t)>& render,
    const std::function<std::filesystem::path(std::size_t)>& shard_file);

// --shard K/N (into `shard`, read by parse_shard) and --merge on `command`, whose
// images are `items` ("combinations", "frames") written by a shard as `shard_files`.
void add_split_options(CLI::App& command, std::string& shard, JobSplit& split, const std::string& items,
                       const std::string& shard_files);

// InputError if both --shard and --merge are given.
void check_split_options(const JobSplit& split);

}  // namespace skylit::cli
