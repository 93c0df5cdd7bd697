#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace motoflex_es {

// True if this library was built with MPI (CMake option MOTOFLEX_WITH_MPI and an MPI found).
bool mpi_built_in();

// How many processes the launcher that started this process says the job has, read from the
// environment without initialising MPI: OMPI_COMM_WORLD_SIZE (OpenMPI's mpirun), PMI_SIZE
// (MPICH/Hydra, srun --mpi=pmi2), SLURM_STEP_NUM_TASKS (srun), in that order. 1 if none is
// set or the value is not a positive integer (a process started by hand).
int launcher_process_count();

// The contiguous slice of a batch that one rank evaluates: individuals [first, first + count).
// Fixed by (batch size, rank, ranks) alone, so the same individual always lands on the same
// rank: rank r gets ⌊n/R⌋ individuals, plus one if r < n mod R, in rank order.
struct BatchSlice {
  std::size_t first = 0;
  std::size_t count = 0;
};
BatchSlice batch_slice(std::size_t batch_size, int rank, int ranks);

// MPI_Init_thread (MPI_THREAD_FUNNELED: only the thread that created the world calls MPI; OpenMP
// threads inside a rank do not) on construction, MPI_Finalize on destruction; one per process.
// Every member function except rank() and size() is collective over MPI_COMM_WORLD.
// Throws std::runtime_error when the library was built without MPI.
class MpiWorld {
 public:
  MpiWorld();
  ~MpiWorld();
  MpiWorld(const MpiWorld&) = delete;
  MpiWorld& operator=(const MpiWorld&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }

  // The ranks whose `ok` is false, in rank order, known to every rank (empty: all agree).
  std::vector<int> failed_ranks(bool ok) const;
  // `text` of rank 0, on every rank.
  std::string broadcast_from_root(const std::string& text) const;

 private:
  int rank_ = 0;
  int size_ = 1;
};

}  // namespace motoflex_es
