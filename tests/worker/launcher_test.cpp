// The command lines of worker jobs (orchestrator/scheduler/launcher.hpp). That the srun line runs
// under a real Slurm is checked by tests/slurm/run_slurm_study.sh (docs/ORCHESTRATOR.md, "Slurm").
#include <catch2/catch.hpp>

#include "orchestrator/scheduler/launcher.hpp"

using namespace aerobreak;

TEST_CASE("Worker job command lines: mpirun, srun with PMIx and stdin to task 0, direct") {
  LauncherConfig config{"mpirun", 4, {"--hostfile", "hosts"}, "/opt/aerobreak"};
  CHECK(join_command(worker_job_command(config)) == "mpirun -np 4 --hostfile hosts /opt/aerobreak worker");
  config.kind = "srun";
  config.arguments = {"--mpi=pmi2"};
  // The launcher's own arguments come after aerobreak's, so that a site can override them.
  CHECK(join_command(worker_job_command(config)) ==
        "srun --ntasks=4 --input=0 --mpi=pmix --mpi=pmi2 /opt/aerobreak worker");
  config = {"direct", 1, {}, "/opt/aerobreak"};
  CHECK(join_command(worker_job_command(config)) == "/opt/aerobreak worker");
  config.ranks = 2;
  CHECK_THROWS_AS(worker_job_command(config), std::invalid_argument);
  config = {"pbs", 1, {}, "/opt/aerobreak"};
  CHECK_THROWS_AS(worker_job_command(config), std::invalid_argument);
}
