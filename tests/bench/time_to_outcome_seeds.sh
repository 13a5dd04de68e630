#!/usr/bin/env bash
# Does a cut of the time to outcome change the outcome? Runs an impact case on a set of seeds as it
# is (base) and with cuts of its settle window and time step, one run at a time, and prints per seed
# and run the outcome class, retained mass fraction, normal restitution, largest fragment share,
# fragments, steps, simulated time, quiet window, CPU seconds of the stepping and final contacts
# (docs/PERFORMANCE.md, "Time to outcome").
#
# usage: time_to_outcome_seeds.sh CASE PRIMARIES SEEDS [OUTDIR]
#   e.g. time_to_outcome_seeds.sh studies/figure4_impact.case.json 1024 "1 2 3 4 5 6 7 8"
# Seed s: the generator's seed plus s and orientation seed s. The runs: base (the case), window/2
# and window/4 (settle.quiet_window half and a quarter of the automatic window of the base run),
# dt*2 (steps_per_period 25: twice the automatic step where the contact period sets it).
# env: AEROBREAK (default build/aerobreak)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
if [[ $# -lt 3 ]]; then
  sed -n '2,13p' "${BASH_SOURCE[0]}" >&2
  exit 2
fi
case_file=$1 primaries=$2 seeds=$3
out=${4:-$(mktemp -d /tmp/time_to_outcome.XXXXXX)}
aerobreak=${AEROBREAK:-$here/../../build/aerobreak}
mkdir -p "$out"

# write_case SEED NAME PYTHON: the case for SEED with PYTHON applied to it (c: the case, base: the
# base run's result or None), as OUT/NAME_sSEED.case.json
write_case() {
  python3 - "$case_file" "$primaries" "$1" "$out/base_s$1.result.json" "$3" > "$out/$2_s$1.case.json" <<'PY'
import json, os, sys
c = json.load(open(sys.argv[1]))
seed = int(sys.argv[3])
c["cluster"]["generator"]["primaries"] = int(sys.argv[2])
c["cluster"]["generator"]["seed"] += seed
c["impact"]["orientation_seed"] = seed
c["run"].pop("snapshot_interval", None)
base = json.load(open(sys.argv[4])) if os.path.exists(sys.argv[4]) else None
exec(sys.argv[5])
json.dump(c, sys.stdout, indent=1)
PY
}

run_case() { "$aerobreak" impact "$out/$2_s$1.case.json" -q -o "$out/$2_s$1.result.json"; }

window='c["run"].setdefault("settle", {})["quiet_window"] = base["run"]["quiet_window"] *'
for s in $seeds; do
  write_case "$s" base "pass" && run_case "$s" base
  write_case "$s" window2 "$window 0.5" && run_case "$s" window2
  write_case "$s" window4 "$window 0.25" && run_case "$s" window4
  write_case "$s" dt2 'c["run"]["steps_per_period"] = 25' && run_case "$s" dt2
done

python3 - "$out" $seeds <<'PY'
import json, sys
out, seeds = sys.argv[1], sys.argv[2:]
print("%5s %8s %10s %9s %8s %8s %5s %9s %10s %9s %8s %8s" % ("seed", "run", "class", "retained", "e_n", "largest",
      "frags", "steps", "time[tau]", "window", "CPU s", "contacts"))
for s in seeds:
    for run in ("base", "window2", "window4", "dt2"):
        r = json.load(open("%s/%s_s%s.result.json" % (out, run, s)))
        o = r["outcome"]
        e_n = o["restitution"]["normal"]
        print("%5s %8s %10s %9.4f %8s %8.4f %5d %9d %10.1f %9.1f %8.1f %8d" % (
            s, run, o["class"], o["retained_mass_fraction"], "-" if e_n is None else "%.4f" % e_n,
            o["largest_fragment_share"], o["fragment_count"], r["run"]["steps"], r["run"]["simulated_time"],
            r["run"]["quiet_window"], r["run"]["cpu_seconds"], r["contacts"]["final"]))
PY
echo "(work files: $out)"
