#!/usr/bin/env bash
# A distributed `motoflex fit` on a Slurm cluster: one MPI rank per task, OpenMP threads inside
# each rank (threads per rank = --cpus-per-task). Rank 0 runs the strategy and writes the run
# folder; every rank evaluates a fixed slice of each generation, so the result is bit-identical
# to a run on one machine with the same seed. Submit from the repository root:
#   sbatch scripts/slurm_fit.sh scenarios/fit/nao_quick.yaml runs/nao_cluster
# Continue a stopped or timed-out run with the same script and `resume`:
#   sbatch scripts/slurm_fit.sh resume runs/nao_cluster
# The run folder must be on a file system every node sees (rank 0 writes it; every rank reads
# the fit config, the scenario and the logs).
#SBATCH --job-name=motoflex-fit
#SBATCH --nodes=2
#SBATCH --ntasks=8
#SBATCH --cpus-per-task=4
#SBATCH --time=02:00:00
#SBATCH --output=motoflex-fit-%j.out
set -euo pipefail

threads="${SLURM_CPUS_PER_TASK:-1}"
export OMP_NUM_THREADS="$threads"
export OMP_PROC_BIND=close OMP_PLACES=cores

if [ "${1:-}" = "resume" ]; then
  arguments=(resume "$2")
else
  arguments=(fit "$1" --out "$2")
fi

# OpenMPI's mpirun reads the allocation from Slurm: --ntasks ranks, each bound to its
# --cpus-per-task cores. With a Slurm built with PMIx, `srun --mpi=pmix build/motoflex ...` works
# the same (motoflex detects either launcher). At the time limit Slurm sends SIGTERM and, after
# KillWait (often 30 s), SIGKILL: rank 0 finishes the current generation if it can, writes the
# checkpoint and releases the other ranks; either way the checkpoint of the last completed
# generation is intact, and `resume` continues from it.
mpirun --map-by "slot:PE=${threads}" --bind-to core \
  build/motoflex "${arguments[@]}" --threads "$threads"
