// MPI support of a build without MPI (CMake: MOTOFLEX_WITH_MPI=OFF or no MPI found): the types
// exist so that callers compile unchanged, and creating an MPI world says why it cannot work.

#include <stdexcept>

#include "motoflex_es/mpi_evaluator.hpp"
#include "motoflex_es/mpi_world.hpp"

namespace motoflex_es {
namespace {

[[noreturn]] void throw_built_without_mpi() {
  throw std::runtime_error(
      "this build has no MPI support (reconfigure with -DMOTOFLEX_WITH_MPI=ON and libopenmpi-dev "
      "installed)");
}

}  // namespace

bool mpi_built_in() {
  return false;
}

MpiWorld::MpiWorld() {
  throw_built_without_mpi();
}
MpiWorld::~MpiWorld() = default;
std::vector<int> MpiWorld::failed_ranks(bool) const {
  throw_built_without_mpi();
}
std::string MpiWorld::broadcast_from_root(const std::string&) const {
  throw_built_without_mpi();
}

MpiEvaluator::MpiEvaluator(const MpiWorld& world, int threads_per_rank)
    : world_(world), threads_per_rank_(threads_per_rank) {
  throw_built_without_mpi();
}
MpiEvaluator::~MpiEvaluator() = default;
void MpiEvaluator::evaluate(Problem&, const std::vector<std::vector<double>>&, std::vector<double>&,
                            const EvaluationContext&) {
  throw_built_without_mpi();
}
std::string MpiEvaluator::name() const {
  return "mpi (not built)";
}
int MpiEvaluator::workers() const {
  return 0;
}
void MpiEvaluator::stop_workers() {}

void serve_mpi_evaluations(const MpiWorld&, Problem&, int) {
  throw_built_without_mpi();
}

}  // namespace motoflex_es
