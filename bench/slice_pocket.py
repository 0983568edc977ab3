#!/usr/bin/env python3
"""Pockets from real parts: slices an STL (binary or ASCII) at height Z (in the file's
units) and writes the largest region of the section as a pocket JSON for `swarf pocket`:
its outer loop as the boundary and the holes inside it as islands, all scaled by SCALE
(25.4 for a part drawn in inches). Written for Swarf, independent of its own slicer, to
make test and bench pockets from tests/data or ../shared/data/real; prints the outer
loop's points, the islands and the area (mm^2).
  bench/slice_pocket.py STL Z SCALE OUT.json"""
import json
import math
import struct
import sys


def read_stl(path):
    data = open(path, 'rb').read()
    if len(data) >= 84:
        n = struct.unpack('<I', data[80:84])[0]
        if 84 + 50 * n == len(data):
            tris = []
            for k in range(n):
                v = struct.unpack_from('<9f', data, 84 + 50 * k + 12)
                tris.append([v[0:3], v[3:6], v[6:9]])
            return tris
    tris, cur = [], []
    for line in data.decode('ascii', 'replace').splitlines():
        t = line.split()
        if t and t[0] == 'vertex':
            cur.append([float(x) for x in t[1:4]])
            if len(cur) == 3:
                tris.append(cur)
                cur = []
    return tris


def area(p):
    return 0.5 * sum(p[i][0] * p[(i + 1) % len(p)][1] - p[(i + 1) % len(p)][0] * p[i][1]
                     for i in range(len(p)))


def inside(pt, poly):
    x, y = pt
    c = False
    n = len(poly)
    for i in range(n):
        x1, y1 = poly[i]
        x2, y2 = poly[(i + 1) % n]
        if (y1 > y) != (y2 > y) and x < x1 + (y - y1) * (x2 - x1) / (y2 - y1):
            c = not c
    return c


scale = float(sys.argv[3])
z = float(sys.argv[2]) * scale
tri = [[[c * scale for c in v] for v in t] for t in read_stl(sys.argv[1])]
segs = []
for t in tri:
    d = [v[2] - z for v in t]
    d = [1e-9 if abs(x) < 1e-9 else x for x in d]
    pts = []
    for i in range(3):
        a, b = t[i], t[(i + 1) % 3]
        da, db = d[i], d[(i + 1) % 3]
        if (da < 0) != (db < 0):
            s = da / (da - db)
            pts.append((a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1])))
    if len(pts) == 2 and math.hypot(pts[0][0] - pts[1][0], pts[0][1] - pts[1][1]) > 1e-9:
        segs.append(pts)


def key(p):
    return (round(p[0], 5), round(p[1], 5))


# Segments chained into loops by their end points rounded to 10 um.
adj = {}
for i, (a, b) in enumerate(segs):
    adj.setdefault(key(a), []).append((i, 0))
    adj.setdefault(key(b), []).append((i, 1))
used = [False] * len(segs)
loops = []
for i in range(len(segs)):
    if used[i]:
        continue
    used[i] = True
    loop = [segs[i][0], segs[i][1]]
    start = key(segs[i][0])
    while True:
        k = key(loop[-1])
        if k == start:
            loop.pop()
            break
        nxt = None
        for j, e in adj.get(k, []):
            if not used[j]:
                nxt = (j, e)
                break
        if nxt is None:
            loop = None
            break
        j, e = nxt
        used[j] = True
        loop.append(segs[j][1 - e])
    if loop and len(loop) >= 3:
        loops.append(loop)
# Loops under 1 mm^2 are slivers; a loop's depth is how many others hold it (even: an
# outline of material, odd: a hole).
loops = [lp for lp in loops if abs(area(lp)) > 1.0]
depth = [sum(inside(lp[0], m) for m in loops if m is not lp) for lp in loops]
outers = [i for i in range(len(loops)) if depth[i] % 2 == 0]
if not outers:
    sys.exit('no closed section at z')
o = max(outers, key=lambda i: abs(area(loops[i])))
isl = [i for i in range(len(loops)) if depth[i] == depth[o] + 1 and inside(loops[i][0], loops[o])]


def r(loop):
    return [[round(float(x), 4), round(float(y), 4)] for x, y in loop]


json.dump({'outer': r(loops[o]), 'islands': [r(loops[i]) for i in isl]}, open(sys.argv[4], 'w'))
print(len(loops[o]), len(isl), round(abs(area(loops[o])), 1))
