#!/usr/bin/env bash
# Installs the Debian packages aerobreak needs (only those missing), the dashboard's npm packages
# (from the committed lockfiles) and builds the aerobreak program into build/ (only the program: ctest
# builds the tests before it runs them, cmake/BuildBeforeTests.cmake).
# Idempotent and quiet when everything is already there. Usage: scripts/setup.sh [--no-build]
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  cmake g++ make pkg-config git ca-certificates
  libopenmpi-dev openmpi-bin
  libhdf5-dev hdf5-tools
  libsqlite3-dev
  libssl-dev
  zlib1g-dev
  nlohmann-json3-dev
  libcpp-httplib-dev
  catch2
  json-schema-test-suite
  libcli11-dev
  libeigen3-dev
  libboost-dev
  gfortran
  python3
  clang-format
  openfoam
  chromium
)
# Node.js and npm for the dashboard's libraries and browser tests; a machine that already has a
# node (e.g. from another source, with its own npm) keeps it.
command -v node >/dev/null || packages+=(nodejs)
command -v npm >/dev/null || packages+=(npm)

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done

if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  sudo=()
  if [[ $(id -u) -ne 0 ]]; then
    command -v sudo >/dev/null || { echo "setup: need root or sudo to install packages" >&2; exit 1; }
    sudo=(sudo)
  fi
  export DEBIAN_FRONTEND=noninteractive
  "${sudo[@]}" apt-get update -qq
  "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# The npm packages pinned by each lockfile: the page's libraries (web/), the browser tests' driver
# (tests/browser/) and the API description's linter (tests/openapi/, Redocly CLI). Installed again
# only when the lockfile changed.
for folder in web tests/browser tests/openapi; do
  stamp="$folder/node_modules/.aerobreak-lock"
  if ! cmp -s "$folder/package-lock.json" "$stamp" 2>/dev/null; then
    echo "setup: npm ci in $folder"
    (cd "$folder" && npm ci --no-audit --no-fund --loglevel=error >/dev/null)
    cp "$folder/package-lock.json" "$stamp"
  fi
done

[[ "${1:-}" == "--no-build" ]] && exit 0

build_dir=${AEROBREAK_BUILD_DIR:-build}
if [[ ! -f "$build_dir/CMakeCache.txt" ]]; then
  cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
cmake --build "$build_dir" -j"$(nproc)" --target aerobreak
echo "setup: built $build_dir/aerobreak"
