#pragma once

namespace aerobreak {

// The loop of a worker rank (rank >= 1): waits for a case from rank 0 without busy-polling, runs
// it on a thread of its own while telling rank 0 every kHeartbeatInterval that it is alive, sends
// its answer back, until rank 0 says stop.
void run_rank_worker(int rank);

}  // namespace aerobreak
