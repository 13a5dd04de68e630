#!/usr/bin/env bash
# Studies across a multi-node Slurm cluster built on this one machine (docs/ORCHESTRATOR.md,
# "Slurm"), from Debian's slurm-wlm, munge and Open MPI: three slurmd nodes, each in network, UTS
# and mount namespaces of its own with its own host name and address on a private bridge, a
# controller in a fourth, and this machine as the login node (tests/slurm/netns_cluster.sh). It
# runs `aerobreak run --launcher srun` and `aerobreak serve --launcher srun` with one worker job
# spread over the nodes, does to the study what clusters do, and checks the store file after each:
#
#   spread     ranks on every node; cases per hour against the same ranks on one node
#   node-loss  a node killed mid-study (its slurmd, step daemons and tasks): the study finishes on
#              the others
#   link-cut   a node's link cut mid-study: the same
#   time-limit the worker job's allocation reaches its time limit (--time) mid-study: the
#              orchestrator goes on in a new allocation
#   scancel    the worker job's allocation cancelled mid-study: the same
#   batch      the orchestrator itself in a batch job, cancelled mid-study; a new batch job resumes
#   few-cases  `aerobreak serve`: more ranks than cases, then a study whose cases are nearly all done
#   sigstop    a rank on a remote node stopped (SIGSTOP) mid-case
#
# The check of the store after each: every case done with exactly one result, every data file as
# its result recorded it, no case, attempt or job left running, no Slurm job left, and every result
# committed before the fault unchanged (same row, same attempts: nothing re-run).
#
# Not part of the test suite: it needs root (namespaces, a bridge, daemons) and installs slurm-wlm
# and munge if missing; it tears down everything it made (namespaces, bridge, daemons, temporary
# files) also when it fails. About 15 minutes on 2 cores.
# Usage: tests/slurm/run_slurm_cluster.sh [BUILD_DIR]
#   SCENARIOS="spread node-loss ..." runs only those; RANKS (6) ranks per worker job; ROUNDS (2)
#   alternations of the spread measurement; KEEP=1 keeps the work directory (logs, stores).
set -euo pipefail
build=${1:-build}
here=$(cd "$(dirname "$0")" && pwd)
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "run_slurm_cluster: needs root or sudo" >&2; exit 1; }
  exec sudo --preserve-env=SCENARIOS,RANKS,ROUNDS,KEEP "$0" "$@"
fi
source "$here/slurm_support.sh"
source "$here/netns_cluster.sh"
install_missing_packages slurm-wlm munge sqlite3 iproute2 util-linux openmpi-bin

scenarios=${SCENARIOS:-spread node-loss link-cut time-limit scancel batch few-cases sigstop}
ranks=${RANKS:-6}
silence=20  # --silence-limit: the tests wait 20 s for a silent job or rank, not the default 60
# The nodes have a /tmp of their own: a work directory there would be out of their reach. The
# binary is copied there too (the build may be under /tmp, or rebuilt while this runs).
work=$(mktemp -d /var/tmp/aerobreak-cluster.XXXXXX)
mkdir -p "$work/bin"
cp "$build/aerobreak" "$work/bin/aerobreak"
aerobreak=$work/bin/aerobreak
orchestrators=()  # aerobreak run/serve processes started here
failures=0

teardown() {
  local status=$? pid
  for pid in "${orchestrators[@]}"; do stop_process "$pid"; done
  cluster_destroy
  if [[ "${KEEP:-0}" == 1 ]]; then echo "run_slurm_cluster: kept $work"; else rm -rf "$work"; fi
  if ip link show "$cluster_bridge" >/dev/null 2>&1 || [[ -n "$(cluster_namespaces)" ]]; then
    echo "run_slurm_cluster: teardown left $cluster_bridge or namespaces behind" >&2
    status=1
  fi
  exit "$status"
}
trap teardown EXIT
trap 'exit 130' INT TERM

say() { echo "run_slurm_cluster: $*"; }
fail() {
  echo "run_slurm_cluster: FAILED: $*" >&2
  failures=$((failures + 1))
}
query() { sqlite3 -cmd ".timeout 5000" "$1" "$2"; }

