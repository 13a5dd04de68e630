#!/usr/bin/env python3
"""Write a LAMMPS data file and input script that run one aerobreak impact case in LAMMPS.

The case: a cluster of spheres (read from a file, used as oriented there) placed a small gap above
a flat wall z = 0 and sent at it with speed v along -z, with the aerobreak contact model (JKR +
visco-elastic damping + Mindlin + rolling + twisting resistance) mapped onto LAMMPS's
`pair_style granular` and `fix wall/gran granular` (LAMMPS 29 Sep 2021 update 2 = Debian
`lammps` 20220106). README.md in this folder derives every mapping and lists the differences.

Units. aerobreak's reduced units: primary diameter d = 1, primary mass m = 1 (density 6/pi),
time tau = sqrt(m/k_n) with k_n = E d / (3 (1 - nu^2)) = 1, so E = 3 (1 - nu^2). LAMMPS runs in
`units lj` with the same mass and time units and a length unit that is d / s: every length is
multiplied by s (default s = 1). With wall adhesion on, s is chosen (see `wall_length_scale`) so
that LAMMPS's wall pull-off test, which is not dimensionally consistent in this LAMMPS version,
lets go at the intended overlap. Forces come out multiplied by s, torques and energies by s^2.

Also `--single-contact pair|wall` writes a two-sphere (or sphere + wall) test used by
check_mapping.py. Python 3 standard library only.
"""
from __future__ import annotations

import argparse
import math
import os
import sys
from dataclasses import dataclass, field

PI = math.pi
X_TOUCH = (4.0 / 9.0) ** (1.0 / 3.0)  # a/a0 at delta = 0 (x^(3/2) = 2/3)
X_FORCE = 4.0 ** (-1.0 / 3.0)  # a/a0 where F = -F_c: LAMMPS's (force-controlled) break point
X_DISPLACEMENT = 6.0 ** (-2.0 / 3.0)  # a/a0 at delta = -delta_c: aerobreak's default break point


# ----------------------------------------------------------------------------------------------
# JKR in aerobreak's form (engine/contact/normal_jkr.hpp), in the variables x = a/a0 and
# D = delta R*/a0^2: D(x) = x^2 - (2/3) sqrt(x), F/F_c = 4 (x^3 - x^(3/2)).
# ----------------------------------------------------------------------------------------------

def overlap_ratio(x: float) -> float:
    return x * x - (2.0 / 3.0) * math.sqrt(x)


def radius_ratio(d: float) -> float:
    """Stable-branch x = a/a0 for D = delta R*/a0^2 (same closed form as the engine)."""
    s = math.sqrt(max(0.0, 1.0 / 1296.0 + d * d * d / 27.0))
    u = (1.0 / 36.0 + s) ** (1.0 / 3.0)
    v = d / (3.0 * u)
    m = (1.0 / 18.0) / (u * u + u * v + v * v)
    root_m = math.sqrt(m)
    inner = max(0.0, 2.0 * math.sqrt(2.0) / (3.0 * root_m) - 2.0 * m)
    y = 0.5 * (math.sqrt(2.0) * root_m + math.sqrt(inner))
    return y * y


def energy_primitive(x: float) -> float:
    return 0.4 * x ** 5 - (2.0 / 3.0) * x ** 3.5 + x * x / 6.0


