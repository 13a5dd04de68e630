#pragma once
#include <string>
#include <vector>

namespace aerobreak {

// MPI for the worker job, initialised with MPI_THREAD_FUNNELED (rank 0 runs cases in a second
// thread, but only its main thread calls MPI) and finalised on destruction. Only the worker
// subcommand creates one: every other subcommand runs without mpirun. Started directly, without
// mpirun, the program is an Open MPI singleton of one rank.
class MpiSession {
 public:
  MpiSession();  // throws std::runtime_error if MPI cannot give FUNNELED
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  ~MpiSession();

  int rank() const { return rank_; }
  int size() const { return size_; }
  const std::string& host() const { return host_; }

  // Every rank's host name, in rank order, on rank 0 (empty on the others). Collective.
  std::vector<std::string> gather_hosts() const;

  // Ends the whole job at once, every rank of it whatever it is doing, with exit status 1 after
  // telling stderr why.
  [[noreturn]] void abort(const std::string& reason) const;

 private:
  int rank_ = 0;
  int size_ = 1;
  std::string host_;
};

}  // namespace aerobreak
