#!/usr/bin/env python3
"""Where an outcome takes over: the fitted correlations that aerobreak serves, per group of a study.

    studies/analysis/transition_fit.py STORE.sqlite [--study ID] [--outcome break-up|stick|bounce]
                                       [--aerobreak build/aerobreak]

Starts `aerobreak serve` on the store of a finished study (loopback, a free port), asks
GET /api/studies/ID/correlations (docs/CORRELATIONS.md) and prints, for each group of grid points
that differ only in the impact speed, what the fitting library computed: v50 from the logistic fit
in log impact speed (OUTCOME.speed.gK) and E50 from the fit in log E_kin/(N_c E_break), the energy
per initial contact each result records (OUTCOME.energy.gK), each with its 95 % profile-likelihood
interval (Venzon & Moolgavkar 1988; Firth's penalised likelihood under separation), and the
measured crossing of 0.5 (observed_crossings: the proportions interpolated in log speed). It also
prints Q*, the energy per contact at which the mean largest fragment falls below half the primaries
(interpolated between speeds from the store's results: a crossing of a mean, not of P), the
catastrophic-disruption measure.

Python 3 standard library only (sqlite3, json, subprocess, urllib), so that it runs wherever
aerobreak runs.
"""
import argparse
import json
import math
import os
import sqlite3
import subprocess
import tempfile
import time
import urllib.request
from collections import defaultdict


def serve(aerobreak, store, folder):
    """`aerobreak serve` on the store; returns the process and its URL once it listens."""
    port_file = os.path.join(folder, "port")
    process = subprocess.Popen([aerobreak, "serve", "--store", store, "--port", "0", "--port-file", port_file,
                                "--ranks", "1", "--quiet"], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    for _ in range(300):
        if os.path.exists(port_file) and open(port_file).read().strip():
            return process, "http://127.0.0.1:" + open(port_file).read().strip()
        if process.poll() is not None:
            raise SystemExit("aerobreak serve stopped: " + process.stderr.read().decode())
        time.sleep(0.1)
    process.kill()
    raise SystemExit("aerobreak serve did not start")


def get(url):
    with urllib.request.urlopen(url, timeout=600) as answer:
        return json.load(answer)


def half_mass_energy(store, study_id):
    """Q* per group (the grid point without its speed): where the mean largest-fragment share of a
    speed falls through 1/2, interpolated linearly in ln E between the two speeds around it."""
    db = sqlite3.connect(store)
    rows = db.execute(
        "select sc.grid_point, r.energy_per_contact, r.largest_fragment_share from study_cases sc "
        "join results r on r.case_id = sc.case_id where sc.study_id = ? "
        "and r.outcome in ('stick', 'bounce', 'break-up')", (study_id,))
    by_group = defaultdict(lambda: defaultdict(list))
    for grid_point, energy, largest in rows:
        point = json.loads(grid_point)
        speed = point.pop("impact_speed")
        by_group[json.dumps(point, sort_keys=True)][speed].append((energy, largest))
    q_star = {}
    for group, by_speed in by_group.items():
        means = [(sum(e for e, _ in r) / len(r), sum(f for _, f in r) / len(r)) for _, r in sorted(by_speed.items())]
        q_star[group] = None
        for (e0, f0), (e1, f1) in zip(means, means[1:]):
            if f0 >= 0.5 > f1:
                q_star[group] = math.exp(math.log(e0) + (f0 - 0.5) / (f0 - f1) * (math.log(e1) - math.log(e0)))
                break
    return q_star


def describe(label, fit):
    if fit is None:
        return f"{label}: no fit"
    if fit["status"] not in ("ok", "separation"):
        return f"{label}: {fit['status']}"
    v50 = next(c for c in fit["critical"] if c["level"] == 0.5)
    low, high = (f"{x:.4g}" if x is not None else "open" for x in v50["ci95"])
    note = "separated, Firth" if fit["status"] == "separation" else "slope %.2f" % fit["coefficients"][1]
    return f"{label} {v50['estimate']:.4g} [{low}, {high}] ({note})"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("store")
    parser.add_argument("--study", type=int, default=1)
    parser.add_argument("--outcome", default="break-up", choices=["break-up", "stick", "bounce"])
    parser.add_argument("--aerobreak", default=os.path.join(os.path.dirname(__file__), "..", "..", "build", "aerobreak"))
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        process, url = serve(args.aerobreak, args.store, folder)
        try:
            summary = get(f"{url}/api/studies/{args.study}/correlations")
        finally:
            process.terminate()
            process.wait()
    fits = {(f["dose"], json.dumps(f["group"], sort_keys=True)): f for f in summary["fits"]
            if f["kind"] == "logistic" and f["response"] == args.outcome and not f["pooled_over"]}
    q_star = half_mass_energy(args.store, args.study)
    for group in sorted({g for _, g in fits}):
        speed, energy = fits.get(("impact_speed", group)), fits.get(("energy_per_contact", group))
        measured = next((c["dose"] for c in (speed or {}).get("observed_crossings", []) if c["level"] == 0.5), None)
        q = q_star.get(group)
        print(f"{group} n={(speed or energy)['cases']} P({args.outcome}): {describe('v50', speed)}, measured crossing "
              f"{'-' if measured is None else f'{measured:.4g}'}; {describe('E50/(N_c E_break)', energy)}; "
              f"largest fragment below half at E/(N_c E_break) = {'-' if q is None else f'{q:.3g}'}")


if __name__ == "__main__":
    main()
