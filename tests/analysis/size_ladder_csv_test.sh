#!/usr/bin/env bash
# size_ladder.py --csv on a ladder of three real stores: the size-ladder study (studies/size_ladder_n32.study.json)
# at N = 8, 16 and 32, one round of 10 cases per wall each (about 10 s), run by `aerobreak run`; the CSV is checked
# against the printed table and the fit's normal equations by check_size_ladder_csv.py.
# Where R is installed, undetermined_sensitivity.sh must give its four fits per N and wall of the same stores.
#   tests/analysis/size_ladder_csv_test.sh build/aerobreak
set -euo pipefail
aerobreak=$(realpath "$1")
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
bash -n "$root/studies/analysis/size_ladder_figure.sh"
bash -n "$root/studies/analysis/undetermined_sensitivity.sh"

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
stores=()
for n in 8 16 32; do
  python3 -c 'import json, sys
study = json.load(open(sys.argv[1]))
study.pop("$schema")
study["axes"]["primaries"]["values"] = [int(sys.argv[2])]
study["search"].update(budget=10, batch=10, initial=10)
json.dump(study, open(sys.argv[3], "w"))' "$root/studies/size_ladder_n32.study.json" "$n" "$work/n$n.study.json"
  if ! "$aerobreak" run "$work/n$n.study.json" --store "$work/n$n.sqlite" --launcher direct --ranks 1 --port 0 \
      --web-dir "" >"$work/n$n.log" 2>&1; then
    cat "$work/n$n.log"
    exit 1
  fi
  stores+=("$work/n$n.sqlite")
done
AEROBREAK=$aerobreak python3 "$root/studies/analysis/size_ladder.py" --csv "$work/ladder.csv" "${stores[@]}" \
  | tee "$work/table.txt"
python3 "$here/check_size_ladder_csv.py" "$work/ladder.csv" "$work/table.txt" 8 16 32

if command -v gnuplot >/dev/null; then
  OUT=$work/ladder.png AEROBREAK=$aerobreak "$root/studies/analysis/size_ladder_figure.sh" "${stores[@]}" >/dev/null
  [[ -s $work/ladder.png ]] || { echo "size_ladder_figure.sh wrote no PNG"; exit 1; }
  echo "size_ladder_figure.sh drew $(stat -c %s "$work/ladder.png") bytes"
else
  echo "no gnuplot: size_ladder_figure.sh checked by bash -n only"
fi

if command -v Rscript >/dev/null && command -v sqlite3 >/dev/null; then
  "$root/studies/analysis/undetermined_sensitivity.sh" "${stores[@]}" | tee "$work/sensitivity.txt"
  lines=$(grep -c "v50 = " "$work/sensitivity.txt" || true)
  [[ $lines == 24 ]] || { echo "undetermined_sensitivity.sh: $lines v50 lines, not 4 per N and wall (24)"; exit 1; }
else
  echo "no R or sqlite3: undetermined_sensitivity.sh checked by bash -n only"
fi
