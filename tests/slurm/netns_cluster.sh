# A Slurm cluster of several nodes on this one machine, for tests/slurm/run_slurm_cluster.sh
# (sourced, not run; needs root). Each node is a slurmd in network, UTS and mount namespaces of its
# own: its own host name (abnode1, ...), its own address on a private bridge, its own /tmp and
# /dev/shm (Slurm's PMIx plugin and Open MPI keep per-node files there). The controller
# (slurmctld, host name abctl) has a namespace of its own too. This machine itself is the login
# node: the bridge's first address, where srun, sbatch and aerobreak run. The bridge connects to
# nothing else, so that all the cluster's traffic stays inside this machine; one munged serves all
# (its socket is a file, which every namespace reaches). Everything lives under $cluster_work and
# is removed by cluster_destroy, which also runs when anything fails.
#
# After cluster_create: SLURM_CONF is exported; node_kill I, node_start I, node_cut I and
# node_join I make node I fail, come back, lose its link and get it back; node_pids I lists the
# processes in its namespace.

cluster_nodes=3
cluster_cpus=6           # per node, as Slurm counts them (more than the machine has: ranks mostly wait)
cluster_tag=ab$(( $$ % 100000 ))  # names of namespaces and links, unique on this machine
cluster_bridge=${cluster_tag}br
cluster_net=
cluster_work=
cluster_munged=

namespace_of() { echo "${cluster_tag}-$1"; }      # ctl, n1, n2, ...
host_link_of() { echo "${cluster_tag}$1h"; }      # the bridge's end of a namespace's link
node_name() { echo "abnode$1"; }
node_address() { echo "$cluster_net.$((10 + $1))"; }

# A 10.231.X.0/24 that no interface or route of this machine uses yet.
free_subnet() {
  local x used
  used=$(ip -4 -o addr show; ip -4 route show)
  for x in $(shuf -i 1-254); do
    grep -q "10\.231\.$x\." <<<"$used" || { echo "10.231.$x"; return; }
  done
  echo "netns_cluster: no free 10.231.X.0/24 subnet" >&2
  return 1
}

# A namespace NAME with a link to the bridge at ADDRESS.
make_namespace() {
  local name ns link
  name=$1
  ns=$(namespace_of "$name")
  link=$(host_link_of "$name")
  ip netns add "$ns"
  ip link add "$link" type veth peer name eth0 netns "$ns"
  ip link set "$link" master "$cluster_bridge" up
  ip netns exec "$ns" ip addr add "$2/24" dev eth0
  ip netns exec "$ns" ip link set eth0 up
  ip netns exec "$ns" ip link set lo up
}

# Runs COMMAND... in namespace NAME as host HOST, in the background, with the cluster's hosts file
# and a /tmp and /dev/shm of the host's own (nsenter keeps this machine's /sys and its cgroups,
# which slurmd needs; ip netns exec would mount a fresh /sys). Prints the pid.
start_in_namespace() {
  local name=$1 host=$2 root=$cluster_work/fs/$2
  shift 2
  mkdir -p "$root/tmp" "$root/shm"
  chmod 1777 "$root/tmp" "$root/shm"
  nsenter --net="/run/netns/$(namespace_of "$name")" unshare --uts --mount --propagation private \
    sh -c 'mount --bind "$1" /etc/hosts && mount --bind "$2/tmp" /tmp && mount --bind "$2/shm" /dev/shm &&
           hostname "$3" && shift 3 && exec "$@"' \
    sh "$cluster_work/hosts" "$root" "$host" "$@" >>"$cluster_work/log/$host.out" 2>&1 &
  echo $!
  disown $!  # a node killed on purpose is no news for this shell
}

write_slurm_conf() {
  local i
  {
    echo "ClusterName=aerobreak-cluster"
    echo "SlurmctldHost=abctl($cluster_net.2)"
    echo "StateSaveLocation=$cluster_work/state"
    echo "SlurmdSpoolDir=$cluster_work/spool/%n"
    echo "SlurmctldPidFile=$cluster_work/slurmctld.pid"
    echo "SlurmdPidFile=$cluster_work/spool/%n/slurmd.pid"
    echo "SlurmctldLogFile=$cluster_work/log/slurmctld.log"
    echo "SlurmdLogFile=$cluster_work/log/slurmd-%n.log"
    common_slurm_conf "$cluster_work/munge"
    # The nodes declare more CPUs than the machine has; take them as configured.
    echo "SlurmdParameters=config_overrides"
    # A node that stops answering is down after 10 s (default 300 s), and a job past its time
    # limit gets SIGTERM, then SIGKILL 5 s later (default 30 s): the failures come within minutes.
    echo "SlurmdTimeout=10"
    echo "KillWait=5"
    for ((i = 1; i <= cluster_nodes; ++i)); do
      echo "NodeName=$(node_name "$i") NodeAddr=$(node_address "$i") CPUs=$cluster_cpus State=UNKNOWN"
    done
    echo "PartitionName=aerobreak Nodes=abnode[1-$cluster_nodes] Default=YES MaxTime=INFINITE State=UP"
  } >"$cluster_work/slurm.conf"
}

