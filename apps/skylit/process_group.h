// The processes one run is spread over (docs/cluster.md): the ranks of MPI when mpirun
// (or srun) started the program, otherwise this process alone. Items (sweep cells,
// animation frames) go to ranks round-robin; a single image is split by tiles.
#pragma once

#include <vector>

#include "skylit/render/image_loop.h"
#include "skylit/spectrum/xyz_image.h"

namespace skylit::cli {

// Joins MPI for the program's lifetime when the environment shows an MPI launcher.
// Built without MPI and started as one of several ranks: InputError saying how to get
// MPI (one process would do all the work N times over).
class ProcessGroup {
 public:
  ProcessGroup(int* argc, char*** argv);
  ~ProcessGroup();
  ProcessGroup(const ProcessGroup&) = delete;
  ProcessGroup& operator=(const ProcessGroup&) = delete;
};

int process_rank();   // 0 alone
int process_count();  // 1 alone
inline bool is_first_process() { return process_rank() == 0; }

// Ends every rank with this exit status (an error on one rank must not leave the
// others waiting); returns when running alone.
void abort_other_processes(int status);

// On the first process, fills in images[i] for every item another rank rendered;
// `owner(i)` names the rank that rendered item i (-1: nobody, it stays as it is).
// Collective: every rank calls it.
void gather_on_first_process(std::vector<XyzImage>& images, const std::vector<int>& owner);

// This process's share of one image's tiles, exchanged between the ranks (ImageShare);
// the whole image when alone.
ImageShare image_share_of_processes();

}  // namespace skylit::cli