@dataclass
class Contact:
    """Effective constants of one contact of identical spheres (or sphere + wall), aerobreak units."""

    radius: float  # R* (R for a wall)
    mass: float  # m* (m for a wall)
    modulus: float  # E*
    shear: float  # G*
    work: float  # w = 2 gamma

    @property
    def a0(self) -> float:  # eq 4
        return (9.0 * PI * self.work * self.radius ** 2 / (2.0 * self.modulus)) ** (1.0 / 3.0)

    @property
    def pull_off(self) -> float:  # eq 5, F_c
        return 1.5 * PI * self.work * self.radius

    @property
    def scale(self) -> float:  # a0^2 / R*
        return self.a0 ** 2 / self.radius

    @property
    def delta_eq(self) -> float:  # F = 0 at a = a0: delta = a0^2/(3R*)
        return self.scale / 3.0

    def delta_at(self, x: float) -> float:
        return self.scale * overlap_ratio(x)

    @property
    def delta_c(self) -> float:  # eq 3, aerobreak breaks at delta = -delta_c
        return -self.delta_at(X_DISPLACEMENT)

    @property
    def delta_f(self) -> float:  # break overlap magnitude of the force-controlled rule (F = -F_c)
        return -self.delta_at(X_FORCE)

    def force(self, delta: float) -> float:
        if self.work <= 0.0:
            return 4.0 / 3.0 * self.modulus * math.sqrt(self.radius) * max(delta, 0.0) ** 1.5
        x = radius_ratio(delta / self.scale)
        return 4.0 * self.pull_off * (x ** 3 - x ** 1.5)

    def contact_radius(self, delta: float) -> float:
        if self.work <= 0.0:
            return math.sqrt(self.radius * max(delta, 0.0))
        return self.a0 * radius_ratio(delta / self.scale)

    def hysteresis(self, x_break: float) -> float:
        """Work lost when a contact made at delta = 0 lets go at a/a0 = x_break (JKR, eq 2 path)."""
        return 4.0 * self.pull_off * self.scale * (energy_primitive(x_break) - energy_primitive(X_TOUCH))


@dataclass
class Model:
    """aerobreak's reduced-unit model parameters (command line)."""

    gamma: float = 0.001  # gamma / k_n (surface energy per surface)
    nu: float = 0.3
    mu: float = 0.5
    xi_crit: float = 0.01  # critical rolling displacement, units of d
    damping_a: float = 0.1  # A of eq 8, units of tau
    wall_adhesion: bool = False
    rolling: bool = True
    twisting: bool = True
    separation: str = "displacement"  # what aerobreak uses; LAMMPS pairs can only do "force"
    radius: float = 0.5  # primary radius (d = 1)

    @property
    def youngs(self) -> float:  # E = 3 (1 - nu^2): k_n = 1 (eq 7)
        return 3.0 * (1.0 - self.nu ** 2)

    @property
    def e_star(self) -> float:  # E* = E / (2 (1 - nu^2)) for identical materials (= 1.5)
        return self.youngs / (2.0 * (1.0 - self.nu ** 2))

    @property
    def g_star(self) -> float:  # G* = G / (2 (2 - nu)), G = E / (2 (1 + nu))
        return self.youngs / (2.0 * (1.0 + self.nu)) / (2.0 * (2.0 - self.nu))

    @property
    def mass(self) -> float:  # density 6/pi
        return (self.radius / 0.5) ** 3

    def pair(self) -> Contact:
        return Contact(self.radius / 2.0, self.mass / 2.0, self.e_star, self.g_star, 2.0 * self.gamma)

    def wall(self) -> Contact:
        w = 2.0 * self.gamma if self.wall_adhesion else 0.0
        return Contact(self.radius, self.mass, self.e_star, self.g_star, w)


# ----------------------------------------------------------------------------------------------
# The LAMMPS side
# ----------------------------------------------------------------------------------------------

def _bisect(f, lo: float, hi: float) -> float:
    flo = f(lo)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        fm = f(mid)
        if (fm > 0) == (flo > 0):
            lo, flo = mid, fm
        else:
            hi = mid
    return 0.5 * (lo + hi)


def wall_length_scale(radius: float, separation: str) -> float:
    """Length scale s (LAMMPS length units per d) that makes LAMMPS's wall JKR contact let go at
    the intended overlap.

    LAMMPS 29Sep2021 FixWallGran::pulloff_distance(R) computes a = cbrt(9 pi coh R / (4E)) where
    the pair style (and JKR) has R^2, and then lets the contact go when the centre-wall distance
    exceeds R + (a^2/R - 2 sqrt(pi coh a / E)). In JKR variables a/a0 = x_f R_L^(-1/3), where R_L
    is the particle radius in LAMMPS length units and x_f = 4^(-1/3), so the break overlap is
    -(a0^2/R) D(x_f R_L^(-1/3)): it depends on the length unit. Choosing R_L solves it:
    D(x_b) = -D(x_f) (force-controlled break, as LAMMPS's pair style) or D(x_b) = delta_c R/a0^2
    (aerobreak's displacement-controlled break), x_b = x_f R_L^(-1/3). Independent of gamma, E.
    """
    target = -overlap_ratio(X_FORCE) if separation == "force" else -overlap_ratio(X_DISPLACEMENT)
    x_b = _bisect(lambda x: overlap_ratio(x) - target, X_TOUCH, 4.0)
    r_lammps = (X_FORCE / x_b) ** 3
    return r_lammps / radius


