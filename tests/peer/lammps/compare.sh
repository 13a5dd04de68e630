#!/usr/bin/env bash
# Speed of aerobreak and LAMMPS side by side on the same clusters, model and time step.
#
# usage: compare.sh [SIZES] [STEPS]       e.g. compare.sh 1000,4000 20000 (the defaults)
# env:   AEROBREAK (default build/aerobreak)
# Both codes run the full model (JKR, visco-elastic damping, Mindlin, rolling, twisting) with
# LAMMPS's break rule (F = -F_c) and a wall without adhesion; see README.md for the mapping.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
sizes=${1:-1000,4000}
steps=${2:-20000}
aerobreak=${AEROBREAK:-$here/../../../build/aerobreak}
work=$(mktemp -d /tmp/aerobreak_compare.XXXXXX)

"$aerobreak" bench --sizes "$sizes" --steps "$steps" --separation force --no-wall-adhesion --export "$work" \
  | tee "$work/aerobreak.txt"
printf '\n%9s %22s %22s %8s\n' N "aerobreak p-steps/s" "LAMMPS p-steps/s" ratio
for n in ${sizes//,/ }; do
  ours=$(awk -v n="$n" '$1 == n { print $6 }' "$work/aerobreak.txt")
  read -r dt gamma mu xi damping speed < <(python3 -c "
import json; p = json.load(open('$work/bench_N$n.json'))
print(p['time_step'], p['gamma_over_kn'], p['friction'], p['critical_rolling'], p['dissipative_time'], p['speed'])")
  theirs=$(LAMMPS_PEER_WORKDIR="$work/lammps_N$n" "$here/run_lammps_peer.sh" "$work/bench_N$n.xyz" \
             --gamma-over-kn "$gamma" --mu "$mu" --xi-crit "$xi" --damping-A "$damping" --speed "$speed" \
             --dt "$dt" --steps "$steps" --gap 0.01 --wall-adhesion off --separation force \
           | awk '/^lammps_particle_steps_per_second/ { print $3 }')
  python3 -c "print('%9d %22.4g %22.4g %8.2f' % ($n, $ours, $theirs, $ours / $theirs))"
done
echo "(work files: $work)"
