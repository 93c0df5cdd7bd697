#pragma once

#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <thread>

namespace motoflex_es {

// Completes a non-blocking MPI operation without spinning a core. OpenMPI's blocking calls
// busy-poll, so a worker waiting for the next batch while rank 0 checkpoints and plots, or a
// rank whose slice finished first, would take a whole core from the ranks and OpenMP threads
// still simulating (two ranks × two threads share two cores). Polling with a sleep that grows to
// 1 ms costs about a millisecond per batch of rollouts that take seconds.
inline void wait_without_spinning(MPI_Request& request) {
  std::chrono::microseconds pause(10);
  while (true) {
    int done = 0;
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (done != 0) return;
    std::this_thread::sleep_for(pause);
    pause = std::min(pause * 2, std::chrono::microseconds(1000));
  }
}

}  // namespace motoflex_es
