#pragma once
#include <chrono>

namespace aerobreak {

// `aerobreak worker`: one MPI worker job for the orchestrator (docs/WORKER_PROTOCOL.md). Started
// as `mpirun -np K aerobreak worker` (or srun), or directly as a singleton of one rank. Rank 0
// announces the job ("ready"), brokers cases from stdin to the ranks and runs cases itself in a
// second thread; ranks >= 1 run the cases rank 0 hands them. Returns after a stop message, once
// every case is answered and MPI is finalised; stdin ending without a stop, or a failure of the
// job itself, aborts the whole job instead (MPI_Abort, exit status 1). A busy rank silent for
// `silence_limit` is given up (broker.hpp).
void run_worker_job(std::chrono::milliseconds silence_limit);

}  // namespace aerobreak
