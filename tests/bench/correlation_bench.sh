#!/usr/bin/env bash
# Correlation benchmark (docs/PERFORMANCE.md, "Correlations"); prints figures, asserts nothing.
#   1. build/tests/correlation_bench: fitting a synthetic study of RESULTS (default 100,000) results,
#      then the same study written to a store: the first request (read, hash, fit, store) and a
#      second one (from the store);
#   2. GET /api/studies/1/correlations on that store under wrk (loopback, 2 threads, 16
#      connections, DURATION s per round, ROUNDS rounds after a warm-up): requests per second and
#      the 99th percentile latency, served from the store; GET /api/health beside it in each round,
#      the service's cheapest answer, to tell the endpoint's cost from the machine's load; and the
#      same request with If-None-Match naming the current ETag (304, no body).
# Usage: tests/bench/correlation_bench.sh [BUILD_DIR] [RESULTS]   (installs wrk and sqlite3 if missing)
#   DURATION=seconds per round (10), ROUNDS=N (3)
set -euo pipefail
build=${1:-build}
results=${2:-100000}
rounds=${ROUNDS:-3}
work=$(mktemp -d /tmp/aerobreak-correlation-bench.XXXXXX)
source "$(dirname "$0")/wrk_support.sh"
trap 'stop_bench_server; rm -rf "$work"' EXIT
install_bench_tools

echo "== fitting"
"$build/tests/correlation_bench" "$results" "$work/bench.sqlite"

start_bench_server "$build/aerobreak" "$work/bench.sqlite" "$work"
url="$bench_url/api/studies/1/correlations"
etag=$(curl -sf -D - -o /dev/null "$url" | awk -F': ' 'tolower($1) == "etag" {print $2}' | tr -d '\r')
# Warm-up, not reported: the server's threads open their pooled store connections.
wrk -t2 -c16 -d2s "$url" >/dev/null

echo "== GET /api/studies/1/correlations from the store (wrk, 2 threads, 16 connections, ${DURATION:-10} s a round)"
for round in $(seq "$rounds"); do
  wrk_figures "round $round: /api/studies/1/correlations" "$url"
  wrk_figures "round $round: (If-None-Match, 304)" "$url" -H "If-None-Match: $etag"
  wrk_figures "round $round: /api/health (reference)" "${url%/studies/1/correlations}/health"
done