write_hosts() {
  local i
  {
    echo "127.0.0.1 localhost"
    echo "$cluster_net.1 ablogin"
    echo "$cluster_net.2 abctl"
    for ((i = 1; i <= cluster_nodes; ++i)); do echo "$(node_address "$i") $(node_name "$i")"; done
  } >"$cluster_work/hosts"
}

node_pids() { ip netns pids "$(namespace_of "n$1")" 2>/dev/null || true; }

node_start() {
  mkdir -p "$cluster_work/spool/$(node_name "$1")"
  start_in_namespace "n$1" "$(node_name "$1")" slurmd -D -N "$(node_name "$1")" >/dev/null
}

# The node fails: its slurmd, its step daemons and its tasks are killed at once.
node_kill() {
  local pids
  pids=$(node_pids "$1")
  [[ -z "$pids" ]] || kill -9 $pids 2>/dev/null || true
}

node_cut() { ip link set "$(host_link_of "n$1")" down; }
node_join() { ip link set "$(host_link_of "n$1")" up; }

node_state() { sinfo -h -N -n "$(node_name "$1")" -o %t 2>/dev/null || true; }

# Waits up to SECONDS for every node to be idle; false if one is not.
wait_nodes_idle() {
  local states
  for _ in $(seq $(($1 * 10))); do
    states=$(sinfo -h -N -o %t 2>/dev/null | sort -u | tr '\n' ' ')
    [[ "$states" == "idle " ]] && return 0
    sleep 0.1
  done
  echo "netns_cluster: nodes not idle after $1 s: $states" >&2
  return 1
}

cluster_create() {
  local i
  cluster_work=$1
  mkdir -p "$cluster_work/state" "$cluster_work/spool" "$cluster_work/log" "$cluster_work/fs"
  chmod 755 "$cluster_work"
  cluster_net=$(free_subnet)
  ip link add "$cluster_bridge" type bridge
  ip addr add "$cluster_net.1/24" dev "$cluster_bridge"
  ip link set "$cluster_bridge" up
  cluster_munged=$(start_munge "$cluster_work/munge")
  write_hosts
  write_slurm_conf
  export SLURM_CONF=$cluster_work/slurm.conf
  make_namespace ctl "$cluster_net.2"
  for ((i = 1; i <= cluster_nodes; ++i)); do make_namespace "n$i" "$(node_address "$i")"; done
  start_in_namespace ctl abctl slurmctld -D -i >/dev/null
  for ((i = 1; i <= cluster_nodes; ++i)); do node_start "$i"; done
  wait_nodes_idle 60
}

# The cluster's namespaces that exist, and the processes in them.
cluster_namespaces() { ip netns list 2>/dev/null | awk -v tag="$cluster_tag-" 'index($1, tag) == 1 {print $1}'; }
cluster_pids() {
  local name
  for name in $(cluster_namespaces); do ip netns pids "$name" 2>/dev/null || true; done
}

# Ends every process in the cluster's namespaces (daemons, steps, tasks, batch scripts), the
# munged, the namespaces and the bridge. Safe to call whatever cluster_create got to.
cluster_destroy() {
  local name pids
  if [[ -n "$cluster_work" && -f "$cluster_work/slurm.conf" ]]; then
    timeout 10 scancel --quiet --partition=aerobreak 2>/dev/null || true
  fi
  pids=$(cluster_pids)
  [[ -z "$pids" ]] || kill $pids 2>/dev/null || true
  for _ in $(seq 50); do
    pids=$(cluster_pids)
    [[ -z "$pids" ]] && break
    sleep 0.1
  done
  [[ -z "$pids" ]] || kill -9 $pids 2>/dev/null || true
  for name in $(cluster_namespaces); do ip netns del "$name" 2>/dev/null || true; done
  [[ -z "$cluster_munged" ]] || stop_process "$cluster_munged"
  ip link del "$cluster_bridge" 2>/dev/null || true
}
