#include "orchestrator/worker/mpi_worker.hpp"

#include <unistd.h>

#include <exception>

#include "engine/core/version.hpp"
#include "orchestrator/worker/broker.hpp"
#include "orchestrator/worker/mpi_session.hpp"
#include "orchestrator/worker/protocol_output.hpp"
#include "orchestrator/worker/rank_worker.hpp"
#include "orchestrator/worker/worker_protocol.hpp"

namespace aerobreak {
namespace {

void run_rank(const MpiSession& mpi, std::chrono::milliseconds silence_limit) {
  std::vector<std::string> hosts = mpi.gather_hosts();
  if (mpi.rank() != 0) {
    send_stdout_to_stderr();
    run_rank_worker(mpi.rank());
    return;
  }
  ProtocolOutput out;
  out.send(ready_message(mpi.size(), hosts, ::getpid(), version()));
  Broker(mpi, out, std::move(hosts), silence_limit).run();
}

}  // namespace

void run_worker_job(std::chrono::milliseconds silence_limit) {
  const MpiSession mpi;
  try {
    run_rank(mpi, silence_limit);
  } catch (const std::exception& e) {
    // One rank cannot go on: the job as a whole cannot keep its protocol, so it ends at once.
    mpi.abort(e.what());
  }
}

}  // namespace aerobreak
