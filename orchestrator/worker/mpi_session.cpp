#include "orchestrator/worker/mpi_session.hpp"

#include <mpi.h>
#include <signal.h>
#include <sys/prctl.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace aerobreak {

namespace {

// Open MPI starts every rank in a process group of its own, so killing the launcher's group does
// not reach them, and a rank whose launcher was killed (kill -9 of mpirun, a lost node daemon)
// would compute on for nobody, holding its case's files. Each rank therefore dies with the process
// that started it (mpirun, orted, slurmstepd, or the orchestrator for a singleton).
void die_with_launcher() {
  const pid_t launcher = ::getppid();
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (::getppid() != launcher) std::_Exit(1);  // it died before the line above
}

}  // namespace

MpiSession::MpiSession() {
  die_with_launcher();
  int provided = MPI_THREAD_SINGLE;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  if (provided < MPI_THREAD_FUNNELED) {
    MPI_Finalize();
    throw std::runtime_error("the MPI library does not support MPI_THREAD_FUNNELED");
  }
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  char name[MPI_MAX_PROCESSOR_NAME] = {};
  int length = 0;
  MPI_Get_processor_name(name, &length);
  host_.assign(name, static_cast<std::size_t>(length));
}

MpiSession::~MpiSession() { MPI_Finalize(); }

std::vector<std::string> MpiSession::gather_hosts() const {
  std::string own(MPI_MAX_PROCESSOR_NAME, '\0');
  own.replace(0, host_.size(), host_);
  std::string all(rank_ == 0 ? static_cast<std::size_t>(size_) * MPI_MAX_PROCESSOR_NAME : 0, '\0');
  MPI_Gather(own.data(), MPI_MAX_PROCESSOR_NAME, MPI_CHAR, all.data(), MPI_MAX_PROCESSOR_NAME, MPI_CHAR, 0,
             MPI_COMM_WORLD);
  std::vector<std::string> hosts;
  if (rank_ != 0) return hosts;
  for (int r = 0; r < size_; ++r)
    hosts.emplace_back(all.c_str() + static_cast<std::size_t>(r) * MPI_MAX_PROCESSOR_NAME);
  return hosts;
}

void MpiSession::abort(const std::string& reason) const {
  std::fprintf(stderr, "aerobreak worker: rank %d: %s\n", rank_, reason.c_str());
  std::fflush(stderr);
  MPI_Abort(MPI_COMM_WORLD, 1);
  std::_Exit(1);  // MPI_Abort does not return; this only tells the compiler so
}

}  // namespace aerobreak
