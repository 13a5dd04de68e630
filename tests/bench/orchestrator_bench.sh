#!/usr/bin/env bash
# Orchestrator benchmarks (docs/ORCHESTRATOR.md, "Performance"); prints figures, asserts nothing.
#   1. cases per hour on the default study with 1 and 2 worker ranks, and the scaling efficiency;
#   2. scheduling overhead per case: wall time of a study of trivial cases minus the time the
#      workers spent inside them, per case (one rank);
#   3. requests per second and p99 latency of the read endpoints under wrk on loopback.
# Usage: tests/bench/orchestrator_bench.sh [BUILD_DIR]   (installs wrk and sqlite3 if missing;
# SKIP_DEFAULT=1 skips part 1, running the default study once on 2 ranks for part 3)
set -euo pipefail
build=${1:-build}
aerobreak=$(realpath "$build/aerobreak")
source_dir=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d /tmp/aerobreak-bench.XXXXXX)
trap 'kill $(jobs -p) 2>/dev/null || true; rm -rf "$work"' EXIT

source "$source_dir/tests/bench/wrk_support.sh"
install_bench_tools

if [ "${SKIP_DEFAULT:-0}" = 1 ]; then
  "$aerobreak" run "$source_dir/studies/default.study.json" --store "$work/default-2.sqlite" --ranks 2 --port 0 >/dev/null 2>&1
else
echo "== cases per hour, studies/default.study.json"
declare -A rate
for ranks in 1 2; do
  store="$work/default-$ranks.sqlite"
  start=$(date +%s.%N)
  "$aerobreak" run "$source_dir/studies/default.study.json" --store "$store" --ranks "$ranks" --port 0 >/dev/null 2>"$work/run-$ranks.log"
  end=$(date +%s.%N)
  cases=$(sqlite3 "$store" "SELECT count(*) FROM results")
  busy=$(sqlite3 "$store" "SELECT sum(wall_clock_seconds) FROM results")
  rate[$ranks]=$(echo "3600 * $cases / ($end - $start)" | bc -l)
  printf "ranks %d: %d cases in %.1f s (case compute %.1f s): %.0f cases/hour\n" \
    "$ranks" "$cases" "$(echo "$end - $start" | bc -l)" "$busy" "${rate[$ranks]}"
done
printf "scaling efficiency 1 -> 2 ranks: %.2f\n" "$(echo "${rate[2]} / (2 * ${rate[1]})" | bc -l)"
fi

echo "== scheduling overhead per case (400 trivial cases, 1 rank)"
cat > "$work/trivial.study.json" <<'STUDY'
{
  "name": "trivial cases",
  "base": {
    "cluster": {"generator": {"method": "ballistic", "primaries": 2}},
    "material": {"gamma_over_kn": 0.001},
    "model": {"damping": {"law": "viscoelastic", "dissipative_time": 0.05}},
    "run": {"time_limit": 2000}
  },
  "axes": {"impact_speed": {"log": {"from": 0.001, "to": 0.1, "count": 40}}},
  "replicates": {"count": 10, "seed": 1}
}
STUDY
store="$work/trivial.sqlite"
start=$(date +%s.%N)
"$aerobreak" run "$work/trivial.study.json" --store "$store" --ranks 1 --port 0 >/dev/null
end=$(date +%s.%N)
cases=$(sqlite3 "$store" "SELECT count(*) FROM results")
busy=$(sqlite3 "$store" "SELECT sum(wall_clock_seconds) FROM results")
printf "%d cases in %.2f s, %.2f s inside the cases: overhead %.1f ms per case\n" "$cases" \
  "$(echo "$end - $start" | bc -l)" "$busy" "$(echo "1000 * ($end - $start - $busy) / $cases" | bc -l)"

echo "== read endpoints under wrk (2 threads, 16 connections, 10 s each)"
"$aerobreak" serve --store "$work/default-2.sqlite" --port 0 --port-file "$work/port" --ranks 1 2>"$work/serve.log" &
for _ in $(seq 100); do [ -s "$work/port" ] && break; sleep 0.1; done
url="http://127.0.0.1:$(cat "$work/port")"
for path in /api/health /api/studies/1/progress /api/studies/1/outcomes "/api/studies/1/results?limit=100" /api/cases/1; do
  DURATION=10 wrk_figures "$path" "$url$path"
done
