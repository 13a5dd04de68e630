#!/usr/bin/env python3
"""Check numerically that LAMMPS, with the coefficients of make_lammps_input.py, reproduces
aerobreak's contact laws for one sphere-sphere and one sphere-wall contact.

Every LAMMPS number comes from running /usr/bin/lmp (or $LMP) on a one- or two-sphere input built
from the same mapping code as the benchmark input (make_lammps_input.LammpsModel), and is converted
back to aerobreak units (d = 1, m = 1, tau = sqrt(m/k_n)). "ours" is aerobreak's analytic value
(engine/contact/*.hpp formulas, re-derived in make_lammps_input.Contact). Rows marked (law) are
known, documented differences between the two models, not mapping errors. Standard library only.
"""
from __future__ import annotations

import argparse
import math
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import make_lammps_input as mk  # noqa: E402

LMP = os.environ.get("LMP", "lmp")


class Runner:
    def __init__(self, model: mk.Model, s: float, workdir: str, keep: bool):
        self.model, self.s, self.workdir, self.keep = model, s, workdir, keep
        self.count = 0

    def run(self, kind: str, overlap: float, body: str, mu: float | None = None, s: float | None = None,
            model: mk.Model | None = None) -> tuple[list[list[float]], dict[str, float]]:
        """One LAMMPS run: `kind` pair (spheres 1 below 2 on the z axis) or wall (sphere 1 above
        z = 0), initial overlap `overlap` (aerobreak units). `body` is LAMMPS text with {s}
        placeholders. Returns (thermo rows, RESULT prints)."""
        m = model or self.model
        s = self.s if s is None else s
        lm = mk.LammpsModel.build(m, s, mu_override=mu)
        r = m.radius
        if kind == "pair":
            atoms = [(0.0, 0.0, 5.0, r), (0.0, 0.0, 5.0 + 2.0 * r - overlap, r)]
        else:
            atoms = [(0.0, 0.0, r - overlap, r)]
        self.count += 1
        d = os.path.join(self.workdir, f"run{self.count:02d}_{kind}")
        os.makedirs(d, exist_ok=True)
        mk.write_data(os.path.join(d, "c.data"), atoms, s, mk.bounding_box(atoms, 2.0), "check_mapping")
        text = mk.header(lm, "c.data", "off", atom_map=True)
        if kind == "wall":
            text += mk.wall_fix(lm)
            text += f"variable delta equal ({r * s!r}-z[1])/{s!r}\n"
        else:
            text += f"variable delta equal ({2 * r * s!r}-(z[2]-z[1]))/{s!r}\n"
        top = len(atoms)
        text += f"group top id {top}\n"
        if kind == "pair":
            text += "group bottom id 1\n"
        text += "compute tq all property/atom tqx tqy tqz\n"
        text += body.format(s=repr(s), top=top, r=r, zt=atoms[-1][2] * s, zb=atoms[0][2] * s)
        path = os.path.join(d, "in.check")
        with open(path, "w") as f:
            f.write(text)
        out = subprocess.run([LMP, "-in", "in.check", "-log", "none", "-echo", "none", "-nocite"], cwd=d,
                             capture_output=True, text=True, env={**os.environ, "OMP_NUM_THREADS": "1"})
        if out.returncode != 0 or "ERROR" in out.stdout:
            raise RuntimeError(f"lmp failed in {d}:\n{out.stdout[-2000:]}\n{out.stderr[-2000:]}")
        rows, results, in_thermo = [], {}, False
        for ln in out.stdout.splitlines():
            t = ln.split()
            if t and t[0] == "Step":
                in_thermo = True
                continue
            if ln.startswith("Loop time"):
                in_thermo = False
            if in_thermo and t and t[0].lstrip("-").isdigit():
                rows.append([float(v) for v in t])
            if t and t[0] == "RESULT":
                results[t[1]] = float(t[2])
        return rows, results