# A study of 3 x REPLICATES cases of ballistic clusters of PRIMARIES (32) at three speeds: about a
# second of one core each.
write_study() {
  cat >"$1" <<STUDY
{
  "name": "$2",
  "base": {
    "cluster": {"generator": {"method": "ballistic", "primaries": ${5:-32}}},
    "material": {"gamma_over_kn": 0.001},
    "model": {"damping": {"law": "viscoelastic", "dissipative_time": 0.05}},
    "run": {"time_limit": 20000}
  },
  "axes": {"impact_speed": {"values": [0.005, 0.02, 0.08]}},
  "replicates": {"count": $3, "seed": $4}
}
STUDY
}

# aerobreak run with srun worker jobs of $ranks ranks; extra arguments are aerobreak's.
run_args() {
  echo --launcher srun --ranks "$ranks" --silence-limit "$silence" --port 0 "$@"
}

# Starts `aerobreak run STUDY --store STORE ARGS...` in the background; its pid in $last_pid.
start_run() {
  local study=$1 store=$2
  shift 2
  # shellcheck disable=SC2046
  "$aerobreak" run "$study" --store "$store" $(run_args "$@") >"${store%.sqlite}.out" 2>&1 &
  last_pid=$!
  orchestrators+=("$last_pid")
}

# Waits up to SECONDS for process PID to end; false if it did not.
wait_process() {
  for _ in $(seq $(($2 * 10))); do kill -0 "$1" 2>/dev/null || return 0; sleep 0.1; done
  return 1
}

# Waits up to SECONDS until STORE has at least COUNT cases done.
wait_done() {
  for _ in $(seq $(($3 * 5))); do
    [[ -f "$1" ]] && (($(query "$1" "SELECT count(*) FROM cases WHERE status = 'done'" 2>/dev/null || echo 0) >= $2)) &&
      return 0
    sleep 0.2
  done
  return 1
}

# Waits up to SECONDS until a case of STORE runs on HOST.
wait_running_on() {
  for _ in $(seq $(($3 * 5))); do
    (($(query "$1" "SELECT count(*) FROM cases WHERE status = 'running' AND worker LIKE '$2:%'") > 0)) && return 0
    sleep 0.2
  done
  return 1
}

# Every committed result with its case's attempt count, one line each, to compare later.
snapshot() {
  query "$1" "SELECT r.case_id, c.attempts, r.attempt, r.outcome, r.data_file_sha256, r.committed_at,
                     length(r.document), r.document FROM results r JOIN cases c ON c.id = r.case_id
              ORDER BY r.case_id" >"$2"
}

wait_no_slurm_jobs() {
  local left=
  for _ in $(seq 300); do
    left=$(squeue -h -o '%i %T %j' 2>/dev/null)
    [[ -z "$left" ]] && return 0
    sleep 0.1
  done
  fail "Slurm jobs left: $left"
}

