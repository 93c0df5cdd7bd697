// The parts of the MPI support that need no MPI: how a batch is split over ranks, and what the
// launcher told this process (compiled with and without MPI).

#include <cerrno>
#include <cstdlib>

#include "motoflex_es/mpi_world.hpp"

namespace motoflex_es {
namespace {

// The value of `name` if it is set to a positive integer, else 0.
long positive_environment_value(const char* name) {
  const char* text = std::getenv(name);
  if (text == nullptr || *text == '\0') return 0;
  char* end = nullptr;
  errno = 0;
  const long value = std::strtol(text, &end, 10);
  if (errno != 0 || *end != '\0' || value <= 0) return 0;
  return value;
}

}  // namespace

BatchSlice batch_slice(std::size_t batch_size, int rank, int ranks) {
  const std::size_t r = static_cast<std::size_t>(rank);
  const std::size_t all = static_cast<std::size_t>(ranks);
  const std::size_t base = batch_size / all;
  const std::size_t extra = batch_size % all;
  BatchSlice slice;
  slice.first = r * base + (r < extra ? r : extra);
  slice.count = base + (r < extra ? 1 : 0);
  return slice;
}

int launcher_process_count() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "SLURM_STEP_NUM_TASKS"}) {
    const long value = positive_environment_value(name);
    if (value > 0) return static_cast<int>(value);
  }
  return 1;
}

}  // namespace motoflex_es