@dataclass
class LammpsModel:
    """pair_coeff / fix wall/gran arguments of a Model, in LAMMPS units (length unit d/s)."""

    model: Model
    s: float = 1.0
    pair_args: str = ""
    wall_args: str = ""
    cutoff: float = 0.0  # pair_style granular global cutoff (LAMMPS length)
    notes: list = field(default_factory=list)

    @classmethod
    def build(cls, model: Model, s: float, r_max: float | None = None, mu_override: float | None = None) -> "LammpsModel":
        m = model
        mu = m.mu if mu_override is None else mu_override
        p, w = m.pair(), m.wall()
        lm = cls(model=m, s=s)
        # E enters LAMMPS as force/length^2 (x 1/s); gamma as energy/length^2 (x 1); eta_n0 of
        # damping viscoelastic as 1/(time length) (x 1/s); k_t of mindlin as force/length^2.
        e_pair = m.youngs / s
        e_star_l = m.e_star / s
        kt = 8.0 * m.g_star / s
        eta_pair = 2.0 * m.damping_a * e_star_l / p.mass
        eta_wall = 2.0 * m.damping_a * e_star_l / w.mass
        tang = f"tangential mindlin {kt:.12g} 0.0 {mu:.12g}"
        roll_pair = roll_wall = ""
        if m.rolling:
            # torque = R* k_roll xi (LAMMPS) vs k_r xi (aerobreak): k_roll = 4 F_c / R* (force/length,
            # unchanged by s); limit R* mu_roll (F_ne + 2F_c) = 4 F_c xi_crit at F_ne = 0.
            roll_pair = (f" rolling sds {4.0 * p.pull_off / p.radius:.12g} 0.0 "
                         f"{2.0 * m.xi_crit / p.radius:.12g}")
            if m.wall_adhesion:
                roll_wall = (f" rolling sds {4.0 * w.pull_off / w.radius:.12g} 0.0 "
                             f"{2.0 * m.xi_crit / w.radius:.12g}")
        twist = " twisting marshall" if m.twisting else ""
        lm.pair_args = (f"jkr {e_pair:.12g} {eta_pair:.12g} {m.nu:.12g} {m.gamma:.12g} damping viscoelastic "
                        f"{tang}{roll_pair}{twist}")
        # fix wall/gran granular uses E_eff = E / (2 (1 - nu)) (should be 1 - nu^2): give it
        # nu = 0 and E = 2 E*, which is exact either way. k_t is given explicitly (its NULL
        # default is wrong in this version).
        e_wall = 2.0 * e_star_l
        if m.wall_adhesion:
            normal_wall = f"jkr {e_wall:.12g} {eta_wall:.12g} 0.0 {m.gamma:.12g}"
        else:
            normal_wall = f"hertz/material {e_wall:.12g} {eta_wall:.12g} 0.0"
        lm.wall_args = f"{normal_wall} damping viscoelastic {tang}{roll_wall}{twist}"
        r_max = m.radius if r_max is None else r_max
        big = Contact(r_max / 2.0, 1.0, m.e_star, m.g_star, 2.0 * m.gamma)
        lm.cutoff = s * (2.0 * r_max + 1.001 * big.delta_f)
        if m.separation == "displacement":
            lm.notes.append("LAMMPS pair_style granular jkr lets pairs go at the force-controlled point "
                            "a = a0/4^(1/3) (delta = -0.1323 a0^2/R*), not at -delta_c = -0.2752 a0^2/R*")
        return lm


def auto_length_scale(model: Model) -> float:
    return wall_length_scale(model.radius, model.separation) if model.wall_adhesion else 1.0


# ----------------------------------------------------------------------------------------------
# Cluster files
# ----------------------------------------------------------------------------------------------

