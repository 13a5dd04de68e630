#!/usr/bin/env bash
# Time to outcome of break-up runs, side by side: the step chosen from the speeds of the moment and
# the verdict as soon as the outcome is fixed (this aerobreak) against the code before them (one
# automatic step per run, from the impact speed, and the quiet and outcome-fixed rules of then).
# Relaxed ballistic clusters of 64 primaries, gamma/k_n = 0.001, the former default study's model
# (JKR, visco-elastic damping A = 0.05 tau, mu = 0.3, rolling resistance xi_crit = 0.02 d), head-on
# at a wall without adhesion; replicate r is generator seed r and orientation seed r, the same cases
# for both codes, run one after the other. Per speed it prints the CPU seconds of the stepping
# (/run/cpu_seconds) and of the whole processes, the steps, the outcome classes and fragment counts
# of both, the ratio of the CPU times, and R's Fisher exact test of the class distributions and
# Wilcoxon-Mann-Whitney test of the fragment counts (p > 0.05: no difference shown)
# (docs/PERFORMANCE.md, "Time to outcome of break-ups").
#
# usage: breakup_speed_bench.sh [REPLICATES] [SPEEDS] [OUTDIR]
#   defaults: 32 replicates, speeds "0.05 0.1 0.2" d/tau (near v50: "0.015 0.02 0.025")
# env: AEROBREAK (default build/aerobreak); AEROBREAK_BASE, the code before (an aerobreak built from
#   a commit before the adaptive step, e.g. 34e0c11); without it the baseline is this aerobreak with the
#   JSON merge patch BASE_PATCH applied to its cases, by default '{"run":{"adaptive_time_step":false}}'
#   (one step per run, the new verdict rules); '{"run":{"settle":{"stop_when_outcome_fixed":false}}}' gives the
#   new step with the quiet rule alone.
# Needs Rscript (Debian r-base-core; installed if missing, root or sudo).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
replicates=${1:-32}
speeds=${2:-"0.05 0.1 0.2"}
out=${3:-$(mktemp -d /tmp/breakup_speed.XXXXXX)}
new=${AEROBREAK:-$here/../../build/aerobreak}
base=${AEROBREAK_BASE:-}
base_patch=${BASE_PATCH:-'{"run":{"adaptive_time_step":false}}'}
mkdir -p "$out"
if ! command -v Rscript > /dev/null; then
  sudo=""; [[ $(id -u) -ne 0 ]] && sudo=sudo
  $sudo apt-get install -y r-base-core > /dev/null
fi

# write_case SPEED SEED PATCH: the case on stdout, with the JSON merge patch PATCH ("" for none) applied.
write_case() {
  python3 - "$1" "$2" "$3" <<'PY'
import json, sys
speed, seed, patch = float(sys.argv[1]), int(sys.argv[2]), sys.argv[3]


def merge(target, change):
    for key, value in change.items():
        if isinstance(value, dict) and isinstance(target.get(key), dict):
            merge(target[key], value)
        elif value is None:
            target.pop(key, None)
        else:
            target[key] = value


c = {"units": "reduced",
     "cluster": {"generator": {"method": "ballistic", "primaries": 64, "seed": seed}, "relax": True},
     "material": {"gamma_over_kn": 0.001, "poisson_ratio": 0.3},
     "model": {"normal": "jkr", "separation": "displacement",
               "damping": {"law": "viscoelastic", "dissipative_time": 0.05}, "tangential": True, "friction": 0.3,
               "rolling": {"enabled": True, "critical_displacement": 0.02}, "twisting": False},
     "impact": {"speed": speed, "angle": 0, "gap": 0.01, "orientation_seed": seed},
     "wall": {"adhesive": False},
     "run": {"time_limit": 50000}}
if patch:
    merge(c, json.loads(patch))
json.dump(c, sys.stdout)
PY
}

# run_case BINARY CASE RESULT: runs it, appending the process's CPU seconds (user + system) to RESULT.cpu
run_case() {
  /usr/bin/time -f "%U %S" -o "$3.cpu" nice -n 10 "$1" impact "$2" -q -o "$3"
}

