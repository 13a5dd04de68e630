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

# `aerobreak serve` of STORE in the background on a free loopback port, for the scripts above:
# start_bench_server AEROBREAK STORE WORK sets `server` (its pid) and `bench_url`
# (http://127.0.0.1:PORT), with its log in WORK/serve.log; stop_bench_server stops it (safe to
# call twice, and from an EXIT trap).
server=
start_bench_server() {
  local aerobreak=$1 store=$2 work=$3
  rm -f "$work/port"
  "$aerobreak" serve --store "$store" --port 0 --port-file "$work/port" --ranks 1 2>>"$work/serve.log" &
  server=$!
  for _ in $(seq 300); do
    if [ -s "$work/port" ]; then
      bench_url="http://127.0.0.1:$(cat "$work/port")"
      return 0
    fi
    sleep 0.1
  done
  echo "serve did not start:" >&2
  cat "$work/serve.log" >&2
  exit 1
}

stop_bench_server() {
  if [ -n "$server" ]; then kill "$server" 2>/dev/null || true; wait "$server" 2>/dev/null || true; server=; fi
}
