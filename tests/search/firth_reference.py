#!/usr/bin/env python3
# Firth's logistic regression by Newton on the modified score (Firth 1993, eq for the canonical
# link: U*(b) = X'(y - n mu + h (1/2 - mu)), h the hat diagonal of W^1/2 X (X'WX)^-1 X' W^1/2).
import math
speeds = [0.01, 0.02, 0.04, 0.08, 0.16]
trials = [5, 5, 5, 5, 5]
hits = [0, 1, 2, 4, 5]
centre = 0.5 * (math.log(0.005) + math.log(0.3))
x = [math.log(v) - centre for v in speeds]
def fit(firth):
    b0 = b1 = 0.0
    for _ in range(200):
        mu = [1 / (1 + math.exp(-(b0 + b1 * xi))) for xi in x]
        w = [n * m * (1 - m) for n, m in zip(trials, mu)]
        a = sum(w); b = sum(wi * xi for wi, xi in zip(w, x)); c = sum(wi * xi * xi for wi, xi in zip(w, x))
        det = a * c - b * b
        inv = [[c / det, -b / det], [-b / det, a / det]]
        h = [wi * (inv[0][0] + 2 * inv[0][1] * xi + inv[1][1] * xi * xi) for wi, xi in zip(w, x)]
        r = [y - n * m + (hi * (0.5 - m) if firth else 0.0) for y, n, m, hi in zip(hits, trials, mu, h)]
        u0 = sum(r); u1 = sum(ri * xi for ri, xi in zip(r, x))
        d0 = inv[0][0] * u0 + inv[0][1] * u1; d1 = inv[1][0] * u0 + inv[1][1] * u1
        b0 += d0; b1 += d1
        if abs(d0) < 1e-14 and abs(d1) < 1e-14: break
    return b0, b1
print("firth %.12g %.12g" % fit(True))
print("ml    %.12g %.12g" % fit(False))