def _is_number(t: str) -> bool:
    try:
        float(t)
        return True
    except ValueError:
        return False


def read_cluster(path: str) -> list[tuple[float, float, float, float | None]]:
    """Spheres as (x, y, z, radius or None), aerobreak units (d = 1).

    Plain: one sphere a line, `x y z [radius]`; blank lines and lines starting with # skipped.
    XYZ / extended XYZ: a count line, a comment line (Properties=... is honoured for pos and
    radius columns), then `species x y z [...]` lines.
    """
    with open(path) as f:
        lines = f.read().splitlines()
    body = [ln for ln in lines if ln.strip() and not ln.lstrip().startswith("#")]
    spheres = []
    first = body[0].split() if body else []
    if len(first) == 1 and first[0].isdigit():
        count = int(first[0])
        idx = lines.index(next(ln for ln in lines if ln.strip() == first[0]))
        comment = lines[idx + 1] if idx + 1 < len(lines) else ""
        pos_col, rad_col = None, None
        if "Properties=" in comment:
            props = comment.split("Properties=")[1].split()[0].split(":")
            col = 0
            for name, kind, n in zip(props[0::3], props[1::3], props[2::3]):
                if name == "pos":
                    pos_col = col
                if name.lower() in ("radius", "radii"):
                    rad_col = col
                col += int(n)
        for ln in lines[idx + 2: idx + 2 + count]:
            t = ln.split()
            if pos_col is None:
                off = 0 if _is_number(t[0]) else 1
                x, y, z = map(float, t[off:off + 3])
                r = float(t[off + 3]) if len(t) > off + 3 and _is_number(t[off + 3]) else None
            else:
                x, y, z = map(float, t[pos_col:pos_col + 3])
                r = float(t[rad_col]) if rad_col is not None else None
            spheres.append((x, y, z, r))
    else:
        for ln in body:
            t = ln.split()
            x, y, z = map(float, t[:3])
            r = float(t[3]) if len(t) > 3 else None
            spheres.append((x, y, z, r))
    if not spheres:
        raise ValueError(f"{path}: no spheres")
    return spheres


# ----------------------------------------------------------------------------------------------
# Writers
# ----------------------------------------------------------------------------------------------

def write_data(path: str, atoms, s: float, box, title: str) -> None:
    """atoms: (x, y, z, radius) in aerobreak units; written in LAMMPS units (x s)."""
    density = 6.0 / PI / s ** 3  # m = 1 for d = 1
    (xlo, xhi), (ylo, yhi), (zlo, zhi) = box
    with open(path, "w") as f:
        f.write(f"{title}\n\n{len(atoms)} atoms\n1 atom types\n\n")
        f.write(f"{xlo * s:.10g} {xhi * s:.10g} xlo xhi\n{ylo * s:.10g} {yhi * s:.10g} ylo yhi\n"
                f"{zlo * s:.10g} {zhi * s:.10g} zlo zhi\n\nAtoms # sphere\n\n")
        for i, (x, y, z, r) in enumerate(atoms, 1):
            f.write(f"{i} 1 {2.0 * r * s:.12g} {density:.12g} {x * s:.12g} {y * s:.12g} {z * s:.12g}\n")


def bounding_box(atoms, margin: float):
    lo = [min(a[k] - a[3] for a in atoms) - margin for k in range(3)]
    hi = [max(a[k] + a[3] for a in atoms) + margin for k in range(3)]
    lo[2] = min(lo[2], -margin)
    return list(zip(lo, hi))


