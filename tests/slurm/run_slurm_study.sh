#!/usr/bin/env bash
# A study through a real Slurm (docs/ORCHESTRATOR.md, "Slurm"): brings up a single-node Slurm on
# this machine from Debian's slurm-wlm and munge (munged, slurmctld and slurmd on localhost, with a
# private key, socket, ports, state and logs in a temporary directory, so that nothing of the
# machine's own configuration is used or changed), runs a small study with
# `aerobreak run --launcher srun`, checks that every case has exactly one result and that the
# worker jobs ran under srun, and tears everything down. Not part of the test suite (it installs
# packages and starts daemons); needs root or sudo. Exit status 0 when the study checks out.
# Usage: tests/slurm/run_slurm_study.sh [BUILD_DIR]   (KEEP=1 keeps the directory for a look)
set -euo pipefail
build=${1:-build}
aerobreak=$(realpath "$build/aerobreak")
source "$(dirname "$0")/slurm_support.sh"
sudo=("${slurm_sudo[@]}")
install_missing_packages slurm-wlm munge sqlite3

work=$(mktemp -d /tmp/aerobreak-slurm.XXXXXX)
chmod 755 "$work"
daemons=()  # munged, slurmctld, slurmd: stopped in the reverse order
# The slurmstepd processes of this cluster: those listening on sockets in its spool directory.
step_daemons() {
  "${sudo[@]}" ss -Hxlp 2>/dev/null | awk -v dir="$work/spool/" 'index($0, dir)' | grep -o 'pid=[0-9]*' |
    cut -d= -f2 | sort -u
}
teardown() {
  local status=$?
  if ((${#daemons[@]} >= 2)); then
    "${sudo[@]}" env SLURM_CONF="$work/slurm.conf" scancel --quiet --partition=aerobreak 2>/dev/null || true
    for _ in $(seq 100); do [[ -z "$(squeue -h 2>/dev/null)" ]] && break; sleep 0.1; done
  fi
  for ((k = ${#daemons[@]} - 1; k >= 0; --k)); do
    if ((k == 1)); then for pid in $(step_daemons); do stop_process "$pid"; done; fi  # after slurmd: its steps
    stop_process "${daemons[k]}"
  done
  if [[ "${KEEP:-0}" == 1 ]]; then echo "run_slurm_study: kept $work"; else "${sudo[@]}" rm -rf "$work"; fi
  exit "$status"
}
trap teardown EXIT

free_port() {
  local port
  while :; do
    port=$(shuf -i 20000-29999 -n 1)
    ss -Htln "sport = :$port" | grep -q . || { echo "$port"; return; }
  done
}

host=$(hostname -s)
cpus=$(nproc)
mkdir -p "$work/state" "$work/spool"
daemons+=("$(start_munge "$work/munge")")  # the socket must be reachable by the user that runs srun

cat >"$work/slurm.conf" <<CONF
ClusterName=aerobreak-test
SlurmctldHost=$host
SlurmctldPort=$(free_port)
SlurmdPort=$(free_port)
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
$(common_slurm_conf "$work/munge")
NodeName=$host CPUs=$cpus State=UNKNOWN
PartitionName=aerobreak Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF="$work/slurm.conf"

"${sudo[@]}" env SLURM_CONF="$SLURM_CONF" slurmctld -D -i >"$work/slurmctld.out" 2>&1 &
daemons+=($!)
"${sudo[@]}" env SLURM_CONF="$SLURM_CONF" slurmd -D >"$work/slurmd.out" 2>&1 &
daemons+=($!)
state=
for _ in $(seq 300); do
  state=$(sinfo -h -N -o %t 2>/dev/null || true)
  [[ "$state" == idle ]] && break
  sleep 0.1
done
if [[ "$state" != idle ]]; then
  echo "run_slurm_study: the node did not come up (state '$state')" >&2
  tail -n 20 "$work/slurmctld.log" "$work/slurmd.log" >&2 || true
  exit 1
fi
echo "run_slurm_study: Slurm $(sinfo -V | cut -d' ' -f2) up: node $host, $cpus CPUs, partition aerobreak"

cat >"$work/study.json" <<'STUDY'
{
  "name": "slurm check",
  "base": {
    "cluster": {"generator": {"method": "ballistic", "primaries": 16}},
    "material": {"gamma_over_kn": 0.001},
    "model": {"damping": {"law": "viscoelastic", "dissipative_time": 0.05}},
    "run": {"time_limit": 20000}
  },
  "axes": {"impact_speed": {"values": [0.005, 0.02, 0.08]}},
  "replicates": {"count": 4, "seed": 7}
}
STUDY
ranks=$((cpus < 2 ? 1 : 2))
store="$work/slurm.sqlite"
echo "run_slurm_study: aerobreak run --launcher srun --ranks $ranks"
"$aerobreak" run "$work/study.json" --store "$store" --launcher srun --ranks "$ranks" --port 0 "${@:2}" \
  >"$work/run.out" 2>&1 || {
  echo "run_slurm_study: aerobreak run failed:" >&2
  tail -n 30 "$work/run.out" >&2
  tail -n 30 "${store%.sqlite}.data"/logs/job-*.log >&2 2>/dev/null || true
  exit 1
}
tail -n 8 "$work/run.out"

query() { sqlite3 "$store" "$1"; }
cases=$(query "SELECT count(*) FROM cases")
done_cases=$(query "SELECT count(*) FROM cases WHERE status = 'done'")
results=$(query "SELECT count(*) FROM results")
distinct=$(query "SELECT count(DISTINCT case_id) FROM results")
srun_jobs=$(query "SELECT count(*) FROM jobs WHERE command LIKE 'srun %'")
ranks_seen=$(query "SELECT count(DISTINCT worker) FROM cases")
echo "run_slurm_study: $cases cases, $done_cases done, $results results ($distinct distinct cases)," \
  "$srun_jobs srun job(s), $ranks_seen worker rank(s) used"
[[ "$cases" -eq 12 && "$done_cases" -eq 12 && "$results" -eq 12 && "$distinct" -eq 12 && "$srun_jobs" -ge 1 &&
   "$ranks_seen" -eq "$ranks" ]] || { echo "run_slurm_study: FAILED" >&2; exit 1; }

# The worker jobs' allocations end with the run: none may be left holding the node.
left=
for _ in $(seq 150); do
  left=$(squeue -h -o '%i %T %j')
  [[ -z "$left" ]] && break
  sleep 0.1
done
if [[ -n "$left" ]]; then
  echo "run_slurm_study: FAILED: Slurm jobs left after the run: $left" >&2
  exit 1
fi
echo "run_slurm_study: OK (exactly one result per case, no Slurm job left)"
