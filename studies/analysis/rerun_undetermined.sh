#!/usr/bin/env bash
# Run a store's undetermined cases again with a longer time limit, one at a time.
#
#   studies/analysis/rerun_undetermined.sh STORE LIMIT_S OUTDIR [WHERE]
#
# STORE    a study store (SQLite; only read).
# LIMIT_S  the new time limit in seconds of physical time (/run/time_limit_s; the study must be in
#          physical units, "units": "physical", as the size ladder is). It replaces the case's
#          /run/time_limit_s (or /run/time_limit in tau); everything else of the case is as stored,
#          its cluster and orientation seeds included, so the engine of the same stepping follows the
#          same trajectory and goes on past the old limit (docs/IMPACT.md sections 4-5: the verdict is
#          judged along the way, not at the limit).
# OUTDIR   gets case<ID>.case.json and, once its run has ended, case<ID>.result.json (ID: the store's
#          case id). A case whose result is already there is skipped, so an interrupted run resumes.
# WHERE    optional SQL condition on the case (table alias c), e.g. the wall without adhesion at
#          20-44 m/s:  "json_extract(c.document, '$.wall.adhesive') = 0 AND
#                        json_extract(c.document, '$.impact.speed') BETWEEN 20 AND 44"
#
# Runs `aerobreak impact CASE -q -o RESULT` ($AEROBREAK, default build/aerobreak under the repository)
# and prints per case its id and rerun_summary.py's line: wall, speed, outcome, simulated time (s),
# CPU seconds and, while still undetermined, when its approaching pieces pass closest and
# /run/unsettled_reason. undetermined_sensitivity.sh --reruns OUTDIR refits v50 with
# these outcomes in place of the stored ones. Needs sqlite3 and python3.
set -euo pipefail
[ $# -ge 3 ] && [ $# -le 4 ] || { sed -n 2,23p "$0"; exit 2; }
store=$1 limit=$2 outdir=$3 where=${4:-1}
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
aerobreak=${AEROBREAK:-$root/build/aerobreak}
[ -r "$store" ] || { echo "rerun_undetermined.sh: cannot read $store" >&2; exit 2; }
python3 -c 'import sys; x = float(sys.argv[1]); assert 0 < x < 1' "$limit" 2>/dev/null ||
  { echo "rerun_undetermined.sh: LIMIT_S must be a time in seconds, 0 < LIMIT_S < 1 (got $limit)" >&2; exit 2; }
mkdir -p "$outdir"

# One line per case: id, then its document with the new limit (the store is only read; opened
# read-only, SQLite would leave the -wal and -shm files of a WAL store behind).
cases=$(sqlite3 -batch -separator $'\t' "$store" "
  SELECT c.id, json_remove(json_set(c.document, '\$.run.time_limit_s', $limit), '\$.run.time_limit')
  FROM cases c JOIN results r ON r.case_id = c.id
  WHERE r.outcome = 'undetermined' AND json_extract(c.document, '\$.units') = 'physical' AND ($where)
  ORDER BY json_extract(c.document, '\$.wall.adhesive'), json_extract(c.document, '\$.impact.speed'), c.id")
[ -n "$cases" ] || { echo "rerun_undetermined.sh: no undetermined case in physical units matches" >&2; exit 1; }
echo "$(grep -c . <<<"$cases") undetermined cases, time limit $limit s, results in $outdir"

summary() { python3 "$root/studies/analysis/rerun_summary.py" "$1"; }

# aerobreak writes its result under the name only once complete, so a result file is a finished
# run; a stopped script stops its running case too.
running=
trap '[ -z "$running" ] || kill "$running" 2>/dev/null' EXIT
trap 'exit 143' TERM INT
failed=0
while IFS=$'\t' read -r id document; do
  result=$outdir/case$id.result.json
  if [ -s "$result" ]; then
    echo "id $id: done before: $(summary "$result")"
    continue
  fi
  printf '%s\n' "$document" >"$outdir/case$id.case.json"
  "$aerobreak" impact "$outdir/case$id.case.json" -q -o "$result" 2>"$outdir/case$id.err" &
  running=$!
  if wait "$running"; then
    echo "id $id: $(summary "$result")"
  else
    echo "id $id: aerobreak impact failed (exit $?), see $outdir/case$id.err" >&2
    failed=$((failed + 1))
  fi
  running=
done <<<"$cases"
[ $failed -eq 0 ] || { echo "rerun_undetermined.sh: $failed cases failed" >&2; exit 1; }
