#!/usr/bin/env bash
# Regenerates the validation figures docs/figures/*.png from the validation_data program.
#   docs/validation/make_figures.sh            build in build-validation, data in a temporary directory
#   BUILD_DIR=/path KEEP_DATA=/path docs/validation/make_figures.sh   other build dir; keep the CSV files
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
build=${BUILD_DIR:-$root/build-validation}
figures=$root/docs/figures

if [[ ! -f $build/CMakeCache.txt ]]; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release
fi
cmake --build "$build" --target validation_data -j"${JOBS:-2}"

if [[ -n ${KEEP_DATA:-} ]]; then
  data=$KEEP_DATA
  mkdir -p "$data"
else
  data=$(mktemp -d)
  trap 'rm -rf "$data"' EXIT
fi
"$build/tests/validation/validation_data" "$data"

term=pngcairo
terminals=$(gnuplot -e "set terminal" 2>&1 || true)
if ! grep -qw pngcairo <<<"$terminals"; then
  echo "make_figures: gnuplot has no pngcairo terminal, using png" >&2
  term=png
fi
mkdir -p "$figures"
for script in "$here"/*.gp; do
  gnuplot -e "here='$here'; data='$data'; out='$figures'; term='$term'" "$script"
done
cat "$data/summary.txt"
echo "engine: $(git -C "$root" describe --always --dirty 2>/dev/null || echo unknown)"
ls -l "$figures"/*.png
