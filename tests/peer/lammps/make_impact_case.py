"""Writes the aerobreak impact case (JSON, schemas/case.schema.json) that runs the cluster and model
`aerobreak bench --export` wrote, for as many steps, through `aerobreak impact`.

usage: make_impact_case.py BENCH_JSON CLUSTER_XYZ > case.json
The cluster is read from the file (relaxed again, as every case's cluster is, and turned by the
case's orientation seed); the wall has no adhesion and JKR contacts let go at F = -F_c (the
LAMMPS rule), as in compare.sh.
"""
import json
import os
import sys

bench = json.load(open(sys.argv[1]))
damping = ({"law": "viscoelastic", "dissipative_time": bench["dissipative_time"]}
           if bench["dissipative_time"] > 0 else {"law": "none"})
rolling = {"enabled": bench.get("rolling", True)}
if rolling["enabled"]:
    rolling["critical_displacement"] = bench["critical_rolling"]
case = {
    "name": "compare.sh: the bench cluster of %d primaries through aerobreak impact" % bench["primaries"],
    "units": "reduced",
    "cluster": {"file": {"path": os.path.abspath(sys.argv[2])}},
    "material": {"gamma_over_kn": bench["gamma_over_kn"], "poisson_ratio": bench["poisson_ratio"]},
    "model": {"normal": "jkr", "separation": bench["separation"], "damping": damping, "tangential": True,
              "friction": bench["friction"], "rolling": rolling, "twisting": bench.get("twisting", True)},
    "impact": {"speed": bench["speed"], "angle": 0, "orientation_seed": bench["seed"] + 1, "gap": 0.01},
    "wall": {"adhesive": bench["wall_adhesion"]},
    "run": {"time_step": bench["time_step"], "time_limit": bench["time_step"] * bench["steps"]},
}
json.dump(case, sys.stdout, indent=2)
print()