# The data file of every result as the result recorded it (size and SHA-256).
check_data_files() {
  local store=$1 data file sha size bad=0
  data=${store%.sqlite}.data
  while IFS='|' read -r file size sha; do
    [[ -z "$file" ]] && continue
    [[ "$file" == /* ]] || file=$data/$file
    if [[ ! -f "$file" || "$(stat -c %s "$file")" != "$size" ||
          "$(sha256sum <"$file" | cut -d' ' -f1)" != "$sha" ]]; then
      bad=$((bad + 1))
    fi
  done < <(query "$store" "SELECT data_file, data_file_size, data_file_sha256 FROM results")
  ((bad == 0)) || fail "$bad data file(s) differ from what their results recorded"
}

# The check of the store after a scenario: CASES cases, each done with exactly one result, nothing
# left running, and (with SNAPSHOT) every result committed before the fault unchanged.
check_store() {
  local label=$1 store=$2 cases=$3 snap=${4:-} counts changed
  counts=$(query "$store" "SELECT (SELECT count(*) FROM cases), (SELECT count(*) FROM cases WHERE status = 'done'),
    (SELECT count(*) FROM results), (SELECT count(DISTINCT case_id) FROM results),
    (SELECT count(*) FROM cases WHERE status IN ('running', 'queued')),
    (SELECT count(*) FROM attempts WHERE ended_at IS NULL), (SELECT count(*) FROM jobs WHERE ended_at IS NULL),
    (SELECT count(*) FROM jobs), (SELECT coalesce(sum(failures), 0) FROM cases)")
  IFS='|' read -r n finished results distinct open attempts jobs_open jobs failures_counted <<<"$counts"
  say "$label: $n cases, $finished done, $results results ($distinct distinct), $open queued or running," \
    "$attempts attempt(s) and $jobs_open job(s) open; $jobs worker job(s), $failures_counted failure(s) counted"
  [[ "$n" -eq "$cases" && "$finished" -eq "$cases" && "$results" -eq "$cases" && "$distinct" -eq "$cases" &&
     "$open" -eq 0 && "$attempts" -eq 0 && "$jobs_open" -eq 0 ]] || fail "$label: the store does not check out"
  if [[ -n "$snap" ]]; then
    snapshot "$store" "$snap.after"
    changed=$(comm -23 <(sort "$snap") <(sort "$snap.after") | wc -l)
    say "$label: $(wc -l <"$snap") result(s) committed before the fault, $changed changed or re-run"
    ((changed == 0)) || fail "$label: results committed before the fault changed"
  fi
  check_data_files "$store"
  wait_no_slurm_jobs
  query "$store" "SELECT '  job ' || id || ': ' || coalesce(hosts, '(never ready)') || ', exit ' ||
                         coalesce(exit_status, '-') || ', ' || coalesce(note, '') FROM jobs"
}

hosts_used() {
  query "$1" "SELECT group_concat(h, ' ') FROM (SELECT DISTINCT substr(worker, 1, instr(worker, ':') - 1) AS h
              FROM cases WHERE worker IS NOT NULL ORDER BY h)"
}
done_cases() { query "$1" "SELECT count(*) FROM cases WHERE status = 'done'"; }

# Cases per hour from the store: cases over the span from the first start to the last finish.
cases_per_hour() {
  query "$1" "SELECT printf('%.0f', count(*) * 3600.0 / (max(finished_at) - min(started_at))) FROM cases"
}

# Node I back after a failure, idle again (ReturnToService=2 returns a node that registers).
revive_node() {
  node_join "$1"
  [[ -n "$(node_pids "$1" | head -c1)" ]] || node_start "$1"
  for _ in $(seq 300); do
    case "$(node_state "$1")" in
      idle) return 0 ;;
      down* | drain*) scontrol update nodename="$(node_name "$1")" state=resume 2>/dev/null || true ;;
    esac
    sleep 0.2
  done
  fail "node $(node_name "$1") did not come back ($(node_state "$1"))"
}

scenario_spread() {
  local round placement store rate
  declare -A rates
  write_study "$work/spread.json" "spread" 20 21
  for round in $(seq "${ROUNDS:-2}"); do
    for placement in one three; do
      store=$work/spread-$placement-$round.sqlite
      placement_args=(--launcher-arg=--nodes=1)
      [[ $placement == one ]] ||
        placement_args=(--launcher-arg=--nodes=3 "--launcher-arg=--ntasks-per-node=$((ranks / 3))")
      "$aerobreak" run "$work/spread.json" --store "$store" $(run_args "${placement_args[@]}") \
        >"$work/spread.out" 2>&1 || fail "spread: aerobreak run failed"
      rate=$(cases_per_hour "$store")
      rates[$placement]="${rates[$placement]:-} $rate"
      say "spread: $ranks ranks on $placement node(s) ($(hosts_used "$store")): $rate cases/hour"
      check_store "spread ($placement node(s), round $round)" "$store" 60
    done
    [[ "$(hosts_used "$store")" == "abnode1 abnode2 abnode3" ]] || fail "spread: the ranks were not on every node"
  done
  say "spread: cases/hour, $ranks ranks on one node:${rates[one]}; on three nodes:${rates[three]}"
}

# A node lost mid-study, by FAULT (node_kill or node_cut) of node NODE.
lose_node_mid_study() {
  local label=$1 fault=$2 node=$3 store=$work/$1.sqlite host pid lost_at
  host=$(node_name "$node")
  write_study "$work/$label.json" "$label" 50 "$4"
  start_run "$work/$label.json" "$store" --launcher-arg=--nodes=2-3 --launcher-arg=--ntasks-per-node=$((ranks / 2)) \
    --launcher-arg=--distribution=cyclic
  pid=$last_pid
  wait_done "$store" 30 300 && wait_running_on "$store" "$host" 60 ||
    fail "$label: the study did not get going on $host"
  snapshot "$store" "$work/$label.snapshot"
  lost_at=$(date +%s.%N)
  "$fault" "$node"
  say "$label: $fault $host with $(done_cases "$store") cases done"
  wait_process "$pid" 900 || fail "$label: the study did not finish within 15 minutes"
  wait "$pid" || fail "$label: aerobreak run failed ($(tail -n 3 "${store%.sqlite}.out"))"
  check_store "$label" "$store" 150 "$work/$label.snapshot"
  local after
  after=$(query "$store" "SELECT count(*) FROM cases
                          WHERE started_at > $lost_at + $silence + 15 AND worker LIKE '$host:%'")
  ((after == 0)) || fail "$label: $after case(s) started on $host after it was lost"
  say "$label: study finished" \
    "$(query "$store" "SELECT printf('%.0f', max(finished_at) - $lost_at) FROM cases") s after the loss"
  revive_node "$node"
}

scenario_node_loss() { lose_node_mid_study node-loss node_kill 3 31; }
scenario_link_cut() { lose_node_mid_study link-cut node_cut 2 32; }

scenario_time_limit() {
  local store=$work/time-limit.sqlite
  write_study "$work/time-limit.json" "time limit" 150 41
  "$aerobreak" run "$work/time-limit.json" --store "$store" \
    $(run_args --launcher-arg=--nodes=3 --launcher-arg=--ntasks-per-node=$((ranks / 3)) --launcher-arg=--time=1) \
    >"$work/time-limit.out" 2>&1 || fail "time-limit: aerobreak run failed"
  check_store "time-limit" "$store" 450
  grep -qs "DUE TO TIME LIMIT" "$work/time-limit.data"/logs/job-*.log ||
    fail "time-limit: no worker job reached its time limit (the study was too short?)"
}

scenario_scancel() {
  local store=$work/scancel.sqlite pid job
  write_study "$work/scancel.json" "scancel" 40 51
  start_run "$work/scancel.json" "$store" --launcher-arg=--nodes=3 --launcher-arg=--ntasks-per-node=$((ranks / 3))
  pid=$last_pid
  wait_done "$store" 30 300 || fail "scancel: the study did not get going"
  snapshot "$store" "$work/scancel.snapshot"
  job=$(squeue -h -o %i | head -n 1)
  scancel "$job"
  say "scancel: cancelled Slurm job $job with $(done_cases "$store") cases done"
  wait_process "$pid" 600 || fail "scancel: the study did not finish within 10 minutes"
  wait "$pid" || fail "scancel: aerobreak run failed"
  check_store "scancel" "$store" 120 "$work/scancel.snapshot"
}

# The orchestrator in a batch job of its own, as on a cluster without a login node that may run it.
submit_batch() {
  sbatch --parsable --nodes=3 --ntasks="$ranks" --ntasks-per-node=$((ranks / 3)) --chdir="$work" \
    --output="$work/batch-%j.out" \
    --wrap="exec $aerobreak run $work/batch.json --store $work/batch.sqlite $(run_args)"
}

wait_batch_end() {
  for _ in $(seq $(($2 * 5))); do [[ -z "$(squeue -h -j "$1" 2>/dev/null)" ]] && return 0; sleep 0.2; done
  return 1
}

scenario_batch() {
  local store=$work/batch.sqlite job
  write_study "$work/batch.json" "batch" 40 61
  job=$(submit_batch)
  wait_done "$store" 30 300 || fail "batch: the study did not get going"
  snapshot "$store" "$work/batch.snapshot"
  scancel "$job"
  wait_batch_end "$job" 60 || fail "batch: job $job did not end"
  say "batch: cancelled the orchestrator's job $job with $(done_cases "$store") cases done," \
    "$(query "$store" "SELECT count(*) FROM cases WHERE status = 'running'") left running"
  job=$(submit_batch)
  wait_batch_end "$job" 600 || fail "batch: the second job $job did not finish within 10 minutes"
  check_store "batch" "$store" 120 "$work/batch.snapshot"
}

scenario_few_cases() {
  local store=$work/few.sqlite url pid
  "$aerobreak" serve --store "$store" --port 0 --port-file "$work/few.port" --idle-shutdown 5 --quiet \
    --launcher srun --ranks "$ranks" --silence-limit "$silence" --launcher-arg=--nodes=3 \
    --launcher-arg=--ntasks-per-node=$((ranks / 3)) >"$work/few.out" 2>&1 &
  pid=$!
  orchestrators+=("$pid")
  for _ in $(seq 100); do [[ -s "$work/few.port" ]] && break; sleep 0.1; done
  url=http://127.0.0.1:$(cat "$work/few.port")
  write_study "$work/few-1.json" "few cases" 1 71     # 3 cases for 6 ranks
  "$aerobreak" study submit "$work/few-1.json" --url "$url" >/dev/null || fail "few-cases: submit failed"
  wait_done "$store" 3 300 || fail "few-cases: the 3 cases did not finish"
  snapshot "$store" "$work/few.snapshot"
  write_study "$work/few-2.json" "few cases" 2 71     # the same 3 and 3 more: 3 remaining for 6 ranks
  "$aerobreak" study submit "$work/few-2.json" --url "$url" >/dev/null || fail "few-cases: submit failed"
  wait_done "$store" 6 300 || fail "few-cases: the second study did not finish"
  # An idle worker job stops, and its allocation goes back, while the service runs on.
  for _ in $(seq 300); do [[ -z "$(squeue -h)" ]] && break; sleep 0.1; done
  kill -0 "$pid" || fail "few-cases: aerobreak serve ended"
  "$aerobreak" study list --url "$url" >/dev/null || fail "few-cases: the service does not answer"
  check_store "few-cases" "$store" 6 "$work/few.snapshot"
  stop_process "$pid"
}

# The process of the rank that runs a case on HOST (its task has SLURM_PROCID = the rank).
busy_rank_process() {
  local store=$1 node=$2 rank p
  rank=$(query "$store" "SELECT substr(worker, instr(worker, ':') + 1) FROM cases
                         WHERE status = 'running' AND worker LIKE '$(node_name "$node"):%' LIMIT 1")
  [[ -n "$rank" ]] || return 0
  for p in $(node_pids "$node"); do
    [[ "$(cat "/proc/$p/comm" 2>/dev/null)" == aerobreak ]] &&
      tr '\0' '\n' <"/proc/$p/environ" 2>/dev/null | grep -qx "SLURM_PROCID=$rank" && { echo "$p"; return; }
  done
}

scenario_sigstop() {
  local store=$work/sigstop.sqlite pid victim=
  write_study "$work/sigstop.json" "sigstop" 40 81
  start_run "$work/sigstop.json" "$store" --launcher-arg=--nodes=3 --launcher-arg=--ntasks-per-node=$((ranks / 3))
  pid=$last_pid
  wait_done "$store" 20 300 || fail "sigstop: the study did not get going"
  for _ in $(seq 100); do
    victim=$(busy_rank_process "$store" 3)
    [[ -n "$victim" ]] && break
    sleep 0.2
  done
  [[ -n "$victim" ]] || fail "sigstop: no rank found running a case on abnode3"
  snapshot "$store" "$work/sigstop.snapshot"
  kill -STOP "$victim"
  say "sigstop: stopped rank process $victim on abnode3"
  wait_process "$pid" 600 || fail "sigstop: the study did not finish within 10 minutes"
  wait "$pid" || fail "sigstop: aerobreak run failed"
  check_store "sigstop" "$store" 120 "$work/sigstop.snapshot"
  (($(query "$store" "SELECT count(*) FROM attempts WHERE outcome = 'lost' AND error LIKE '%sent nothing%'") >= 1)) ||
    fail "sigstop: no case was given up as lost by its silent rank"
  kill -0 "$victim" 2>/dev/null && fail "sigstop: the stopped rank $victim is still there"
  true
}

cluster_create "$work/cluster"
say "Slurm $(sinfo -V | cut -d' ' -f2) up: $(sinfo -h -N -o '%N(%c CPUs)' | tr '\n' ' ')on bridge $cluster_bridge" \
  "($cluster_net.0/24); worker jobs of $ranks ranks"
for scenario in $scenarios; do
  say "== $scenario"
  start=$(date +%s)
  "scenario_${scenario//-/_}"
  say "$scenario: $(($(date +%s) - start)) s"
done
((failures == 0)) || { echo "run_slurm_cluster: $failures check(s) failed" >&2; exit 1; }
say "OK"
