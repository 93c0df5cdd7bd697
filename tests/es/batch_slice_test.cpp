// How the MpiEvaluator splits a batch over ranks, and how a process learns it was started by an
// MPI launcher (both without MPI itself).

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>

#include "motoflex_es/mpi_world.hpp"

namespace motoflex_es {
namespace {

TEST(BatchSliceTest, SlicesAreContiguousInRankOrderAndDifferByAtMostOne) {
  for (std::size_t n = 0; n <= 41; ++n) {
    for (int ranks = 1; ranks <= 7; ++ranks) {
      std::size_t next = 0, smallest = n, largest = 0;
      for (int r = 0; r < ranks; ++r) {
        const BatchSlice slice = batch_slice(n, r, ranks);
        EXPECT_EQ(slice.first, next) << "n " << n << " ranks " << ranks << " rank " << r;
        next = slice.first + slice.count;
        smallest = std::min(smallest, slice.count);
        largest = std::max(largest, slice.count);
      }
      EXPECT_EQ(next, n) << "n " << n << " ranks " << ranks;
      EXPECT_LE(largest - smallest, 1u) << "n " << n << " ranks " << ranks;
    }
  }
  // The larger slices go to the first ranks: 10 over 3 ranks is 4, 3, 3.
  EXPECT_EQ(batch_slice(10, 0, 3).count, 4u);
  EXPECT_EQ(batch_slice(10, 1, 3).first, 4u);
  EXPECT_EQ(batch_slice(10, 2, 3).first, 7u);
  EXPECT_EQ(batch_slice(10, 2, 3).count, 3u);
}

TEST(BatchSliceTest, LauncherProcessCountReadsOpenMpiPmiAndSlurm) {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "SLURM_STEP_NUM_TASKS"}) {
    unsetenv(name);
  }
  EXPECT_EQ(launcher_process_count(), 1);
  setenv("SLURM_STEP_NUM_TASKS", "8", 1);
  EXPECT_EQ(launcher_process_count(), 8);
  setenv("PMI_SIZE", "4", 1);
  EXPECT_EQ(launcher_process_count(), 4);  // PMI before Slurm
  setenv("OMPI_COMM_WORLD_SIZE", "2", 1);
  EXPECT_EQ(launcher_process_count(), 2);  // OpenMPI first
  setenv("OMPI_COMM_WORLD_SIZE", "two", 1);
  EXPECT_EQ(launcher_process_count(), 4);  // not a positive integer: ignored
  setenv("OMPI_COMM_WORLD_SIZE", "0", 1);
  EXPECT_EQ(launcher_process_count(), 4);
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "SLURM_STEP_NUM_TASKS"}) {
    unsetenv(name);
  }
  EXPECT_EQ(launcher_process_count(), 1);
}

}  // namespace
}  // namespace motoflex_es
