#!/usr/bin/env python3
"""Compare the CL points of `swarf surface --csv` with `swarf dropcut --csv` on the same grid.

Used by bench/surface_stress.sh. Prints one markdown table row (or, with --header, the
header). Deviations are surface minus dropcut, in micrometres: positive = the scan's tool tip
lies above the exact drop-cutter's (material left), negative = below it (the ball would cut
into the part).

  surface_stress_cmp.py SURFACE.csv DROPCUT.csv --label 'part|tris|tool|pitch|dir'
      [--times 'surface_s|dropcut_s'] [--analytic sphere:R | cone:R:H] [--radius r]
      [--stl PART.stl]

Columns (besides the label):
  pts       CL points of the surface CSV (adaptive: those evaluated), all of them matched
            on the dropcut grid;
  max|dev|  the largest vertical deviation at those points, and where (x, y);
  1/2/5um   share of them within 1, 2, 5 um;
  max nrm   the largest deviation measured along the normal of the exact CL surface
            (vertical deviation x cos(slope), the slope from the dropcut grid's neighbours,
            the steeper one-sided difference along and across the lines): on a steep flank a
            vertical deviation mostly measures the slope;
  3D        at the 25 points furthest below the exact CL, vertically and along the normal: how far the scan's ball reaches into
            the mesh in 3D (radius minus the distance from its centre to the triangles, um;
            0 = it does not touch): the gouge a machinist would see, whatever the slope;
  interp    the adaptive path: every dropcut grid point against the scan line linearly
            interpolated between the points it evaluated (min and max, um);
  analytic  (sphere, cone) max |dropcut - closed form| and max |surface - closed form|, along
            the normal of the closed-form CL surface (um).
"""
import argparse
import bisect
import csv
import math
import sys


def read(path):
    """Points by (x, y) rounded to 0.1 um (the key) -> z, the lines as lists of (x, y, z), and
    the unrounded coordinates of each key."""
    lines = {}
    pts = {}
    exact = {}
    with open(path) as f:
        for r in csv.DictReader(f):
            x, y, z = float(r["x"]), float(r["y"]), float(r["z"])
            key = (round(x, 4), round(y, 4))
            pts[key] = z
            exact[key] = (x, y)
            lines.setdefault(int(r["line"]), []).append((x, y, z))
    return pts, lines, exact


def read_stl_ascii(path):
    v = []
    with open(path) as f:
        for line in f:
            w = line.split()
            if w and w[0] == "vertex":
                v.append((float(w[1]), float(w[2]), float(w[3])))
    return [tuple(v[i:i + 3]) for i in range(0, len(v) - 2, 3)]


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def closest_on_triangle(p, a, b, c):
    """Ericson, Real-Time Collision Detection 5.1.5."""
    ab, ac, ap = sub(b, a), sub(c, a), sub(p, a)
    d1, d2 = dot(ab, ap), dot(ac, ap)
    if d1 <= 0 and d2 <= 0:
        return a
    bp = sub(p, b)
    d3, d4 = dot(ab, bp), dot(ac, bp)
    if d3 >= 0 and d4 <= d3:
        return b
    vc = d1 * d4 - d3 * d2
    if vc <= 0 and d1 >= 0 and d3 <= 0:
        v = d1 / (d1 - d3)
        return (a[0] + v * ab[0], a[1] + v * ab[1], a[2] + v * ab[2])
    cp = sub(p, c)
    d5, d6 = dot(ab, cp), dot(ac, cp)
    if d6 >= 0 and d5 <= d6:
        return c
    vb = d5 * d2 - d1 * d6
    if vb <= 0 and d2 >= 0 and d6 <= 0:
        w = d2 / (d2 - d6)
        return (a[0] + w * ac[0], a[1] + w * ac[1], a[2] + w * ac[2])
    va = d3 * d6 - d5 * d4
    if va <= 0 and (d4 - d3) >= 0 and (d5 - d6) >= 0:
        w = (d4 - d3) / ((d4 - d3) + (d5 - d6))
        return (b[0] + w * (c[0] - b[0]), b[1] + w * (c[1] - b[1]), b[2] + w * (c[2] - b[2]))
    denom = 1.0 / (va + vb + vc)
    v, w = vb * denom, vc * denom
    return (a[0] + ab[0] * v + ac[0] * w, a[1] + ab[1] * v + ac[1] * w, a[2] + ab[2] * v + ac[2] * w)