for v in $speeds; do
  for r in $(seq 1 "$replicates"); do
    if [[ -n $base ]]; then
      write_case "$v" "$r" "" > "$out/base_v${v}_r$r.case.json"
      run_case "$base" "$out/base_v${v}_r$r.case.json" "$out/base_v${v}_r$r.json"
    else
      write_case "$v" "$r" "$base_patch" > "$out/base_v${v}_r$r.case.json"
      run_case "$new" "$out/base_v${v}_r$r.case.json" "$out/base_v${v}_r$r.json"
    fi
    write_case "$v" "$r" "" > "$out/new_v${v}_r$r.case.json"
    run_case "$new" "$out/new_v${v}_r$r.case.json" "$out/new_v${v}_r$r.json"
  done
done

python3 - "$out" "$replicates" $speeds > "$out/table.tsv" <<'PY'
import json, sys
out, replicates, speeds = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
print("speed\tcode\treplicate\tclass\tfragments\tsettled_by\tsteps\tstepping_cpu\tprocess_cpu\tsimulated_time")
for v in speeds:
    for code in ("base", "new"):
        for r in range(1, replicates + 1):
            name = "%s/%s_v%s_r%d.json" % (out, code, v, r)
            d = json.load(open(name))
            user, system = map(float, open(name + ".cpu").read().split()[-2:])
            o, run = d["outcome"], d["run"]
            print("%s\t%s\t%d\t%s\t%d\t%s\t%d\t%.4f\t%.4f\t%.2f" % (v, code, r, o["class"], o["fragment_count"],
                  run.get("settled_by") or "-", run["steps"], run["cpu_seconds"], user + system, run["simulated_time"]))
PY

Rscript --vanilla - "$out/table.tsv" <<'R'
args <- commandArgs(trailingOnly = TRUE)
t <- read.delim(args[1], stringsAsFactors = FALSE)
cat(sprintf("%6s %5s %9s %9s %9s %9s %9s %9s %7s %7s %6s %6s %-22s %-22s\n", "speed", "runs", "base CPU", "new CPU",
            "base proc", "new proc", "base step", "new step", "ratio", "proc r", "Fisher", "MWU", "base classes",
            "new classes"))
for (v in unique(t$speed)) {
  b <- t[t$speed == v & t$code == "base", ]; n <- t[t$speed == v & t$code == "new", ]
  classes <- c("stick", "bounce", "break-up", "undetermined")
  tab <- rbind(table(factor(b$class, classes)), table(factor(n$class, classes)))
  tab <- tab[, colSums(tab) > 0, drop = FALSE]
  fisher <- if (ncol(tab) > 1) fisher.test(tab)$p.value else 1
  mwu <- suppressWarnings(wilcox.test(b$fragments, n$fragments, exact = FALSE)$p.value)
  describe <- function(x) paste(sprintf("%s %d", names(x), x), collapse = ", ")
  cat(sprintf("%6.3f %5d %9.2f %9.2f %9.2f %9.2f %9.3g %9.3g %7.2f %7.2f %6.3f %6.3f %-22s %-22s\n", v, nrow(n),
              sum(b$stepping_cpu), sum(n$stepping_cpu), sum(b$process_cpu), sum(n$process_cpu), sum(b$steps),
              sum(n$steps), sum(b$stepping_cpu) / sum(n$stepping_cpu), sum(b$process_cpu) / sum(n$process_cpu),
              fisher, mwu, describe(table(b$class)), describe(table(n$class))))
  cat(sprintf("       fragments: base median %g (mean %.1f), new median %g (mean %.1f); new settled by %s\n",
              median(b$fragments), mean(b$fragments), median(n$fragments), mean(n$fragments),
              describe(table(n$settled_by))))
}
b <- t[t$code == "base", ]; n <- t[t$code == "new", ]
cat(sprintf(paste("all speeds: stepping CPU s base %.2f, new %.2f (%.2fx less);",
                  "process CPU s base %.2f, new %.2f (%.2fx less)\n"),
            sum(b$stepping_cpu), sum(n$stepping_cpu), sum(b$stepping_cpu) / sum(n$stepping_cpu), sum(b$process_cpu),
            sum(n$process_cpu), sum(b$process_cpu) / sum(n$process_cpu)))
R
echo "results in $out"
