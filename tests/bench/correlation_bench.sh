#!/usr/bin/env bash
# Correlation benchmark (docs/PERFORMANCE.md, "Correlations"); prints figures, asserts nothing.
#   1. build/tests/correlation_bench: fitting a synthetic study of RESULTS (default 100,000) results,
#      then the same study written to a store: the first request (read, hash, fit, store) and a
#      second one (from the store);
#   2. GET /api/studies/1/correlations on that store under wrk (loopback, 2 threads, 16
#      connections, 10 s): requests per second and latency percentiles, served from the store.
# Usage: tests/bench/correlation_bench.sh [BUILD_DIR] [RESULTS]   (installs wrk if missing)
set -euo pipefail
build=${1:-build}
results=${2:-100000}
work=$(mktemp -d /tmp/aerobreak-correlation-bench.XXXXXX)
trap 'kill $(jobs -p) 2>/dev/null || true; rm -rf "$work"' EXIT

if ! command -v wrk >/dev/null; then
  sudo=$([ "$(id -u)" -eq 0 ] && echo "" || echo sudo)
  $sudo apt-get update -qq && $sudo apt-get install -y -qq wrk >/dev/null
fi

echo "== fitting"
"$build/tests/correlation_bench" "$results" "$work/bench.sqlite"

echo "== GET /api/studies/1/correlations from the store (wrk, 2 threads, 16 connections, 10 s)"
"$build/aerobreak" serve --store "$work/bench.sqlite" --port 0 --port-file "$work/port" --ranks 1 >"$work/serve.log" 2>&1 &
for _ in $(seq 100); do [ -s "$work/port" ] && break; sleep 0.1; done
url="http://127.0.0.1:$(cat "$work/port")/api/studies/1/correlations"
curl -sf "$url" >/dev/null
wrk -t2 -c16 -d10s --latency "$url" | grep -E "Latency|50%|90%|99%|Requests/sec"