def header(lm: LammpsModel, data_file: str, newton: str, atom_map: bool) -> str:
    m, s = lm.model, lm.s
    lines = [
        "# generated by tests/peer/lammps/make_lammps_input.py (aerobreak -> LAMMPS peer case)",
        f"# aerobreak units: d = 1, m = 1, tau = sqrt(m/k_n); LAMMPS length unit = d/{s:.10g}",
        f"# gamma/k_n = {m.gamma:g}, nu = {m.nu:g}, mu = {m.mu:g}, xi_crit = {m.xi_crit:g} d, A = {m.damping_a:g} tau,",
        f"# wall adhesion {'on' if m.wall_adhesion else 'off'}, rolling {'on' if m.rolling else 'off'}, "
        f"twisting {'on' if m.twisting else 'off'}, separation (aerobreak) {m.separation}",
    ]
    lines += [f"# NOTE: {n}" for n in lm.notes]
    lines += [
        "units           lj",
        "atom_style      sphere",
    ]
    if atom_map:
        lines.append("atom_modify     map array")
    lines += [
        "dimension       3",
        "boundary        m m m",
        f"newton          {newton}",
        "comm_modify     vel yes",
        f"read_data       {data_file}",
        f"pair_style      granular {lm.cutoff:.10g}",
        f"pair_coeff      * * {lm.pair_args}",
        f"neighbor        {0.1 * s:.10g} bin",
        "neigh_modify    every 1 delay 0 check yes",
    ]
    return "\n".join(lines) + "\n"


def wall_fix(lm: LammpsModel, group: str = "all") -> str:
    return f"fix             wall {group} wall/gran granular {lm.wall_args} zplane 0.0 NULL\n"


