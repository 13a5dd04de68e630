#!/usr/bin/env bash
# rerun_undetermined.sh and undetermined_sensitivity.sh --reruns on a small real store: the size-ladder study
# (studies/size_ladder_n32.study.json) at N = 16 with the time limit cut to 8e-9 s, two rounds of 10 cases per wall
# (about 2 s), run by `aerobreak run`, which leaves some cases undetermined. Checks that
#  - a case rerun with its old limit reproduces its stored result (the same trajectory: every number but the
#    timings and the code's commit),
#  - rerun at 3e-8 s, each undetermined case gets a result (most settle), and a second call skips them all,
#  - rerun_summary.py's closest approach of two pieces equals the hand-worked one,
#  - the refit prints six ways per wall, its Firth fit with the undetermined left out equals the search's own
#    v50 and interval in the store, and a rerun whose case is not the store's is refused.
#   tests/analysis/rerun_undetermined_test.sh build/aerobreak
set -euo pipefail
export AEROBREAK=$(realpath "$1")
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
analysis=$(cd "$here/../../studies/analysis" && pwd)
bash -n "$analysis/rerun_undetermined.sh"
if ! command -v Rscript >/dev/null || ! command -v sqlite3 >/dev/null; then
  echo "no R or sqlite3: rerun_undetermined.sh checked by bash -n only"
  exit 0
fi
# rerun_summary.py's straight-line closest approach against the hand-worked one: b 10 d from a along x, closing
# at (-1, 1, 0) 1e-3 d/tau: closest after 10 * 1e-3 / 2e-6 = 5000 tau, 50^0.5 = 7.07 d apart (< 5 + 3: may meet).
PYTHONPATH=$analysis python3 - <<'PY'
import math
from rerun_summary import closest_approach
a = {"centre_of_mass": [0, 0, 0], "velocity": [0, 0, 0], "bounding_radius": 5}
b = {"centre_of_mass": [10, 0, 0], "velocity": [-1e-3, 1e-3, 0], "bounding_radius": 3}
t, closest = closest_approach(a, b)
assert abs(t - 5000) < 1e-9 and abs(closest - math.sqrt(50)) < 1e-12, (t, closest)
assert closest_approach(b, a) == (t, closest)
assert closest_approach(a, dict(b, bounding_radius=2)) is None  # passes 7.07 d apart, beyond 5 + 2
assert closest_approach(a, dict(b, velocity=[1e-3, 0, 0])) is None  # receding
print("closest approach: 5000 tau, 7.07 d, as worked by hand")
PY
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
store=$work/n16.sqlite
python3 -c 'import json, sys
study = json.load(open(sys.argv[1]))
study.pop("$schema")
study["axes"]["primaries"]["values"] = [16]
study["base"]["run"]["time_limit_s"] = 8e-9
study["search"].update(budget=20, batch=10, initial=10)
json.dump(study, open(sys.argv[2], "w"))' "$here/../../studies/size_ladder_n32.study.json" "$work/n16.study.json"
if ! "$AEROBREAK" run "$work/n16.study.json" --store "$store" --launcher direct --ranks 1 --port 0 --web-dir "" \
    >"$work/run.log" 2>&1; then
  cat "$work/run.log"
  exit 1
fi
undetermined=$(sqlite3 "$store" "SELECT count(*) FROM results WHERE outcome = 'undetermined'")
echo "store: $(sqlite3 "$store" "SELECT count(*) FROM results") results, $undetermined undetermined"
[[ $undetermined -ge 2 ]] || { echo "the store has $undetermined undetermined cases, the test needs 2"; exit 1; }

first=$(sqlite3 "$store" "SELECT min(case_id) FROM results WHERE outcome = 'undetermined'")
"$analysis/rerun_undetermined.sh" "$store" 8e-9 "$work/same" "c.id = $first"
sqlite3 "$store" "SELECT document FROM results WHERE case_id = $first" >"$work/stored.json"
python3 - "$work/stored.json" "$work/same/case$first.result.json" <<'PY'
import json, sys
timings = {"/code/git_commit", "/run/cpu_seconds", "/run/wall_clock_seconds", "/run/particle_steps_per_second",
           "/run/particle_steps_per_cpu_second", "/run/snapshots", "/setup/relaxation/wall_clock_seconds"}
def leaves(d, path=""):
    items = d.items() if isinstance(d, dict) else enumerate(d) if isinstance(d, list) else None
    if items is None:
        yield path, d
        return
    for key, value in items:
        yield from leaves(value, f"{path}/{key}")
stored, rerun = (dict(leaves(json.load(open(p)))) for p in sys.argv[1:])
differ = sorted(k for k in stored.keys() | rerun.keys() if k not in timings and stored.get(k) != rerun.get(k))
print(f"rerun at the old limit: {len(stored)} numbers, {len(differ)} differ beyond the timings")
if differ or stored["/outcome/class"] != "undetermined":
    sys.exit("not the stored trajectory: " + ", ".join(f"{k}: {stored.get(k)} -> {rerun.get(k)}" for k in differ[:10]))
PY

"$analysis/rerun_undetermined.sh" "$store" 3e-8 "$work/longer" | tee "$work/longer.log"
results=$(ls "$work/longer"/case*.result.json | wc -l)
[[ $results == "$undetermined" ]] || { echo "$results rerun results for $undetermined undetermined cases"; exit 1; }
"$analysis/rerun_undetermined.sh" "$store" 3e-8 "$work/longer" >"$work/again.log"
skipped=$(grep -c "done before" "$work/again.log" || true)
[[ $skipped == "$undetermined" ]] || { echo "the second call skipped $skipped of $undetermined cases"; exit 1; }

"$analysis/undetermined_sensitivity.sh" --reruns "$work/longer" "$store" | tee "$work/refit.txt"
lines=$(grep -c "v50 = " "$work/refit.txt" || true)
[[ $lines == 12 ]] || { echo "undetermined_sensitivity.sh --reruns: $lines v50 lines, not 6 per wall (12)"; exit 1; }
python3 - "$store" "$work/refit.txt" <<'PY'
import json, re, sqlite3, sys
db = sqlite3.connect(sys.argv[1])
printed = {}
for line in open(sys.argv[2]):
    m = re.search(r"(adhesive wall|without adhesion) +undetermined +\d+ of +\d+  left out +v50 = .* "
                  r"Firth +([\d.]+) \[([\d.]+), ([\d.]+)\]", line)
    if m:
        printed[m.group(1) == "adhesive wall"] = [float(x) for x in m.groups()[1:]]
for point, estimates in db.execute("SELECT group_point, estimates FROM search_groups"):
    wall = json.loads(point)["/wall/adhesive"]
    e = json.loads(estimates)[0]
    search = [round(e[k], 2) for k in ("estimate", "lower", "upper")]
    print(f"adhesive={wall}: search {search}, refit {printed[wall]}")
    if search != printed[wall]:
        sys.exit("the refit's Firth v50 with the undetermined left out is not the search's")
PY

python3 - "$work/longer" "$work/forged" <<'PY'
import json, os, sys
os.makedirs(sys.argv[2])
name = sorted(f for f in os.listdir(sys.argv[1]) if f.endswith(".result.json"))[0]
result = json.load(open(os.path.join(sys.argv[1], name)))
result["case"]["impact"]["speed"] *= 1.01
json.dump(result, open(os.path.join(sys.argv[2], name), "w"))
PY
if "$analysis/undetermined_sensitivity.sh" --reruns "$work/forged" "$store" >/dev/null 2>"$work/forged.err"; then
  echo "a rerun of another case was accepted"
  exit 1
fi
grep "is not case" "$work/forged.err"