THERMO = ("variable fz equal fz[{top}]/{s}\nvariable vz equal vz[{top}]/{s}\n"
          "thermo_style custom step v_delta v_fz v_vz\nthermo_modify format float %.14g\n")


TORQUE = ("variable tx equal c_tq[{top}][1]\nvariable ty equal c_tq[{top}][2]\nvariable tz equal c_tq[{top}][3]\n"
          "thermo_style custom step v_tx v_ty v_tz\nthermo_modify format float %.14g\n")


def rel(a: float, b: float) -> float:
    return abs(a - b) / abs(a) if a != 0 else abs(b)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--gamma-over-kn", type=float, default=0.01)
    ap.add_argument("--nu", type=float, default=0.3)
    ap.add_argument("--mu", type=float, default=0.5)
    ap.add_argument("--xi-crit", type=float, default=0.01)
    ap.add_argument("--damping-A", type=float, default=0.5, help="A for the damping and settling checks")
    ap.add_argument("--separation", choices=["displacement", "force"], default="displacement")
    ap.add_argument("--keep", help="keep the LAMMPS runs in this folder")
    a = ap.parse_args()

    model = mk.Model(gamma=a.gamma_over_kn, nu=a.nu, mu=a.mu, xi_crit=a.xi_crit, damping_a=0.0,
                     wall_adhesion=True, rolling=True, twisting=True, separation=a.separation)
    damped = mk.Model(**{**model.__dict__, "damping_a": a.damping_A})
    s = mk.auto_length_scale(model)
    pair, wall = model.pair(), model.wall()
    workdir = a.keep or tempfile.mkdtemp(prefix="lammps_check_")
    run = Runner(model, s, workdir, bool(a.keep)).run
    table: list[tuple[str, float, float, str]] = []

    def row(name, ours, lammps, note=""):
        table.append((name, ours, lammps, note))

    # 1. elastic JKR force at rest, three overlaps (run 0)
    for kind, c in (("pair", pair), ("wall", wall)):
        for f in (2.0, 1.0, 0.3):
            delta = f * c.delta_eq
            _, res = run(kind, delta, "run 0\nprint \"RESULT F $(fz[{top}]/{s}:%.14g)\"\n")
            row(f"{kind}: F_n at delta = {f:g} delta_eq", c.force(delta), res["F"])

    # 2. equilibrium overlap: from touching at rest, settle with visco-elastic damping
    for kind, c in (("pair", damped.pair()), ("wall", damped.wall())):
        dt, n = 0.002, 50000
        rows, _ = run(kind, 1e-6, "fix integrate all nve/sphere\n" + THERMO + f"timestep {dt}\nthermo 1000\nrun {n}\n",
                      model=damped)
        row(f"{kind}: delta_eq = a0^2/(3R*) after settling (A = {a.damping_A:g})", c.delta_eq, rows[-1][1],
            f"|v| at end {abs(rows[-1][3]):.1e}")

    # 3. pull-off at prescribed slow separation (displacement control), no damping
    pull, dt = 2e-4, 0.005
    for kind, c, s_run, label in (("pair", pair, s, ""), ("wall", wall, s, ""), ("wall", wall, 1.0, " [s = 1, raw LAMMPS]")):
        n = int(1.2 * (c.delta_eq + c.delta_c) / (pull * dt))
        body = ("fix hold bottom move linear 0.0 0.0 0.0\n" if kind == "pair" else "")
        body += f"fix pull top move linear 0.0 0.0 {pull * s_run!r}\n" + THERMO + f"timestep {dt}\nthermo 10\nrun {n}\n"
        rows, _ = run(kind, c.delta_eq, body, s=s_run)
        live = [(r_[1], r_[2]) for r_ in rows if r_[2] != 0.0]  # (delta, force on the top sphere, > 0 repulsive)
        fmin = min(f for _, f in live)
        dbreak = min(d for d, _ in live)
        if not label:
            worst = max(abs(f - c.force(d)) for d, f in live)
            row(f"{kind}: max |F_LAMMPS - F_ours| along the pull path / F_c", 0.0, worst / c.pull_off,
                "absolute, in units of F_c")
            row(f"{kind}: largest tension = F_c = 1.5 pi w R*", c.pull_off, -fmin)
        if kind == "pair":
            notes = ("(law) LAMMPS pairs: force rule only", "")
        elif label:
            notes = ("LAMMPS bug, see README", "LAMMPS bug, see README")
        else:  # the length scale s puts the wall break where --separation says
            notes = ("", "not targeted") if model.separation == "displacement" else ("not targeted", "")
        row(f"{kind}: break overlap{label} vs ours (-delta_c)", -c.delta_c, dbreak, notes[0])
        row(f"{kind}: break overlap{label} vs force rule (-delta_f)", -c.delta_f, dbreak, notes[1])

    # 4. damping coefficient: F(v) - F(0) at delta_eq (run 0 twice)
    for kind, c in (("pair", damped.pair()), ("wall", damped.wall())):
        u = 0.01
        body = ("run 0\nvariable f0 equal $(fz[{top}]:%.14g)\n"
                f"velocity top set 0.0 0.0 {-u * s!r} units box\nrun 0\n"
                "print \"RESULT eta $((fz[{top}]-v_f0)/(" + f"{u * s!r}" + "):%.14g)\"\n")
        _, res = run(kind, c.delta_eq, body, model=damped)
        eta = 2.0 * a.damping_A * c.modulus * c.contact_radius(c.delta_eq)
        row(f"{kind}: eta_n = 2 A E* a at delta_eq", eta, res["eta"])

    # 5. tangential stiffness 8 G* a: one step of prescribed sliding at delta_eq
    for kind, c in (("pair", pair), ("wall", wall)):
        u, dt = 0.01, 0.001
        body = ("fix hold bottom move linear 0.0 0.0 0.0\n" if kind == "pair" else "")
        body += (f"fix slide top move linear {u * s!r} 0.0 0.0\ntimestep {dt}\nrun 1\n"
                 "print \"RESULT kt $(-fx[{top}]/(" + f"{u * s * dt!r}" + "):%.14g)\"\n")
        _, res = run(kind, c.delta_eq, body)
        row(f"{kind}: k_t = 8 G* a at delta_eq", 8.0 * c.shear * c.contact_radius(c.delta_eq), res["kt"])

    # 6. twisting: stiffness k_t a^2/2 = 4 G* a^3 (one step) and limit (2/3) mu a (F_n + 2F_c)
    for kind, c in (("pair", pair), ("wall", wall)):
        a_eq = c.contact_radius(c.delta_eq)
        k_tw = 4.0 * c.shear * a_eq ** 3
        limit = 2.0 / 3.0 * model.mu * a_eq * 2.0 * c.pull_off
        dt = 0.001
        omega = limit / k_tw / (50 * dt)
        body = ("fix hold bottom move linear 0.0 0.0 0.0\n" if kind == "pair" else "")
        body += (f"fix spin top move rotate 0.0 0.0 {{zt}} 0.0 0.0 1.0 {2 * math.pi / omega!r}\n" + TORQUE +
                 f"timestep {dt}\nthermo 1\nrun 200\n")
        rows, _ = run(kind, c.delta_eq, body)
        res = {"k": abs(rows[1][3]) / (s * s * omega * dt), "M": abs(rows[-1][3]) / (s * s)}
        row(f"{kind}: twisting stiffness 4 G* a^3 at delta_eq", k_tw, res["k"])
        row(f"{kind}: twisting limit (2/3) mu a (F_n + 2F_c) at delta_eq", limit, res["M"])

    # 7. rolling: stiffness M/xi (one step) at delta_eq and at 0.3 delta_eq, and the limit
    for kind, c in (("pair", pair), ("wall", wall)):
        dt = 0.001
        for f in (1.0, 0.3):
            delta = f * c.delta_eq
            x = c.contact_radius(delta) / c.a0
            k_r = 4.0 * c.pull_off * x ** 1.5
            omega = model.xi_crit / c.radius / (50 * dt) / (2.0 if kind == "pair" else 1.0)
            period = 2 * math.pi / omega
            body = ""
            if kind == "pair":
                body += f"fix spinb bottom move rotate 0.0 0.0 {{zb}} -1.0 0.0 0.0 {period!r}\n"
            body += f"fix spin top move rotate 0.0 0.0 {{zt}} 1.0 0.0 0.0 {period!r}\n" + TORQUE
            body += f"timestep {dt}\nthermo 1\nrun {300 if f == 1.0 else 1}\n"
            xi_step = c.radius * omega * dt * (2.0 if kind == "pair" else 1.0)  # aerobreak units
            # the wall has no spin of its own: sliding would add a tangential torque, so mu = 0 there
            rows, _ = run(kind, delta, body, mu=0.0 if kind == "wall" else None)
            res = {"k": abs(rows[1][1]) / (s * s * xi_step), "M": abs(rows[-1][1]) / (s * s)}
            note = "" if f == 1.0 else "(law) LAMMPS k_roll is constant"
            row(f"{kind}: rolling stiffness 4 F_c (a/a0)^1.5 at delta = {f:g} delta_eq", k_r, res["k"], note)
            if f == 1.0:
                row(f"{kind}: rolling limit k_r xi_crit at delta_eq", k_r * model.xi_crit, res["M"])

    # 8. restitution of a sphere dropped on the adhesive wall, no damping
    v_stick = math.sqrt(2.0 * wall.hysteresis(mk.X_DISPLACEMENT) / wall.mass)
    for k in (1.2, 2.0, 4.0):
        v = k * v_stick
        dt = 0.0005
        gap = 0.002
        n = int((gap / v + 30.0) / dt)
        body = (f"fix integrate all nve/sphere\nvelocity top set 0.0 0.0 {-v * s!r} units box\n" + THERMO +
                f"timestep {dt}\nthermo {n}\nrun {n}\n")
        rows, _ = run("wall", -gap, body)
        e_lmp = rows[-1][3] / v
        x_break = mk.X_DISPLACEMENT if a.separation == "displacement" else mk.X_FORCE
        e_ours = math.sqrt(1.0 - wall.hysteresis(x_break) / (0.5 * wall.mass * v * v))
        e_force = math.sqrt(1.0 - wall.hysteresis(mk.X_FORCE) / (0.5 * wall.mass * v * v))
        row(f"wall: restitution at v = {v:.4g} ({k:g} v_stick)", e_ours, e_lmp,
            f"force-rule e = {e_force:.4f}" if a.separation == "displacement" else "")

    # 8b. lever arms: spin both spheres (or the one on the wall) about x, one step, no slip limit
    for kind, c in (("pair", pair), ("wall", wall)):
        omega, dt = 0.01, 0.001
        period = 2 * math.pi / omega
        body = (f"fix spinb bottom move rotate 0.0 0.0 {{zb}} 1.0 0.0 0.0 {period!r}\n" if kind == "pair" else "")
        body += (f"fix spin top move rotate 0.0 0.0 {{zt}} 1.0 0.0 0.0 {period!r}\n" + TORQUE.replace(
            "step v_tx", "step v_fy v_tx").replace("variable tx", "variable fy equal fy[{top}]\nvariable tx") +
                 f"timestep {dt}\nthermo 1\nrun 1\n")
        no_roll = mk.Model(**{**model.__dict__, "rolling": False})  # a spinning sphere also rolls on the wall
        rows, _ = run(kind, c.delta_eq, body, mu=1e6, model=no_roll)
        f_t, m_t = abs(rows[1][1]) / s, abs(rows[1][2]) / (s * s)
        k_t = 8.0 * c.shear * c.contact_radius(c.delta_eq)
        spheres = 2.0 if kind == "pair" else 1.0
        ours = model.radius - c.delta_eq / spheres
        lever = "R - delta/2" if kind == "pair" else "R - delta"
        row(f"{kind}: lever arm in the slip velocity (ours {lever})", ours,
            f_t / (k_t * omega * dt) / spheres, "(law) LAMMPS uses R")
        row(f"{kind}: lever arm of the tangential torque (ours {lever})", ours, m_t / f_t,
            "same as ours" if kind == "pair" else "(law) LAMMPS uses R")

    # 9. wall without adhesion (hertz/material, as with --wall-adhesion off): force, damping, k_t
    plain = mk.Model(**{**damped.__dict__, "wall_adhesion": False})
    hw = plain.wall()
    s_plain = mk.auto_length_scale(plain)
    for delta in (0.01, 0.05):
        _, res = run("wall", delta, "run 0\nprint \"RESULT F $(fz[{top}]/{s}:%.14g)\"\n", s=s_plain, model=plain)
        row(f"wall, no adhesion: Hertz F_n at delta = {delta:g}", hw.force(delta), res["F"])
    delta, u = 0.05, 0.01
    body = ("run 0\nvariable f0 equal $(fz[{top}]:%.14g)\n"
            f"velocity top set 0.0 0.0 {-u * s_plain!r} units box\nrun 0\n"
            "print \"RESULT eta $((fz[{top}]-v_f0)/(" + f"{u * s_plain!r}" + "):%.14g)\"\n")
    _, res = run("wall", delta, body, s=s_plain, model=plain)
    row(f"wall, no adhesion: eta_n = 2 A E* a at delta = {delta:g}",
        2.0 * a.damping_A * hw.modulus * hw.contact_radius(delta), res["eta"])
    dt = 0.001
    body = (f"fix slide top move linear {u * s_plain!r} 0.0 0.0\ntimestep {dt}\nrun 1\n"
            "print \"RESULT kt $(-fx[{top}]/(" + f"{u * s_plain * dt!r}" + "):%.14g)\"\n")
    _, res = run("wall", delta, body, s=s_plain, model=plain)
    row(f"wall, no adhesion: k_t = 8 G* a at delta = {delta:g}", 8.0 * hw.shear * hw.contact_radius(delta), res["kt"],
        "tangential damping off: x_gamma,t = 0")

    # report
    print(f"# aerobreak <-> LAMMPS contact mapping check (lmp = {LMP})")
    print(f"# gamma/k_n = {model.gamma:g}, nu = {model.nu:g}, mu = {model.mu:g}, xi_crit = {model.xi_crit:g} d, "
          f"separation = {model.separation}, LAMMPS length scale s = {s:.6f} LAMMPS units per d")
    print(f"# pair: R* = {pair.radius:g}, a0 = {pair.a0:.6f}, F_c = {pair.pull_off:.6g}, delta_eq = {pair.delta_eq:.6g}, "
          f"delta_c = {pair.delta_c:.6g}, delta_f = {pair.delta_f:.6g}")
    print(f"# wall: R* = {wall.radius:g}, a0 = {wall.a0:.6f}, F_c = {wall.pull_off:.6g}, delta_eq = {wall.delta_eq:.6g}, "
          f"delta_c = {wall.delta_c:.6g}, delta_f = {wall.delta_f:.6g}")
    w = max(len(t[0]) for t in table)
    print(f"{'quantity':<{w}}  {'ours (analytic)':>16}  {'LAMMPS':>16}  {'rel. diff':>9}  note")
    for name, ours, lmp, note in table:
        d = abs(lmp - ours) if "/ F_c" in name else rel(ours, lmp)
        print(f"{name:<{w}}  {ours:>16.9g}  {lmp:>16.9g}  {d:>9.2e}  {note}")
    if a.keep:
        print(f"# LAMMPS runs kept in {workdir}")
    else:
        shutil.rmtree(workdir, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
