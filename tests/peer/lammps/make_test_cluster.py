#!/usr/bin/env python3
"""A random branched-chain test cluster of N spheres of diameter 1 (standard library only).

Each new sphere is bonded to an existing one (the previous sphere with probability --chain, a
random earlier one otherwise) in a random direction, at centre distance --bond (< 1: bonds start
at an overlap, e.g. 1 - delta_eq so that JKR contacts start near equilibrium); directions that
bring it closer than --bond to any other sphere are redrawn. Not a relaxed fractal aggregate:
only a stand-in with chain-like, branched connectivity for speed benchmarks. Writes `x y z` lines.
"""
import argparse
import math
import random


def main() -> None:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("n", type=int)
    p.add_argument("out")
    p.add_argument("--bond", type=float, default=0.985, help="centre distance of bonded spheres (d)")
    p.add_argument("--chain", type=float, default=0.7, help="probability of continuing from the last sphere")
    p.add_argument("--seed", type=int, default=1)
    a = p.parse_args()
    rng = random.Random(a.seed)
    cell = 1.0
    grid: dict[tuple[int, int, int], list[int]] = {}
    pos: list[tuple[float, float, float]] = []

    def key(q):
        return (math.floor(q[0] / cell), math.floor(q[1] / cell), math.floor(q[2] / cell))

    def free(q, parent):
        kx, ky, kz = key(q)
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for dz in (-1, 0, 1):
                    for j in grid.get((kx + dx, ky + dy, kz + dz), ()):
                        if j == parent:
                            continue
                        r2 = sum((q[k] - pos[j][k]) ** 2 for k in range(3))
                        if r2 < (a.bond - 1e-9) ** 2:
                            return False
        return True

    def add(q):
        pos.append(q)
        grid.setdefault(key(q), []).append(len(pos) - 1)

    add((0.0, 0.0, 0.0))
    while len(pos) < a.n:
        parent = len(pos) - 1 if rng.random() < a.chain else rng.randrange(len(pos))
        for _ in range(50):
            z = rng.uniform(-1.0, 1.0)
            phi = rng.uniform(0.0, 2.0 * math.pi)
            r = math.sqrt(1.0 - z * z)
            q = tuple(pos[parent][k] + a.bond * u for k, u in enumerate((r * math.cos(phi), r * math.sin(phi), z)))
            if free(q, parent):
                add(q)
                break
    n = len(pos)
    c = [sum(q[k] for q in pos) / n for k in range(3)]
    rg = math.sqrt(sum(sum((q[k] - c[k]) ** 2 for k in range(3)) for q in pos) / n)
    with open(a.out, "w") as f:
        f.write(f"# random branched chain, N = {n}, bond = {a.bond}, chain = {a.chain}, seed = {a.seed}, "
                f"Rg = {rg:.3f} d\n")
        for q in pos:
            f.write(f"{q[0]:.9f} {q[1]:.9f} {q[2]:.9f}\n")
    print(f"N = {n}, Rg = {rg:.3f} d -> {a.out}")


if __name__ == "__main__":
    main()
