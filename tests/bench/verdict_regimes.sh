#!/usr/bin/env bash
# The early verdict against running on to the quiet rule, regime by regime (docs/IMPACT.md section 4,
# "Checked on seeds"): build/tests/verdict_bench on the physical-units example
# (studies/examples/physical.case.json: 20 nm primaries, E = 25 GPa, gamma = 0.05 J/m^2, time limit
# 3e-7 s) with N primaries, per regime a wall and a speed; seeds are run one at a time, the regimes
# in turn, so that a run cut short has the same seeds of every regime. Then one line per regime:
# the seeds compared, the quiet rule's classes, the rules of the first verdicts, the seeds with no
# verdict by the time limit or compared with the state at it, those whose class, retained fraction,
# fragment count or largest fragment differ, the largest restitution difference, and the CPU seconds
# to the first verdict and to the quiet rule's (summed over the seeds).
#
# usage: verdict_regimes.sh N SEEDS [OUTDIR]
#   SEEDS: a count S (seeds 1 .. S) or a range A-B; OUTDIR: where the per-regime outputs go (appended)
# env: REGIMES, "wall:speed" pairs (wall true: adhesive; speed in m/s), by default
#   "true:5 true:15 true:60 false:10 false:20 false:30 false:60"; VERDICT_BENCH (build/tests/verdict_bench)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
n=$1
range=$2
out=${3:-$(mktemp -d /tmp/verdict_regimes.XXXXXX)}
bench=${VERDICT_BENCH:-$here/../../build/tests/verdict_bench}
regimes=${REGIMES:-"true:5 true:15 true:60 false:10 false:20 false:30 false:60"}
first=1
last=$range
if [[ $range == *-* ]]; then first=${range%-*}; last=${range#*-}; fi
mkdir -p "$out"

for s in $(seq "$first" "$last"); do
  for regime in $regimes; do
    wall=${regime%:*}
    speed=${regime#*:}
    nice -n 10 "$bench" "$here/../../studies/examples/physical.case.json" \
      "{\"cluster\":{\"generator\":{\"primaries\":$n}},\"impact\":{\"speed\":$speed},\"wall\":{\"adhesive\":$wall}}" \
      "$s-$s" >> "$out/n${n}_${wall}_v${speed}.txt"
  done
done

python3 - "$out" "$n" $regimes <<'PY'
import collections, sys
out, n, regimes = sys.argv[1], sys.argv[2], sys.argv[3:]
print("| N | wall | m/s | seeds | classes (quiet rule) | first verdict by | none / at limit | differ | max Δe_n "
      "| CPU s first / quiet |")
for regime in regimes:
    wall, speed = regime.split(":")
    seeds = {}
    for line in open("%s/n%s_%s_v%s.txt" % (out, n, wall, speed)):
        f = line.split()
        if len(f) == 10 and f[1] in ("first", "quiet"):
            seeds.setdefault(int(f[0]), {})[f[1]] = f
    classes, rules = collections.Counter(), collections.Counter()
    none = at_limit = differ = 0
    worst = cpu_first = cpu_last = 0.0
    for d in seeds.values():
        a, b = d["first"], d["quiet"]
        if a[3] == "-":
            none += 1
            continue
        at_limit += b[3] == "limit"
        classes[b[2]] += 1
        rules[a[3]] += 1
        differ += a[2] != b[2] or abs(float(a[4]) - float(b[4])) > 1e-12 or a[5] != b[5] or a[6] != b[6]
        worst = max(worst, abs(float(a[7]) - float(b[7])))
        cpu_first += float(a[9])
        cpu_last += float(b[9])
    describe = lambda c: ", ".join("%s %d" % kv for kv in sorted(c.items()))
    print("| %s | %s | %s | %d | %s | %s | %d / %d | %d | %.3g | %.1f / %.1f |" % (
        n, "adhesive" if wall == "true" else "none", speed, len(seeds), describe(classes), describe(rules), none,
        at_limit, differ, worst, cpu_first, cpu_last))
PY
echo "outputs in $out"
