#!/usr/bin/env bash
# Speed of aerobreak and LAMMPS side by side on the same clusters, model and time step, through
# `aerobreak bench` (the stepping alone) and through `aerobreak impact` (a whole impact case run
# as a user runs it: the cluster read from the file bench exported, relaxed, turned, placed, with
# the settle check; its result's particle-steps/s count the stepping of the run loop). Every rate
# is particle-steps per CPU second of the stepping (aerobreak: the stepping thread's CPU time;
# LAMMPS: Loop time x its %CPU), so that runs on a machine shared with other work compare; the
# wall-clock rates are in the work files.
#
# usage: compare.sh [SIZES] [STEPS] [BENCH_OPTIONS]   e.g. compare.sh 1000,4000 20000 (the defaults)
#        compare.sh 1024 20000 "--damping 0 --no-rolling --no-twisting --time-step 0.0158"
# env:   AEROBREAK (default build/aerobreak)
# By default both codes run the full model (JKR, visco-elastic damping, Mindlin, rolling,
# twisting); BENCH_OPTIONS change it, and the LAMMPS and impact runs follow. Always LAMMPS's
# break rule (F = -F_c) and a wall without adhesion; see README.md for the mapping.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
sizes=${1:-1000,4000}
steps=${2:-20000}
read -r -a extra <<< "${3:-}"
aerobreak=${AEROBREAK:-$here/../../../build/aerobreak}
work=$(mktemp -d /tmp/aerobreak_compare.XXXXXX)

"$aerobreak" bench --sizes "$sizes" --steps "$steps" --separation force --no-wall-adhesion --export "$work" \
  "${extra[@]}" | tee "$work/aerobreak.txt"
printf '\n%9s %18s %18s %18s %10s %10s %14s\n' N "bench p-s/CPU s" "impact p-s/CPU s" "LAMMPS p-s/CPU s" \
  "bench/L" "impact/L" "impact/bench"
for n in ${sizes//,/ }; do
  bench=$(awk -v n="$n" '$1 == n { print $12 }' "$work/aerobreak.txt")
  python3 "$here/make_impact_case.py" "$work/bench_N$n.json" "$work/bench_N$n.xyz" > "$work/impact_N$n.case.json"
  "$aerobreak" impact "$work/impact_N$n.case.json" -q -o "$work/impact_N$n.result.json"
  impact=$(python3 -c "import json; print(json.load(open('$work/impact_N$n.result.json'))['run']['particle_steps_per_cpu_second'])")
  read -r dt gamma mu xi damping speed rolling twisting < <(python3 -c "
import json; p = json.load(open('$work/bench_N$n.json'))
on = lambda key: 'on' if p.get(key, True) else 'off'
print(p['time_step'], p['gamma_over_kn'], p['friction'], p['critical_rolling'], p['dissipative_time'], p['speed'],
      on('rolling'), on('twisting'))")
  theirs=$(LAMMPS_PEER_WORKDIR="$work/lammps_N$n" "$here/run_lammps_peer.sh" "$work/bench_N$n.xyz" \
             --gamma-over-kn "$gamma" --mu "$mu" --xi-crit "$xi" --damping-A "$damping" --speed "$speed" \
             --dt "$dt" --steps "$steps" --gap 0.01 --wall-adhesion off --separation force \
             --rolling "$rolling" --twisting "$twisting" \
           | tee "$work/lammps_N$n.txt" | awk '/^lammps_particle_steps_per_cpu_second/ { print $3 }')
  python3 -c "print('%9d %18.4g %18.4g %18.4g %10.2f %10.2f %14.2f' % ($n, $bench, $impact, $theirs, $bench / $theirs,
               $impact / $theirs, $impact / $bench))"
done
echo "(work files: $work)"
