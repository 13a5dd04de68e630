#!/usr/bin/env python3
"""One line per impact result (aerobreak impact's JSON): wall, speed, class, simulated time, CPU seconds and,
for an undetermined one, its /run/unsettled_reason and when its pieces that may still meet pass closest.

    studies/analysis/rerun_summary.py RESULT.json...

A run ends undetermined at a wall without adhesion mostly because two pieces still approach each other: the quiet
rule (docs/IMPACT.md section 4, condition 4) waits while the centres of a pair approach and, moving on in straight
lines, would pass closer than the sum of their bounding radii. For the pieces of 10 primaries or more this prints
the pair whose straight-line closest approach comes last, and how much later than the end of the run it comes:
a guide to the time limit a rerun needs (a pair that touches may join instead; instantaneous velocities, where the
rule takes them averaged over its window). rerun_undetermined.sh prints it for each rerun.
"""
import itertools
import json
import math
import sys

SMALLEST_PIECE = 10  # primaries


def closest_approach(a, b):
    """(time in tau until the centres of pieces a and b pass closest in straight lines, closest distance) or None
    if they are not approaching or would pass farther apart than the sum of their bounding radii."""
    dx = [q - p for p, q in zip(a["centre_of_mass"], b["centre_of_mass"])]
    dv = [q - p for p, q in zip(a["velocity"], b["velocity"])]
    approach = sum(x * v for x, v in zip(dx, dv))
    speed2 = sum(v * v for v in dv)
    if approach >= 0 or speed2 == 0:
        return None
    t = -approach / speed2
    closest = math.hypot(*(x + v * t for x, v in zip(dx, dv)))
    return (t, closest) if closest < a["bounding_radius"] + b["bounding_radius"] else None


def last_pass(result):
    """(seconds after the run's end, primaries of the two pieces) of the latest closest approach, or None."""
    pieces = [f for f in result["fragments"]["list"] if f["size"] >= SMALLEST_PIECE]
    passes = [(meeting[0], a["size"], b["size"]) for a, b in itertools.combinations(pieces, 2)
              if (meeting := closest_approach(a, b))]
    if not passes:
        return None
    t, size_a, size_b = max(passes)
    run = result["run"]
    return t * run["simulated_time_s"] / run["simulated_time"], size_a, size_b


def summary(result):
    run, case = result["run"], result["case"]
    wall = "adhesive wall" if case["wall"]["adhesive"] else "without adhesion"
    line = (f'{wall:16}  {case["impact"]["speed"]:7.3f} m/s  {result["outcome"]["class"]:12}'
            f'  t = {run["simulated_time_s"]:.3g} s  {run["cpu_seconds"]:7.1f} CPU s')
    if result["outcome"]["class"] != "undetermined":
        return line
    passing = last_pass(result)
    if passing:
        line += "  pieces of %d and %d primaries pass closest %.2g s later" % (passing[1], passing[2], passing[0])
    return line + f'  ({run["unsettled_reason"]})'


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    for path in sys.argv[1:]:
        with open(path) as f:
            print(summary(json.load(f)))