def write_case(args, model: Model, s: float) -> tuple[str, str]:
    spheres = read_cluster(args.cluster)
    radii = [r if r is not None else 0.5 for (_, _, _, r) in spheres]
    if max(radii) > 1.01 * min(radii):
        print("warning: polydisperse cluster; the damping, rolling and wall-break mappings use the "
              "median radius", file=sys.stderr)
    model.radius = sorted(radii)[len(radii) // 2]
    if args.length_scale == "auto":
        s = auto_length_scale(model)
    lm = LammpsModel.build(model, s, r_max=max(radii))
    # place: centroid at x = y = 0, lowest sphere surface `gap` above the wall
    n = len(spheres)
    cx = sum(p[0] for p in spheres) / n
    cy = sum(p[1] for p in spheres) / n
    zmin = min(p[2] - r for p, r in zip(spheres, radii))
    atoms = [(x - cx, y - cy, z - zmin + args.gap, r) for (x, y, z, _), r in zip(spheres, radii)]
    box = bounding_box(atoms, 1.0)
    os.makedirs(args.out, exist_ok=True)
    data = os.path.join(args.out, "cluster.data")
    script = os.path.join(args.out, "in.impact")
    write_data(data, atoms, s, box, f"aerobreak peer case from {os.path.basename(args.cluster)}")
    with open(script, "w") as f:
        f.write(header(lm, "cluster.data", args.newton, atom_map=False))
        f.write("fix             integrate all nve/sphere\n")
        f.write(wall_fix(lm))
        f.write(f"velocity        all set 0.0 0.0 {-args.speed * s:.12g} units box\n")
        f.write(f"timestep        {args.dt:.12g}\n")
        f.write("thermo_style    custom step atoms ke\n")
        f.write(f"thermo          {args.thermo}\n")
        f.write(f"run             {args.steps}\n")
    return data, script


def write_single_contact(args, model: Model, s: float) -> tuple[str, str]:
    """Two spheres along z (pair) or one sphere above the wall (wall), at overlap --overlap,
    approaching at relative speed --speed (or pulled apart at --pull with fix move). Thermo
    prints separation (aerobreak units: overlap delta), forces and velocities every --thermo steps.
    """
    if args.length_scale == "auto":
        s = auto_length_scale(model)
    lm = LammpsModel.build(model, s)
    r = model.radius
    d = args.overlap
    if args.single_contact == "pair":
        atoms = [(0.0, 0.0, 5.0, r), (0.0, 0.0, 5.0 + 2.0 * r - d, r)]
    else:
        atoms = [(0.0, 0.0, r - d, r)]
    box = bounding_box(atoms, 2.0)
    os.makedirs(args.out, exist_ok=True)
    data = os.path.join(args.out, "contact.data")
    script = os.path.join(args.out, "in.contact")
    write_data(data, atoms, s, box, f"aerobreak single-contact test ({args.single_contact})")
    top = len(atoms)
    with open(script, "w") as f:
        f.write(header(lm, "contact.data", args.newton, atom_map=True))
        if args.single_contact == "wall":
            f.write(wall_fix(lm))
            f.write(f"variable        delta equal ({r * s:.12g}-z[1])/{s:.12g}\n")
        else:
            f.write(f"variable        delta equal ({2 * r * s:.12g}-(z[2]-z[1]))/{s:.12g}\n")
        f.write(f"group           top id {top}\n")
        if args.pull is not None:
            f.write(f"fix             pull top move linear 0.0 0.0 {args.pull * s:.12g}\n")
            if top == 2:
                f.write("group           bottom id 1\nfix             hold bottom move linear 0.0 0.0 0.0\n")
        else:
            f.write("fix             integrate all nve/sphere\n")
            f.write(f"velocity        top set 0.0 0.0 {-args.speed * s:.12g} units box\n")
        f.write(f"variable        fz equal fz[{top}]/{s:.12g}\n")
        f.write(f"variable        vz equal vz[{top}]/{s:.12g}\n")
        f.write(f"timestep        {args.dt:.12g}\n")
        f.write("thermo_style    custom step v_delta v_fz v_vz\n")
        f.write("thermo_modify   format float %.12g\n")
        f.write(f"thermo          {args.thermo}\n")
        f.write(f"run             {args.steps}\n")
    return data, script


def model_from_args(a) -> Model:
    return Model(gamma=a.gamma_over_kn, nu=a.nu, mu=a.mu, xi_crit=a.xi_crit, damping_a=a.damping_A,
                 wall_adhesion=a.wall_adhesion == "on", rolling=a.rolling == "on", twisting=a.twisting == "on",
                 separation=a.separation)


def parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("cluster", nargs="?", help="cluster file (x y z [radius] lines, or (extended) XYZ), units of d")
    p.add_argument("--out", default="lammps_case", help="output folder (data file + input script)")
    p.add_argument("--gamma-over-kn", type=float, default=0.001)
    p.add_argument("--nu", type=float, default=0.3)
    p.add_argument("--mu", type=float, default=0.5)
    p.add_argument("--xi-crit", type=float, default=0.01, help="critical rolling displacement (d)")
    p.add_argument("--damping-A", type=float, default=0.1, help="visco-elastic A (tau); 0 = no damping")
    p.add_argument("--speed", type=float, default=1.0, help="impact speed (d/tau), along -z")
    p.add_argument("--dt", type=float, default=0.02, help="time step (tau)")
    p.add_argument("--steps", type=int, default=20000)
    p.add_argument("--thermo", type=int, default=1000)
    p.add_argument("--gap", type=float, default=0.05, help="lowest sphere surface above the wall (d)")
    p.add_argument("--wall-adhesion", choices=["on", "off"], default="off")
    p.add_argument("--rolling", choices=["on", "off"], default="on")
    p.add_argument("--twisting", choices=["on", "off"], default="on")
    p.add_argument("--separation", choices=["displacement", "force"], default="displacement",
                   help="aerobreak's JKR break rule; LAMMPS pairs always use 'force' (see README); "
                        "the wall's break follows this via the length scale when wall adhesion is on")
    p.add_argument("--length-scale", default="auto",
                   help="LAMMPS length units per d: 'auto' (1, or the wall pull-off fix when wall "
                        "adhesion is on) or a number")
    p.add_argument("--newton", choices=["on", "off"], default="off")
    p.add_argument("--single-contact", choices=["pair", "wall"], help="write a 2-sphere / sphere-wall test instead")
    p.add_argument("--overlap", type=float, default=-0.01, help="single contact: initial overlap (d); < 0 = gap")
    p.add_argument("--pull", type=float, default=None,
                   help="single contact: move the top sphere away at this speed (d/tau) with fix move")
    p.add_argument("--radius", type=float, default=0.5, help="single contact: sphere radius (d)")
    return p


def main(argv=None) -> int:
    a = parser().parse_args(argv)
    model = model_from_args(a)
    s = 1.0 if a.length_scale == "auto" else float(a.length_scale)
    if a.single_contact:
        model.radius = a.radius
        data, script = write_single_contact(a, model, s)
    else:
        if not a.cluster:
            print("a cluster file is required (or --single-contact)", file=sys.stderr)
            return 2
        data, script = write_case(a, model, s)
    print(f"data = {data}")
    print(f"input = {script}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
