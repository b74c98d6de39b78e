// MPI behind ProcessGroup (process_group.h); without MPI (SKYLIT_HAVE_MPI unset) one
// process does everything.
#include "process_group.h"

#include <cstdlib>
#include <span>
#include <string>

#include "skylit/core/error.h"

#ifdef SKYLIT_HAVE_MPI
#include <mpi.h>
#endif

namespace skylit::cli {

namespace {

int g_rank = 0, g_count = 1;
#ifdef SKYLIT_HAVE_MPI
bool g_joined = false;
#endif

// The number of ranks an MPI launcher announced, 0 if none did: Open MPI's mpirun, or
// the PMI of MPICH, Intel MPI and Slurm's srun.
int launcher_rank_count() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"})
    if (const char* value = std::getenv(name)) return std::atoi(value);
  return 0;
}

#ifdef SKYLIT_HAVE_MPI
// Floats are sent in pieces of at most this many, as MPI counts are ints.
constexpr std::size_t kMaxFloatsPerMessage = std::size_t{1} << 28;

void send_floats(std::span<float> values, int peer, int tag, bool sending) {
  for (std::size_t start = 0; start < values.size(); start += kMaxFloatsPerMessage) {
    const int count = static_cast<int>(std::min(kMaxFloatsPerMessage, values.size() - start));
    if (sending)
      MPI_Send(values.data() + start, count, MPI_FLOAT, peer, tag, MPI_COMM_WORLD);
    else
      MPI_Recv(values.data() + start, count, MPI_FLOAT, peer, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  }
}
#endif

}  // namespace

ProcessGroup::ProcessGroup([[maybe_unused]] int* argc, [[maybe_unused]] char*** argv) {
  const int announced = launcher_rank_count();
#ifdef SKYLIT_HAVE_MPI
  if (announced > 0) {
    MPI_Init(argc, argv);
    MPI_Comm_rank(MPI_COMM_WORLD, &g_rank);
    MPI_Comm_size(MPI_COMM_WORLD, &g_count);
    g_joined = true;
  }
#else
  if (announced > 1)
    throw InputError("this skylit was built without MPI, so each of the " + std::to_string(announced) +
                     " ranks would do all the work: install Open MPI (Debian: apt-get install libopenmpi-dev "
                     "openmpi-bin) and rebuild, CMake finds it (docs/cluster.md); or use --shard K/N");
#endif
}

ProcessGroup::~ProcessGroup() {
#ifdef SKYLIT_HAVE_MPI
  if (g_joined) MPI_Finalize();
#endif
}

int process_rank() { return g_rank; }
int process_count() { return g_count; }

void abort_other_processes([[maybe_unused]] int status) {
#ifdef SKYLIT_HAVE_MPI
  if (g_joined && g_count > 1) MPI_Abort(MPI_COMM_WORLD, status);
#endif
}

void gather_on_first_process([[maybe_unused]] std::vector<XyzImage>& images,
                             [[maybe_unused]] const std::vector<int>& owner) {
#ifdef SKYLIT_HAVE_MPI
  if (g_count == 1) return;
  for (std::size_t i = 0; i < images.size(); ++i) {
    const int from = owner[i];
    if (from <= 0 || (g_rank != 0 && g_rank != from)) continue;
    const int tag = static_cast<int>(i % 30000);  // below every MPI's least tag upper bound, 32767
    int size[2] = {images[i].width, images[i].height};
    if (g_rank == from) {
      MPI_Send(size, 2, MPI_INT, 0, tag, MPI_COMM_WORLD);
      send_floats(images[i].xyz, 0, tag, /*sending=*/true);
    } else {
      MPI_Recv(size, 2, MPI_INT, from, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      images[i] = XyzImage(size[0], size[1]);
      send_floats(images[i].xyz, from, tag, /*sending=*/false);
    }
  }
#endif
}

ImageShare image_share_of_processes() {
  ImageShare share;
  share.part = g_rank;
  share.parts = g_count;
#ifdef SKYLIT_HAVE_MPI
  // Every rank packs its tiles' pixels in tile order; all ranks gather all packs and
  // unpack each rank's tiles where they belong.
  share.exchange = [](XyzImage& image) {
    const int tiles = image_tile_count(image.width, image.height);
    const auto tile_floats = [&](int tile) {
      const ImageTile t = image_tile(tile, image.width, image.height);
      return 3 * (t.x1 - t.x0) * (t.y1 - t.y0);
    };
    std::vector<int> counts(g_count, 0), offsets(g_count, 0);
    for (int tile = 0; tile < tiles; ++tile) counts[tile % g_count] += tile_floats(tile);
    for (int r = 1; r < g_count; ++r) offsets[r] = offsets[r - 1] + counts[r - 1];
    const auto for_each_value = [&](int rank, auto&& visit) {
      for (int tile = rank; tile < tiles; tile += g_count) {
        const ImageTile t = image_tile(tile, image.width, image.height);
        for (int y = t.y0; y < t.y1; ++y)
          for (int x = t.x0; x < t.x1; ++x)
            for (int c = 0; c < 3; ++c) visit(image.xyz[3 * (static_cast<std::size_t>(y) * image.width + x) + c]);
      }
    };
    std::vector<float> mine;
    mine.reserve(counts[g_rank]);
    for_each_value(g_rank, [&](float v) { mine.push_back(v); });
    std::vector<float> all(static_cast<std::size_t>(offsets.back()) + counts.back());
    MPI_Allgatherv(mine.data(), counts[g_rank], MPI_FLOAT, all.data(), counts.data(), offsets.data(), MPI_FLOAT,
                   MPI_COMM_WORLD);
    for (int r = 0; r < g_count; ++r) {
      std::size_t next = offsets[r];
      for_each_value(r, [&](float& v) { v = all[next++]; });
    }
  };
#endif
  return share;
}

}  // namespace skylit::cli
