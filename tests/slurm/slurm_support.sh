# Shared by the Slurm scripts of tests/slurm/ (sourced, not run): packages, munge, ending processes.
# Each script runs only daemons of its own (a munge key and socket, Slurm state, spool and logs in
# a temporary directory): nothing of the machine's own Slurm or munge configuration is used or
# changed.

# The prefix for commands that need root: nothing as root, sudo otherwise.
slurm_sudo=()
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "$(basename "$0"): needs root or sudo" >&2; exit 1; }
  slurm_sudo=(sudo)
fi

# Installs the Debian packages named that are missing.
install_missing_packages() {
  local missing=() p
  for p in "$@"; do
    [[ "$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)" == "install ok installed" ]] || missing+=("$p")
  done
  ((${#missing[@]})) || return 0
  echo "$(basename "$0"): installing ${missing[*]}"
  "${slurm_sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
    "${missing[@]}" >/dev/null
}

# Ends a process this script started: SIGTERM, SIGKILL after 10 s.
stop_process() {
  "${slurm_sudo[@]}" kill "$1" 2>/dev/null || return 0
  for _ in $(seq 100); do "${slurm_sudo[@]}" kill -0 "$1" 2>/dev/null || return 0; sleep 0.1; done
  "${slurm_sudo[@]}" kill -9 "$1" 2>/dev/null || true
}

# Starts munged with a key of its own and its socket at DIR/socket (DIR readable by the users that
# run srun); prints its pid.
start_munge() {
  local dir=$1
  mkdir -p "$dir"
  chmod 755 "$dir"
  "${slurm_sudo[@]}" dd if=/dev/urandom of="$dir/munge.key" bs=1024 count=1 status=none
  "${slurm_sudo[@]}" chmod 400 "$dir/munge.key"
  "${slurm_sudo[@]}" munged --force --socket="$dir/socket" --key-file="$dir/munge.key" \
    --pid-file="$dir/munged.pid" --log-file="$dir/munged.log" --seed-file="$dir/munged.seed" \
    </dev/null >"$dir/munged.out" 2>&1
  for _ in $(seq 50); do [[ -s "$dir/munged.pid" ]] && break; sleep 0.1; done
  cat "$dir/munged.pid"
}

# The lines of slurm.conf every test cluster shares: root runs the daemons, munge authenticates
# through the socket in MUNGE_DIR, and no cgroups, accounting or switch plugins are needed.
common_slurm_conf() {
  local munge_dir=$1
  cat <<CONF
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$munge_dir/socket
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SwitchType=switch/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
ReturnToService=2
CONF
}
