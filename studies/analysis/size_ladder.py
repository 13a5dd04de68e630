#!/usr/bin/env python3
"""The size ladder: v50 of break-up against N, from the stores of the size_ladder_n*.study.json studies.

    studies/analysis/size_ladder.py runs/size_ladder_n32.sqlite runs/size_ladder_n128.sqlite ... [--csv FILE]

For each store (one N) and wall: the adaptive search's v50 with its 95 % interval (Firth's fit and
profile interval, docs/ADAPTIVE.md), the cases, the CPU seconds of the settled cases' stepping (the
sum of /run/cpu_seconds; the fits are made of them) and of all cases (the undetermined ones ran to
the time limit: what the study cost), the mean number of initial contacts N_c, E50/(N_c E_break) with its 95 % profile
interval (the logistic fit of break-up in ln(E_kin/(N_c E_break)) that `aerobreak serve` computes
for the store, asked as transition_fit.py, which sits beside this script, asks it; env AEROBREAK
names the program, build/aerobreak by default), and the mobility-equivalent diameter d N^0.463
(free-molecular regime, docs/EXPORT.md section 2; in nm for the 20 nm primaries of the default
material). Then, per wall, v50 = a N^b fitted by weighted least squares to ln v50 against ln N,
each point weighted by its interval (sigma = (ln upper - ln lower) / (2 x 1.96)), with the 95 %
interval of b (t quantile with n - 2 degrees of freedom, the residual scatter taken when it exceeds
the intervals'). --csv FILE also writes the table, each row with its wall's fit, as CSV (for
size_ladder_figure.sh beside this script, which draws it).

Python 3 standard library only.
"""
import argparse
import csv
import importlib.util
import json
import math
import os
import sqlite3
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
spec = importlib.util.spec_from_file_location("transition_fit", os.path.join(HERE, "transition_fit.py"))
transition_fit = importlib.util.module_from_spec(spec)
spec.loader.exec_module(transition_fit)

AEROBREAK = os.environ.get("AEROBREAK", os.path.join(HERE, "..", "..", "build", "aerobreak"))
PRIMARY_NM = 20.0
T975 = {1: 12.706, 2: 4.303, 3: 3.182, 4: 2.776, 5: 2.571, 6: 2.447}


def groups_of(path):
    """(group point, state, cases, estimate, lower, upper) of each search group."""
    db = sqlite3.connect(path)
    rows = db.execute("SELECT group_point, state, cases, estimates FROM search_groups ORDER BY position").fetchall()
    for point, state, cases, estimates in rows:
        found = [e for e in json.loads(estimates) if e["response"] == "break-up" and e["level"] == 0.5]
        e = found[0] if found else {}
        yield json.loads(point), state, cases, e.get("estimate"), e.get("lower"), e.get("upper")


def results_of(path, wall):
    """Per result of one wall: (initial contacts, stepping CPU s, settled)."""
    db = sqlite3.connect(path)
    out = []
    for (document,) in db.execute("SELECT document FROM results"):
        d = json.loads(document)
        if d["case"]["wall"]["adhesive"] == wall:
            out.append((d["contacts"]["initial"], d["run"]["cpu_seconds"], d["run"]["settled"]))
    return out


def energy_fits(path):
    """E50/(N_c E_break) with its 95 % interval per wall: the service's logistic fit of break-up in
    log energy per contact (docs/CORRELATIONS.md), asked of `aerobreak serve` on the store."""
    with tempfile.TemporaryDirectory() as folder:
        process, url = transition_fit.serve(AEROBREAK, path, folder)
        try:
            summary = transition_fit.get(url + "/api/studies/1/correlations")
        finally:
            process.terminate()
            process.wait()
    out = {}
    for f in summary["fits"]:
        if (f["kind"] != "logistic" or f["response"] != "break-up" or f["dose"] != "energy_per_contact"
                or f["pooled_over"] or f["status"] not in ("ok", "separation")):
            continue
        e50 = next(c for c in f["critical"] if c["level"] == 0.5)
        if None not in e50["ci95"]:
            out[f["group"]["/wall/adhesive"]] = (e50["estimate"], e50["ci95"][0], e50["ci95"][1])
    return out


def power_law(points):
    """Weighted least squares of ln v50 = ln a + b ln N; returns b and its 95 % interval."""
    xs = [math.log(n) for n, _, _, _ in points]
    ys = [math.log(v) for _, v, _, _ in points]
    ws = [1.0 / ((math.log(u) - math.log(l)) / (2 * 1.96)) ** 2 for _, _, l, u in points]
    sw = sum(ws)
    mx = sum(w * x for w, x in zip(ws, xs)) / sw
    my = sum(w * y for w, y in zip(ws, ys)) / sw
    sxx = sum(w * (x - mx) ** 2 for w, x in zip(ws, xs))
    b = sum(w * (x - mx) * (y - my) for w, x, y in zip(ws, xs, ys)) / sxx
    a = my - b * mx
    dof = len(points) - 2
    chi2 = sum(w * (y - a - b * x) ** 2 for w, x, y in zip(ws, xs, ys))
    scale = max(1.0, chi2 / dof) if dof > 0 else 1.0
    se = math.sqrt(scale / sxx)
    t = T975.get(dof, 1.96)
    return b, b - t * se, b + t * se, math.exp(a), chi2, dof


