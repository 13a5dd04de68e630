#!/usr/bin/env python3
"""Checks size_ladder.py's --csv output against its printed table: check_size_ladder_csv.py CSV TABLE N...

The columns size_ladder_figure.sh reads by position, one row per N and wall, every number equal to the table's at
the table's precision, each interval holding its estimate, the mobility diameter 20 nm x N^0.463 (docs/EXPORT.md
section 2), and each wall's fit v50 = a N^b solving the normal equations of the weighted least squares in ln v50
against ln N (weights 1 / sigma^2, sigma = (ln upper - ln lower) / (2 x 1.96)) with an interval symmetric about b.
Exits 1 naming each failed check.
"""
import csv
import math
import sys

COLUMNS = ["primaries", "wall", "cases", "search", "v50_m_s", "v50_lower_m_s", "v50_upper_m_s", "cpu_s_settled",
           "cpu_s_all", "contacts", "e50_per_contact", "e50_lower", "e50_upper", "d_mob_over_d", "d_mob_nm",
           "fit_a_m_s", "fit_b", "fit_b_lower", "fit_b_upper", "fit_sizes"]
failures = []


def check(condition, what):
    if not condition:
        failures.append(what)


def number(text):
    return float(text) if text != "" else None


def check_row(row, printed):
    """One CSV row against its printed line (split on blanks, brackets and commas dropped)."""
    name = "N = %s, %s" % (row["primaries"], row["wall"])
    v50, low, high = (number(row[k]) for k in ("v50_m_s", "v50_lower_m_s", "v50_upper_m_s"))
    check(low < v50 < high, name + ": v50 outside its interval")
    e50, e_low, e_high = (number(row[k]) for k in ("e50_per_contact", "e50_lower", "e50_upper"))
    check(e50 is None or e_low < e50 < e_high, name + ": E50 outside its interval")
    check(float(row["cpu_s_all"]) >= float(row["cpu_s_settled"]) > 0, name + ": CPU seconds")
    n = int(row["primaries"])
    check(abs(float(row["d_mob_nm"]) - 20 * n ** 0.463) < 1e-9 * n, name + ": mobility diameter")
    expected = [row["primaries"], row["wall"], row["cases"], row["search"].replace("budget_spent", "budget"),
                "%.2f" % v50, "%.2f" % low, "%.2f" % high, "%.1f" % float(row["cpu_s_settled"]),
                "%.1f" % float(row["cpu_s_all"]), "%.1f" % float(row["contacts"])]
    expected += ["%.2f" % e for e in (e50, e_low, e_high)] if e50 is not None else ["-"]
    expected += ["%.2f" % float(row["d_mob_over_d"]), "%.1f" % float(row["d_mob_nm"])]
    check(printed == expected, "%s: CSV %s, table %s" % (name, expected, printed))


def check_fit(wall, rows, printed_fits):
    """The fit's columns are the same on each row of the wall and solve the weighted normal equations."""
    fits = {tuple(r[k] for k in COLUMNS[15:]) for r in rows}
    check(len(fits) == 1, wall + ": rows disagree on the fit")
    a, b, b_low, b_high, sizes = (float(x) for x in fits.pop())
    check(sizes == len(rows), wall + ": fit_sizes")
    check(b_low < b < b_high and abs((b_high - b) - (b - b_low)) < 1e-9, wall + ": interval of b")
    score = [0.0, 0.0]
    for r in rows:
        x = math.log(float(r["primaries"]))
        sigma = (math.log(float(r["v50_upper_m_s"])) - math.log(float(r["v50_lower_m_s"]))) / (2 * 1.96)
        residual = (math.log(float(r["v50_m_s"])) - math.log(a) - b * x) / sigma ** 2
        score = [score[0] + residual, score[1] + residual * x]
    check(max(abs(s) for s in score) < 1e-6, wall + ": normal equations off by %s" % score)
    check(printed_fits.get(wall) == "%.3f [%.3f, %.3f]" % (b, b_low, b_high), wall + ": printed fit")


def main(csv_path, table_path, sizes):
    with open(csv_path) as f:
        reader = csv.DictReader(f)
        check(reader.fieldnames == COLUMNS, "columns %s" % reader.fieldnames)
        rows = list(reader)
    lines = open(table_path).read().splitlines()
    table = [line.replace("[", " ").replace("]", " ").replace(",", " ").split() for line in lines[1:]]
    table = [t for t in table if t and t[0].isdigit()]
    printed_fits = {line.split()[0]: line.split("b = ")[1].split(" (")[0] for line in lines if " x N^b, " in line}
    check([(r["primaries"], r["wall"]) for r in rows] == [(n, w) for n in sizes for w in ("adhesive", "none")],
          "rows: %s" % [(r["primaries"], r["wall"]) for r in rows])
    check(len(table) == len(rows), "table rows %d, CSV rows %d" % (len(table), len(rows)))
    for row, printed in zip(rows, table):
        check_row(row, printed)
    for wall in ("adhesive", "none"):
        check_fit(wall, [r for r in rows if r["wall"] == wall], printed_fits)
    for failure in failures:
        print("FAIL", failure)
    print("%d rows, %d failed checks" % (len(rows), len(failures)))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2], sys.argv[3:]))
