#!/usr/bin/env bash
# Run one aerobreak impact case in LAMMPS (serial, one OpenMP thread) and report its speed.
#
# usage: run_lammps_peer.sh CLUSTER_FILE [make_lammps_input.py options...]
#   e.g. run_lammps_peer.sh cluster.xyz --gamma-over-kn 0.001 --speed 0.1 --dt 0.02 --steps 20000
# env:   LMP (default lmp), LAMMPS_PEER_WORKDIR (default: a new /tmp/lammps_peer.XXXXXX)
# prints key = value lines; lammps_particle_steps_per_second = atoms * steps / LAMMPS Loop time
# (wall clock); lammps_cpu_use_percent < ~99 means the run shared its core with other work, and
# lammps_particle_steps_per_cpu_second = atoms * steps / (Loop time x %CPU) is then its own rate.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
if [[ $# -lt 1 ]]; then
  sed -n '2,10p' "${BASH_SOURCE[0]}" >&2
  exit 2
fi
cluster=$(realpath "$1")
shift
work=${LAMMPS_PEER_WORKDIR:-$(mktemp -d /tmp/lammps_peer.XXXXXX)}
mkdir -p "$work"
python3 "$here/make_lammps_input.py" "$cluster" --out "$work" "$@" >/dev/null
cd "$work"
OMP_NUM_THREADS=1 "${LMP:-lmp}" -in in.impact -log log.lammps -screen none -nocite
awk -v work="$work" '
  /^LAMMPS \(/ { version = $0; sub(/^LAMMPS \(/, "", version); sub(/\)$/, "", version) }
  /^timestep/ { dt = $2 }
  /^Loop time of/ { loop = $4; procs = $6; steps = $9; atoms = $12 }
  /% CPU use with/ { cpu = $1; sub(/%/, "", cpu) }
  /^Neighbor list builds/ { builds = $NF }
  /^Dangerous builds/ { dangerous = $NF }
  END {
    if (loop == "" || loop <= 0) { print "error: no Loop time in " work "/log.lammps" > "/dev/stderr"; exit 1 }
    printf "lammps_particle_steps_per_second = %.6g\n", atoms * steps / loop
    if (cpu > 0) printf "lammps_particle_steps_per_cpu_second = %.6g\n", atoms * steps / (loop * cpu / 100)
    printf "lammps_atoms = %d\n", atoms
    printf "lammps_steps = %d\n", steps
    printf "lammps_dt = %s\n", dt
    printf "lammps_loop_time_s = %s\n", loop
    printf "lammps_procs = %d\n", procs
    printf "lammps_cpu_use_percent = %s\n", cpu
    printf "lammps_neighbor_builds = %s\n", builds
    printf "lammps_dangerous_builds = %s\n", dangerous
    printf "lammps_version = %s\n", version
    printf "lammps_workdir = %s\n", work
  }' log.lammps