def ladder_rows(paths):
    """One row per store (one N) and wall: the search's v50, the cases' CPU, contacts, E50 and d_mob."""
    rows = []
    for path in paths:
        energies = energy_fits(path)
        for point, state, cases, v50, lower, upper in groups_of(path):
            n, wall = point["primaries"], point["/wall/adhesive"]
            results = results_of(path, wall)
            settled = [r for r in results if r[2]]
            rows.append({
                "primaries": n, "adhesive": wall, "cases": cases, "state": state, "v50": (v50, lower, upper),
                "cpu_settled": sum(r[1] for r in settled), "cpu_all": sum(r[1] for r in results),
                "contacts": sum(r[0] for r in settled) / len(settled) if settled else float("nan"),
                "energy": energies.get(wall), "d_mob": n ** 0.463})
    return rows


def ladder_fits(rows):
    """Per wall with at least 3 sizes: power_law's (b, b lower, b upper, a, chi2, dof) and the sizes."""
    fits = {}
    for wall in (True, False):
        points = sorted((r["primaries"],) + r["v50"] for r in rows if r["adhesive"] == wall and all(r["v50"]))
        if len(points) >= 3:
            fits[wall] = power_law(points) + (len(points),)
    return fits


def wall_name(wall):
    return "adhesive" if wall else "none"


def print_table(rows, fits):
    print("%6s %-9s %5s %-8s %22s %10s %10s %7s %24s %8s %9s" % (
        "N", "wall", "cases", "search", "v50 m/s [95 %]", "CPU s set.", "CPU s all", "N_c", "E50/(N_c E_break) [95 %]",
        "d_mob d", "d_mob nm"))
    for r in rows:
        e_text = "%.2f [%.2f, %.2f]" % r["energy"] if r["energy"] else "-"
        v_text = "%.2f [%.2f, %.2f]" % r["v50"] if r["v50"][0] else "-"
        print("%6d %-9s %5d %-8s %22s %10.1f %10.1f %7.1f %24s %8.2f %9.1f" % (
            r["primaries"], wall_name(r["adhesive"]), r["cases"], r["state"].replace("budget_spent", "budget"), v_text,
            r["cpu_settled"], r["cpu_all"], r["contacts"], e_text, r["d_mob"], r["d_mob"] * PRIMARY_NM))
    for wall, (b, b_low, b_high, a, chi2, dof, sizes) in fits.items():
        print("%-9s v50 = %.1f m/s x N^b, b = %.3f [%.3f, %.3f] (%d sizes, chi2 %.2f on %d degrees of freedom)" %
              (wall_name(wall), a, b, b_low, b_high, sizes, chi2, dof))


CSV_COLUMNS = ("primaries", "wall", "cases", "search", "v50_m_s", "v50_lower_m_s", "v50_upper_m_s", "cpu_s_settled",
               "cpu_s_all", "contacts", "e50_per_contact", "e50_lower", "e50_upper", "d_mob_over_d", "d_mob_nm",
               "fit_a_m_s", "fit_b", "fit_b_lower", "fit_b_upper", "fit_sizes")


def write_csv(path, rows, fits):
    """The table as CSV, one row per N and wall, each with its wall's fit v50 = a N^b (empty: no value); the
    search column is the store's state (converged, budget_spent or searching)."""
    with open(path, "w", newline="") as out:
        writer = csv.writer(out)
        writer.writerow(CSV_COLUMNS)
        for r in rows:
            fit = fits.get(r["adhesive"])
            fit_cells = [fit[3], fit[0], fit[1], fit[2], fit[6]] if fit else [None] * 5
            cells = [r["primaries"], wall_name(r["adhesive"]), r["cases"], r["state"], *r["v50"], r["cpu_settled"],
                     r["cpu_all"], r["contacts"], *(r["energy"] or (None,) * 3), r["d_mob"], r["d_mob"] * PRIMARY_NM,
                     *fit_cells]
            writer.writerow(["" if c is None or c != c else c for c in cells])


def main(arguments):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("stores", nargs="+", metavar="STORE", help="a size_ladder_n*.sqlite store (one N)")
    parser.add_argument("--csv", metavar="FILE", help="also write the table and the fits to FILE as CSV")
    options = parser.parse_args(arguments)
    rows = ladder_rows(options.stores)
    fits = ladder_fits(rows)
    print_table(rows, fits)
    if options.csv:
        write_csv(options.csv, rows, fits)


if __name__ == "__main__":
    main(sys.argv[1:])
