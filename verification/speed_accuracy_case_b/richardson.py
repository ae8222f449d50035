#!/usr/bin/env python3
"""Richardson extrapolation of a measure from three cell sizes of unequal ratio.

The procedure of Celik et al. (2008, J. Fluids Eng. 130, 078001), the one `lituya sweep`
reports for its three finest sizes, for any three sizes picked from a table of run means:

    h1 < h2 < h3, r21 = h2 / h1, r32 = h3 / h2, e21 = f2 - f1, e32 = f3 - f2,
    s = sign(e32 / e21),
    p = |ln|e32 / e21| + q(p)| / ln r21,  q(p) = ln((r21^p - s) / (r32^p - s)),

solved by fixed-point iteration; f_ext = (r21^p f1 - f2) / (r21^p - 1). When e32 / e21 < 0
the changes alternate in sign and no order exists.

This repeats, in Python, what `sweep/src/convergence.cpp` computes for a sweep's own runs: it
exists only because no `lituya` command yet re-reports that convergence for sizes taken from
several sweeps. When one does, use it and delete this file.

Usage: richardson.py MEANS.csv MEASURE H1 H2 H3
MEANS.csv has the columns cell_size_m, measure, mean (one row per size and measure).
"""
import csv
import math
import sys


def observed_order(h, f):
    r21, r32 = h[1] / h[0], h[2] / h[1]
    e21, e32 = f[1] - f[0], f[2] - f[1]
    if e21 == 0 or e32 / e21 <= 0:
        return None
    s = 1.0
    p = abs(math.log(abs(e32 / e21))) / math.log(r21)
    for _ in range(200):
        q = math.log((r21**p - s) / (r32**p - s))
        p_next = abs(math.log(abs(e32 / e21)) + q) / math.log(r21)
        if abs(p_next - p) < 1e-12:
            break
        p = p_next
    return p


def main():
    table, measure = sys.argv[1], sys.argv[2]
    sizes = [float(x) for x in sys.argv[3:6]]
    means = {}
    with open(table, newline="") as f:
        for row in csv.DictReader(f):
            if row["measure"] == measure:
                means[float(row["cell_size_m"])] = float(row["mean"])
    f = [means[h] for h in sizes]
    print(f"{measure}: h = {sizes}, means = {[round(v, 6) for v in f]}")
    p = observed_order(sizes, f)
    if p is None:
        print("  the changes alternate in sign (or vanish): no order, no extrapolation")
        return
    r21 = sizes[1] / sizes[0]
    extrapolated = (r21**p * f[0] - f[1]) / (r21**p - 1)
    gci = 1.25 * abs((f[0] - f[1]) / f[0]) / (r21**p - 1)
    print(f"  observed order {p:.3f}, extrapolated {extrapolated:.6g}, "
          f"finest differs by {100 * (f[0] - extrapolated) / extrapolated:+.2f} %, "
          f"GCI {100 * gci:.2f} %")


if __name__ == "__main__":
    main()
