#!/usr/bin/env python3
"""Where an outcome takes over: a logistic fit per group of a study's results in a store.

    studies/analysis/transition_fit.py STORE.sqlite [--study ID] [--outcome break-up|stick|bounce]

For each group of grid points that differ only in the impact speed, fits

    P(outcome) = 1 / (1 + exp(-s (x - x50)))

by maximum likelihood to the individual results (undetermined and failed ones left out), once with
x = ln v (the impact speed, in the study's units) and once with x = ln(E_kin / (N_c E_break)), the
energy per initial contact each result records (docs/MODEL.md 1.3), and prints v50 and E50 with 95 %
profile-likelihood intervals: the x50 where 2 (ln L_max - ln L_profile(x50)) <= 3.841 (chi-square,
one degree of freedom; Venzon & Moolgavkar 1988), the slope s maximised at each x50. Also prints
Q*, the energy per contact at which the mean largest fragment falls below half the primaries
(interpolated between speeds), the catastrophic-disruption measure. With no
overlap between the two classes the slope is unbounded: the interval is then the gap between the
two classes (printed as "separated"). A negative slope: the outcome gives way with speed (stick).

Python 3 standard library only (sqlite3, json, math), so that it runs wherever aerobreak runs.
"""
import argparse
import json
import math
import sqlite3
from collections import defaultdict

CHI2_95 = 3.841
MAX_SLOPE = 200.0


def log_likelihood(xs, ys, x50, slope):
    total = 0.0
    for x, y in zip(xs, ys):
        z = slope * (x - x50) if y else -slope * (x - x50)
        total -= math.log1p(math.exp(-abs(z))) + max(-z, 0.0)  # log(1 + exp(-z)) without overflow
    return total


def best_slope(xs, ys, x50):
    """Maximises the (concave) log-likelihood over the slope in [-MAX_SLOPE, MAX_SLOPE] by golden
    section (a negative slope: the outcome gives way with speed, as stick does)."""
    lo, hi = -MAX_SLOPE, MAX_SLOPE
    ratio = (math.sqrt(5.0) - 1.0) / 2.0
    a, b = hi - ratio * (hi - lo), lo + ratio * (hi - lo)
    fa, fb = log_likelihood(xs, ys, x50, a), log_likelihood(xs, ys, x50, b)
    for _ in range(80):
        if fa < fb:
            lo, a, fa = a, b, fb
            b = lo + ratio * (hi - lo)
            fb = log_likelihood(xs, ys, x50, b)
        else:
            hi, b, fb = b, a, fa
            a = hi - ratio * (hi - lo)
            fa = log_likelihood(xs, ys, x50, a)
    slope = 0.5 * (lo + hi)
    return slope, log_likelihood(xs, ys, x50, slope)


def fit(xs, ys):
    """x50, its 95 % profile interval and the slope, or None when one class is absent."""
    if not any(ys) or all(ys):
        return None
    lo, hi = min(xs) - 1.0, max(xs) + 1.0
    grid = [lo + (hi - lo) * k / 500 for k in range(501)]
    profile = [best_slope(xs, ys, x50)[1] for x50 in grid]
    best = max(range(len(grid)), key=lambda k: profile[k])
    inside = [grid[k] for k in range(len(grid)) if 2.0 * (profile[best] - profile[k]) <= CHI2_95]
    slope = best_slope(xs, ys, grid[best])[0]
    for side in (True, False):  # the outcome above (slope > 0) or below (slope < 0) a gap
        below = max(x for x, y in zip(xs, ys) if y != side)
        above = min(x for x, y in zip(xs, ys) if y == side)
        if below < above:
            return 0.5 * (below + above), below, above, math.inf if side else -math.inf, True
    return grid[best], min(inside), max(inside), slope, False


def load(store, study_id):
    db = sqlite3.connect(store)
    rows = db.execute(
        "select sc.grid_point, r.outcome, r.energy_per_contact, r.largest_fragment_share from study_cases sc "
        "join results r on r.case_id = sc.case_id where sc.study_id = ? "
        "and r.outcome in ('stick', 'bounce', 'break-up')", (study_id,))
    groups = defaultdict(list)
    for grid_point, outcome, energy, largest in rows:
        point = json.loads(grid_point)
        speed = point.pop("impact_speed")
        groups[json.dumps(point, sort_keys=True)].append((speed, energy, outcome, largest))
    return groups


def half_mass_energy(results):
    """Q*: the energy per contact where the mean largest-fragment share (in primaries) of a speed
    falls through 1/2, interpolated linearly in ln E between the two speeds around it."""
    by_speed = defaultdict(list)
    for speed, energy, _, largest in results:
        by_speed[speed].append((energy, largest))
    means = [(sum(e for e, _ in rows) / len(rows), sum(f for _, f in rows) / len(rows))
             for _, rows in sorted(by_speed.items())]
    for (e0, f0), (e1, f1) in zip(means, means[1:]):
        if f0 >= 0.5 > f1:
            return math.exp(math.log(e0) + (f0 - 0.5) / (f0 - f1) * (math.log(e1) - math.log(e0)))
    return None


def describe(label, result, transform):
    if result is None:
        return f"{label}: one class only"
    centre, lo, hi, slope, separated = result
    note = "separated" if separated else f"slope {slope:.2f}"
    return f"{label} {transform(centre):.4g} [{transform(lo):.4g}, {transform(hi):.4g}] ({note})"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("store")
    parser.add_argument("--study", type=int, default=1)
    parser.add_argument("--outcome", default="break-up", choices=["break-up", "stick", "bounce"])
    args = parser.parse_args()
    for group, results in sorted(load(args.store, args.study).items()):
        hits = [outcome == args.outcome for _, _, outcome, _ in results]
        by_speed = fit([math.log(v) for v, _, _, _ in results], hits)
        by_energy = fit([math.log(e) for _, e, _, _ in results], hits)
        q_star = half_mass_energy(results)
        print(f"{group} n={len(results)} P({args.outcome}): "
              f"{describe('v50', by_speed, math.exp)}; {describe('E50/(N_c E_break)', by_energy, math.exp)}; "
              f"largest fragment below half at E/(N_c E_break) = {'-' if q_star is None else f'{q_star:.3g}'}")


if __name__ == "__main__":
    main()