def penetration(tris, boxes, centre, r):
    """How far a ball of radius r at `centre` reaches into the surface: r - distance, mm."""
    best = math.inf
    for t, (lo, hi) in zip(tris, boxes):
        if (lo[0] - r > centre[0] or hi[0] + r < centre[0] or lo[1] - r > centre[1]
                or hi[1] + r < centre[1] or lo[2] - r > centre[2] or hi[2] + r < centre[2]):
            continue
        q = closest_on_triangle(centre, *t)
        best = min(best, math.sqrt(dot(sub(centre, q), sub(centre, q))))
    return r - best if best < math.inf else -math.inf


def analytic_tip(kind, params, r, x, y):
    d = math.hypot(x, y)
    if kind == "sphere":
        (rs,) = params
        if d > rs + r:
            return None
        return math.sqrt((rs + r) ** 2 - d * d) - r
    if kind == "cone":  # base radius rb at z = 0, apex at height h; convex solid
        rb, h = params
        a = math.atan2(h, rb)  # flank slope
        best = -math.inf
        if d <= r:  # apex
            best = max(best, h + math.sqrt(r * r - d * d) - r)
        rc = d - r * math.sin(a)  # flank contact radius
        if 0.0 <= rc <= rb:
            best = max(best, h - rc * math.tan(a) + r * math.cos(a) - r)
        if abs(d - rb) <= r:  # base rim
            best = max(best, math.sqrt(r * r - (d - rb) ** 2) - r)
        if d <= rb:  # bottom face seen from above cannot hold the ball up higher
            best = max(best, 0.0)
        return best if best > -math.inf else None
    raise SystemExit("unknown analytic shape " + kind)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("surface", nargs="?")
    ap.add_argument("dropcut", nargs="?")
    ap.add_argument("--label", default="")
    ap.add_argument("--times", default="|")
    ap.add_argument("--analytic", default="")
    ap.add_argument("--radius", type=float, default=0.0)
    ap.add_argument("--header", action="store_true")
    ap.add_argument("--stl", default="", help="with --radius: 3D check of the worst points")
    a = ap.parse_args()
    if a.header:
        print("| part | tris | tool | pitch | dir | pts | max dev um (at x, y) | <=1 / 2 / 5 um % "
              "| max nrm um | 3D um | interp min / max um | analytic dc / surf um | surface s | dropcut s |")
        print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
        return
    s_pts, s_lines, s_xy = read(a.surface)
    d_pts, d_lines, d_xy = read(a.dropcut)
    keys = [k for k in s_pts if k in d_pts]
    missing = len(s_pts) - len(keys)
    devs = [((s_pts[k] - d_pts[k]) * 1000.0, k) for k in keys]
    n = len(devs)
    if n == 0:
        print(f"| {a.label} | 0 (surface {len(s_pts)}, dropcut {len(d_pts)}) | | | | | | {a.times} |")
        return
    ab = [abs(v) for v, _ in devs]
    worst = max(range(n), key=lambda i: ab[i])
    wv, wk = devs[worst]
    share = [100.0 * sum(x <= t for x in ab) / n for t in (1.0, 2.0, 5.0)]

    # Slope of the exact CL surface at a grid point: the steeper one-sided difference along
    # the line and across the lines (dropcut grid neighbours).
    xs = sorted({k[0] for k in d_pts})
    ys = sorted({k[1] for k in d_pts})

    def slope(k):
        i = bisect.bisect_left(xs, k[0])
        j = bisect.bisect_left(ys, k[1])
        z = d_pts[k]
        g = []
        for nb_x, nb_y in ((i - 1, j), (i + 1, j), (i, j - 1), (i, j + 1)):
            if 0 <= nb_x < len(xs) and 0 <= nb_y < len(ys):
                q = (xs[nb_x], ys[nb_y])
                if q in d_pts:
                    dist = abs(q[0] - k[0]) + abs(q[1] - k[1])
                    g.append((abs(d_pts[q] - z) / dist, nb_x != i))
        gx = max([v for v, alongx in g if alongx], default=0.0)
        gy = max([v for v, alongx in g if not alongx], default=0.0)
        return math.hypot(gx, gy)

    nrm_of = [(v / math.sqrt(1.0 + slope(k) ** 2), k) for v, k in devs]
    nrm = max(abs(v) for v, _ in nrm_of)

    # Adaptive path between evaluated points, at every dropcut grid point of the same line.
    imin, imax, iat = 0.0, 0.0, None
    by_y, by_x = {}, {}
    for k, zd in d_pts.items():
        by_y.setdefault(k[1], []).append((k, zd))
        by_x.setdefault(k[0], []).append((k, zd))
    for line in s_lines.values():
        if len(line) < 2:
            continue
        along_x = abs(line[-1][0] - line[0][0]) >= abs(line[-1][1] - line[0][1])
        t = [p[0] if along_x else p[1] for p in line]
        across = round(line[0][1] if along_x else line[0][0], 4)
        for k, zd in (by_y if along_x else by_x).get(across, []):
            u = d_xy[k][0] if along_x else d_xy[k][1]
            m = bisect.bisect_left(t, u - 1e-7)
            if m >= len(t):
                continue
            if abs(t[m] - u) < 1e-7:
                z = line[m][2]
            elif m == 0:
                continue
            else:
                f = (u - t[m - 1]) / (t[m] - t[m - 1])
                z = line[m - 1][2] + f * (line[m][2] - line[m - 1][2])
            dv = (z - zd) * 1000.0
            if dv < imin:
                imin, iat = dv, k
            imax = max(imax, dv)

    ana = ""
    if a.analytic:
        kind, *ps = a.analytic.split(":")
        ps = [float(v) for v in ps]
        worst_d = worst_s = 0.0
        h = 1e-5
        floor = min(d_pts.values())  # both clamp the tip to the part's lowest z
        for k in keys:
            t = analytic_tip(kind, ps, a.radius, k[0], k[1])
            if t is None:
                continue
            t = max(t, floor)
            # Along the normal of the closed-form CL surface (its slope by central differences).
            near = [analytic_tip(kind, ps, a.radius, k[0] + dx, k[1] + dy)
                    for dx, dy in ((h, 0), (-h, 0), (0, h), (0, -h))]
            if any(v is None for v in near):
                continue
            near = [max(v, floor) for v in near]
            g = math.hypot((near[0] - near[1]) / (2 * h), (near[2] - near[3]) / (2 * h))
            c = 1000.0 / math.sqrt(1.0 + g * g)
            worst_d = max(worst_d, abs(d_pts[k] - t) * c)
            worst_s = max(worst_s, abs(s_pts[k] - t) * c)
        ana = f"{worst_d:.2f} / {worst_s:.2f}"
    # The 3D truth at the points furthest below the exact CL: how far the scan's ball reaches
    # into the mesh (r - distance from its centre to the triangles; > 0 cuts the part).
    pen3 = ""
    if a.stl and a.radius > 0:
        tris = read_stl_ascii(a.stl)
        boxes = [(tuple(min(p[i] for p in t) for i in range(3)),
                  tuple(max(p[i] for p in t) for i in range(3))) for t in tris]
        low = sorted(devs)[:25] + sorted(nrm_of)[:25]
        worst_pen = max((penetration(tris, boxes, (s_xy[k][0], s_xy[k][1], s_pts[k] + a.radius),
                                     a.radius) for v, k in low if v < 0), default=0.0)
        pen3 = f"{max(worst_pen, 0.0) * 1000.0:.2f}"
    extra = f" ({missing} unmatched)" if missing else ""
    at = f" ({iat[0]:g}, {iat[1]:g})" if iat is not None and imin < -1.0 else ""
    print(f"| {a.label} | {n}{extra} | {wv:+.2f} ({wk[0]:g}, {wk[1]:g}) | "
          f"{share[0]:.2f} / {share[1]:.2f} / {share[2]:.2f} | {nrm:.2f} | {pen3} | {imin:.1f} / {imax:.1f}{at} | "
          f"{ana} | {a.times} |")


if __name__ == "__main__":
    sys.exit(main())
