#include "motoflex_es/mpi_world.hpp"

#include <mpi.h>

#include <stdexcept>

namespace motoflex_es {

bool mpi_built_in() {
  return true;
}

MpiWorld::MpiWorld() {
  int initialised = 0;
  MPI_Initialized(&initialised);
  if (initialised != 0) throw std::logic_error("MpiWorld: MPI is already initialised");
  int provided = 0;
  // MPI's default error handler aborts the whole job on a communication error, which is what
  // a distributed fit wants: no rank can go on without the others.
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiWorld::~MpiWorld() {
  MPI_Finalize();
}

std::vector<int> MpiWorld::failed_ranks(bool ok) const {
  const int mine = ok ? 1 : 0;
  std::vector<int> all(static_cast<std::size_t>(size_), 0);
  MPI_Allgather(&mine, 1, MPI_INT, all.data(), 1, MPI_INT, MPI_COMM_WORLD);
  std::vector<int> failed;
  for (int r = 0; r < size_; ++r) {
    if (all[static_cast<std::size_t>(r)] == 0) failed.push_back(r);
  }
  return failed;
}

std::string MpiWorld::broadcast_from_root(const std::string& text) const {
  unsigned long long length = rank_ == 0 ? text.size() : 0;
  MPI_Bcast(&length, 1, MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD);
  std::string result = rank_ == 0 ? text : std::string(length, '\0');
  if (length > 0) {
    MPI_Bcast(result.data(), static_cast<int>(length), MPI_CHAR, 0, MPI_COMM_WORLD);
  }
  return result;
}

}  // namespace motoflex_es
