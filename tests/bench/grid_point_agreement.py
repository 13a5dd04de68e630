#!/usr/bin/env python3
"""Do two runs of the same study agree grid point by grid point, and case by case?

usage: grid_point_agreement.py BEFORE.sqlite AFTER.sqlite

Both stores hold a run of the same study (e.g. the code before a change and after it). For each
grid point and outcome class it prints the counts where they differ and whether each run's
probability lies inside the other's 95 % Wilson interval (both ways), with Fisher's exact test
(two-sided) of the two counts; then how many such misses two runs of ONE law would give: with each
grid point's class probability taken as the two runs' pooled share, the chance that two independent
binomial samples of those sizes both lie inside each other's interval, summed over grid points and
classes into the expected number of misses (a probability near 0 or 1 makes a miss likely: 0 of 20
lies outside the interval of 1 of 20); then, case by case (matched
by grid point and replicate, so that runs whose case documents differ, e.g. by new defaults, are
compared too), how many have the same class, retained mass fraction, fragment count and largest
fragment, and the largest restitution difference. A side-by-side benchmark (docs/PERFORMANCE.md),
not a test: runs that follow different trajectories may differ by chance.
"""
import math
import sqlite3
import sys
from collections import Counter, defaultdict

CLASSES = ("stick", "bounce", "break-up", "undetermined")
Z95 = 1.959963984540054


def counts_per_grid_point(db):
    per_point = defaultdict(Counter)
    rows = db.execute("SELECT sc.grid_key, r.outcome FROM results r JOIN study_cases sc ON sc.case_id = r.case_id")
    for key, outcome in rows:
        per_point[key][outcome] += 1
    return per_point


def wilson(k, n, z=Z95):
    centre = (k / n + z * z / (2 * n)) / (1 + z * z / n)
    half = z * math.sqrt(k / n * (1 - k / n) / n + z * z / (4 * n * n)) / (1 + z * z / n)
    return centre - half, centre + half


def inside(k, n, other_k, other_n):
    low, high = wilson(other_k, other_n)
    return low <= k / n <= high


def binomial_pmf(k, n, p):
    return math.comb(n, k) * p**k * (1 - p) ** (n - k)


def fisher_exact(ka, na, kb, nb):
    """Two-sided p of Fisher's exact test on the 2x2 table (ka, na - ka; kb, nb - kb): the sum of the
    hypergeometric probabilities of the tables with the same margins no more likely than the one seen."""
    column, total = ka + kb, na + nb

    def table_probability(k):
        return math.comb(na, k) * math.comb(nb, column - k) / math.comb(total, column)

    seen = table_probability(ka)
    tables = range(max(0, column - nb), min(na, column) + 1)
    return min(1.0, sum(q for q in map(table_probability, tables) if q <= seen * (1 + 1e-7)))


def miss_probability_under_one_law(ka, na, kb, nb):
    """The chance that two runs drawn from one law, at the pooled share, miss the both-ways check."""
    p = (ka + kb) / (na + nb)
    pass_probability = sum(binomial_pmf(i, na, p) * binomial_pmf(j, nb, p)
                           for i in range(na + 1) for j in range(nb + 1)
                           if inside(i, na, j, nb) and inside(j, nb, i, na))
    return 1 - pass_probability


def compare_grid_points(a, b):
    agree = total = 0
    expected_misses = 0.0
    smallest_fisher = 1.0
    for key in sorted(set(a) | set(b)):
        na, nb = sum(a[key].values()), sum(b[key].values())
        if not na or not nb:
            print(f"{key}: only in one run")
            continue
        for outcome in CLASSES:
            ka, kb = a[key][outcome], b[key][outcome]
            ok = inside(ka, na, kb, nb) and inside(kb, nb, ka, na)
            total += 1
            agree += ok
            expected_misses += miss_probability_under_one_law(ka, na, kb, nb)
            if ka * nb != kb * na or not ok:
                fisher = fisher_exact(ka, na, kb, nb)
                smallest_fisher = min(smallest_fisher, fisher)
                verdict = "inside" if ok else "OUTSIDE"
                print(f"{key} {outcome}: {ka}/{na} against {kb}/{nb}, {verdict} the other's interval, "
                      f"Fisher p = {fisher:.3g}")
    print(f"{agree} of {total} probabilities inside the other run's 95 % Wilson interval both ways "
          f"({len(a)} grid points); two runs of one law would miss {expected_misses:.1f} of them on "
          f"average; smallest Fisher p {smallest_fisher:.3g}")


def compare_cases(path_a, path_b):
    db = sqlite3.connect(path_a)
    db.execute("ATTACH ? AS other", (path_b,))
    row = db.execute("""
        SELECT count(*), sum(a.outcome = b.outcome),
               sum(abs(a.retained_mass_fraction - b.retained_mass_fraction) < 1e-12),
               sum(a.fragment_count = b.fragment_count),
               sum(abs(a.largest_fragment_share - b.largest_fragment_share) < 1e-12),
               max(abs(coalesce(a.restitution, 0) - coalesce(b.restitution, 0)))
        FROM results a JOIN study_cases sa ON sa.case_id = a.case_id
        JOIN other.study_cases sb ON sb.grid_key = sa.grid_key AND sb.replicate = sa.replicate
        JOIN other.results b ON b.case_id = sb.case_id""").fetchone()
    cases, same_class, same_retained, same_count, same_largest, restitution = row
    if not cases:
        print("no case in both runs")
        return
    print(f"{cases} cases in both: same class {same_class}, retained fraction {same_retained}, "
          f"fragment count {same_count}, largest fragment {same_largest}; "
          f"largest restitution difference {restitution if restitution is not None else 0:.3g}")


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    a, b = (counts_per_grid_point(sqlite3.connect(p)) for p in sys.argv[1:])
    compare_grid_points(a, b)
    compare_cases(*sys.argv[1:])


if __name__ == "__main__":
    main()
