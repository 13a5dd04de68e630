#!/usr/bin/env bash
# How much does v50 of break-up move with the cases left undetermined at the time limit?
#
#   studies/analysis/undetermined_sensitivity.sh [--reruns DIR] STORE...
#
# The adaptive search and the correlations leave undetermined cases out of their fits (they never
# guess). Left out is unbiased only if a case's chance of ending undetermined does not depend on its
# class. Per store and wall this fits the logistic regression of break-up in ln v four ways:
# undetermined cases left out (the search's way); counted by their state at the time limit (mass
# off the wall and, on a wall without adhesion, no piece holding the bounce share 0.9: a break-up);
# all counted as break-ups; none counted as break-ups. The last two are bounds no physics suggests,
# the second a reading of states that may still change (docs/IMPACT.md section 5).
# --reruns DIR: the results of rerun_undetermined.sh (DIR/case<ID>.result.json, the same cases run
# on with a longer limit; each must be its store case's own, the limit aside) replace the stored
# undetermined ones, two ways more: those still undetermined left out, or counted by their state
# at the new limit. Each way by maximum likelihood (R's glm) and by Firth's penalised likelihood
# (the search's fit), v50 with its 95 % profile interval (undetermined_sensitivity.R).
# Needs sqlite3, python3 and R (Debian: r-base-core).
set -euo pipefail
reruns=
if [ "${1:-}" = --reruns ]; then
  [ $# -ge 2 ] && [ -d "$2" ] || { echo "undetermined_sensitivity.sh: --reruns needs a folder" >&2; exit 2; }
  reruns=$2
  shift 2
fi
[ $# -ge 1 ] || { sed -n 2,18p "$0"; exit 2; }
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for store in "$@"; do
  sqlite3 -csv "$store" "SELECT c.id, c.primaries, json_extract(c.document, '\$.wall.adhesive'),
      json_extract(c.document, '\$.impact.speed'), r.outcome, r.largest_fragment_share,
      r.retained_mass_fraction FROM results r JOIN cases c ON c.id = r.case_id" > "$work/cases.csv"
  if [ -z "$reruns" ]; then
    Rscript --vanilla "$here/undetermined_sensitivity.R" "$work/cases.csv"
    continue
  fi
  python3 - "$store" "$reruns" > "$work/reruns.csv" <<'PY'
# One CSV row per rerun result of this store's undetermined cases: id, outcome, largest fragment
# share, retained mass fraction, simulated time (s). A result whose case differs from the stored
# one in anything but the time limit is refused.
import csv, glob, json, os, re, sqlite3, sys
store, folder = sys.argv[1], sys.argv[2]
db = sqlite3.connect(store)
out = csv.writer(sys.stdout)
for path in sorted(glob.glob(os.path.join(folder, "case*.result.json"))):
    case_id = int(re.fullmatch(r"case(\d+)\.result\.json", os.path.basename(path)).group(1))
    row = db.execute("SELECT document FROM results WHERE case_id = ? AND outcome = 'undetermined'",
                     (case_id,)).fetchone()
    if row is None:
        continue
    stored, rerun = json.loads(row[0])["case"], json.load(open(path))
    for case in (stored, rerun["case"]):
        case["run"].pop("time_limit_s", None)
        case["run"].pop("time_limit", None)
    if stored != rerun["case"]:
        sys.exit(f"{path}: its case is not case {case_id} of {store} (beyond the time limit)")
    o = rerun["outcome"]
    out.writerow([case_id, o["class"], o["largest_fragment_share"], o["retained_mass_fraction"],
                  rerun["run"]["simulated_time_s"]])
PY
  Rscript --vanilla "$here/undetermined_sensitivity.R" "$work/cases.csv" "$work/reruns.csv"
done
