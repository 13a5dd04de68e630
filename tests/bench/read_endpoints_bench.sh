#!/usr/bin/env bash
# Read endpoints at scale (docs/ORCHESTRATOR.md, "Performance"); prints figures, asserts nothing.
# Fills a store with one study of 100,000 finished cases (100 grid points x 1,000 replicates, results
# of about 1 KB each), written by direct SQL in one transaction, then serves it with
# `aerobreak serve` and measures each read endpoint with wrk on loopback (2 threads, 16
# connections): requests per second and the 99th percentile latency; for the lookup tables also
# the time of the first request (which builds the table) and the bytes sent, plain and gzip.
# Usage: tests/bench/read_endpoints_bench.sh [BUILD_DIR]   (installs wrk and sqlite3 if missing)
#   CASES=N (default 100000), GRID_POINTS=N (100), DURATION=seconds per endpoint (10), ROUNDS=N (1),
#   KEEP=1 keeps the filled store (its path is printed)
set -euo pipefail
build=${1:-build}
aerobreak=$(realpath "$build/aerobreak")
cases=${CASES:-100000}
grid_points=${GRID_POINTS:-100}
rounds=${ROUNDS:-1}
work=$(mktemp -d /tmp/aerobreak-read-bench.XXXXXX)
source "$(dirname "$0")/wrk_support.sh"
trap 'stop_bench_server; if [ "${KEEP:-0}" = 1 ]; then echo "kept $work/store.sqlite"; else rm -rf "$work"; fi' EXIT
install_bench_tools

store="$work/store.sqlite"
# The store's schema as this aerobreak makes it: serve once on an empty store.
start_bench_server "$aerobreak" "$store" "$work"
stop_bench_server

echo "== filling the store: $cases finished cases, $grid_points grid points"
start=$(date +%s.%N)
sqlite3 "$store" <<SQL
PRAGMA cache_size = -400000;
BEGIN;
INSERT INTO studies (id, hash, name, description, document, status, max_attempts, case_wall_time, created_at)
  VALUES (1, 'read-endpoints-bench', 'read endpoints bench', '', '{"name": "read endpoints bench"}', 'active', 3, 600,
          unixepoch() - 7200);
CREATE TEMP TABLE n AS
  WITH RECURSIVE k(k) AS (SELECT 0 UNION ALL SELECT k + 1 FROM k WHERE k + 1 < $cases)
  SELECT k, k % $grid_points AS g, k / $grid_points AS replicate,
         CASE abs(random()) % 10 WHEN 0 THEN 'bounce' WHEN 1 THEN 'undetermined'
           WHEN 2 THEN 'break-up' WHEN 3 THEN 'break-up' ELSE 'stick' END AS outcome
  FROM k;
INSERT INTO cases (id, hash, document, status, attempts, max_attempts, wall_time_limit, queued_at, started_at, finished_at)
  SELECT k + 1, printf('%064x', k), '{"bench": ' || k || '}', 'done', 1, 3, 600, unixepoch() - 7200,
         unixepoch() - 7000 + k * 0.05, unixepoch() - 7000 + k * 0.05 + 0.2
  FROM n;
INSERT INTO study_cases (study_id, case_id, position, grid_point, grid_key, replicate)
  SELECT 1, k + 1, k, json_object('impact_speed', 0.001 * (g + 1)), json_object('impact_speed', 0.001 * (g + 1)),
         replicate
  FROM n;
INSERT INTO results (case_id, attempt, outcome, restitution, largest_fragment_share, fragment_count,
                     retained_mass_fraction, impact_energy, wall_clock_seconds, data_file, document, committed_at)
  SELECT k + 1, 1, outcome, 0.1, 0.9, 2, 1.0, 0.001, 0.2, NULL,
         json_object('outcome', json_object('class', outcome), 'padding', hex(randomblob(450))),
         unixepoch() - 7000 + k * 0.05 + 0.2
  FROM n;
COMMIT;
SQL
end=$(date +%s.%N)
printf "filled in %.1f s (%s MB)\n" "$(echo "$end - $start" | bc -l)" "$(du -m "$store" | cut -f1)"

start_bench_server "$aerobreak" "$store" "$work"
url=$bench_url
etag=$(curl -s -D - -o /dev/null "$url/api/studies/1/outcomes" | awk -F': ' 'tolower($1) == "etag" {print $2}' | tr -d '\r')

# Warm-up, not reported: the server's threads open their pooled store connections, the outcome
# table is made once.
for path in /api/health /api/studies/1/progress /api/studies/1/outcomes; do
  wrk -t2 -c16 -d2s "$url$path" >/dev/null
done

echo "== read endpoints under wrk (2 threads, 16 connections, ${DURATION:-10} s each), $cases results"
for round in $(seq "$rounds"); do
  ((rounds > 1)) && echo "-- round $round"
  for path in /api/health /api/studies/1/progress /api/studies/1/outcomes; do wrk_figures "$path" "$url$path"; done
  if [ -n "$etag" ]; then
    wrk_figures "/api/studies/1/outcomes (If-None-Match)" "$url/api/studies/1/outcomes" -H "If-None-Match: $etag"
  fi
done

# The lookup tables (docs/EXPORT.md): the first request builds the table, later ones are served as
# kept (the service keeps a table per result-set version and request), gzip to a client that asks.
tables=("/api/studies/1/tables?format=csv" "/api/studies/1/tables?format=json" "/api/studies/1/tables?kind=sections&format=csv")
echo "== lookup tables: first request (builds the table) and bytes sent, plain and gzip"
for path in "${tables[@]}"; do
  first=$(curl -s -o /dev/null -w '%{time_total}' "$url$path")
  plain=$(curl -s -o /dev/null -w '%{size_download}' "$url$path")
  packed=$(curl -s -o /dev/null -w '%{size_download}' -H 'Accept-Encoding: gzip' "$url$path")
  printf "%-44s first %6.3f s   %9s bytes   gzip %9s bytes\n" "$path" "$first" "$plain" "$packed"
done
echo "== lookup tables under wrk (2 threads, 16 connections, ${DURATION:-10} s each)"
for path in "${tables[@]}"; do
  wrk_figures "$path" "$url$path"
  wrk_figures "$path (gzip)" "$url$path" -H "Accept-Encoding: gzip"
done
