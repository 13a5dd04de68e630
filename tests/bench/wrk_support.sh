# Shared by the benchmark scripts that measure the REST service with wrk (sourced, not run).

# Installs wrk and sqlite3 (Debian packages) when they are missing.
install_bench_tools() {
  local missing=()
  command -v wrk >/dev/null || missing+=(wrk)
  command -v sqlite3 >/dev/null || missing+=(sqlite3)
  ((${#missing[@]})) || return 0
  local sudo
  sudo=$([ "$(id -u)" -eq 0 ] && echo "" || echo sudo)
  $sudo apt-get update -qq && $sudo apt-get install -y -qq "${missing[@]}" >/dev/null
}

# One line of figures for URL under wrk (2 threads, 16 connections, DURATION seconds, 10 unless
# set): requests per second, the 99th percentile latency and the answers >= 400.
# Usage: wrk_figures LABEL URL [wrk options, e.g. -H 'If-None-Match: TAG']
wrk_figures() {
  local label=$1 url=$2
  shift 2
  local out rps p99 errors
  out=$(wrk -t2 -c16 -d"${DURATION:-10}s" --latency "$@" "$url")
  rps=$(awk '/Requests\/sec/ {print $2}' <<<"$out")
  p99=$(awk '$1 == "99%" {print $2}' <<<"$out")
  errors=$(awk '/Non-2xx/ {print $NF}' <<<"$out")
  printf "%-44s %10s requests/s   p99 %8s   non-2xx %s\n" "$label" "$rps" "$p99" "${errors:-0}"
}
