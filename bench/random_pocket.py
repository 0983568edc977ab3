#!/usr/bin/env python3
"""A random pocket for the benchmarks (bench/pocket_random.sh, bench/compare_freecad_random.sh):
a star, polygon, rectangle, circle or L outline up to 120 mm with 0-4 round or square islands
(some nearer each other or a wall than the tool), a flat end mill of 3-20 mm and a stepover of
5-40 % of its diameter. The same seed gives the same pocket.

  python3 bench/random_pocket.py SEED OUT.json    prints: diameter stepover shape islands
"""
import json, math, random, sys
seed, out = int(sys.argv[1]), sys.argv[2]
random.seed(seed)
D = random.choice([3, 4, 6, 8, 10, 12, 16, 20])
size = min(120, D * random.uniform(6, 14))
kind = random.choice(["star", "rect", "poly", "circle", "lshape"])
def star(cx, cy, r0, r1, n):
    pts = []
    for k in range(n):
        a = 2 * math.pi * k / n + random.uniform(-0.3, 0.3) * math.pi / n
        r = random.uniform(r0, r1)
        pts.append([cx + r * math.cos(a), cy + r * math.sin(a)])
    return pts
if kind == "star":
    outer = star(0, 0, size * 0.3, size * 0.5, random.randint(5, 16))
elif kind == "rect":
    w, h = size, size * random.uniform(0.4, 1.0)
    outer = [[0, 0], [w, 0], [w, h], [0, h]]
elif kind == "poly":
    outer = star(0, 0, size * 0.45, size * 0.5, random.randint(3, 9))
elif kind == "circle":
    outer = star(0, 0, size * 0.5, size * 0.5, 96)
else:
    w = size; t = size * random.uniform(0.3, 0.6)
    outer = [[0, 0], [w, 0], [w, t], [t, t], [t, w], [0, w]]
xs = [p[0] for p in outer]; ys = [p[1] for p in outer]
def inside(x, y, poly):
    c = False
    for i in range(len(poly)):
        x1, y1 = poly[i]; x2, y2 = poly[i - 1]
        if (y1 > y) != (y2 > y) and x < x1 + (y - y1) * (x2 - x1) / (y2 - y1):
            c = not c
    return c
def dseg(px, py, a, b):
    ax, ay = a; bx, by = b
    dx, dy = bx - ax, by - ay
    t = max(0, min(1, ((px - ax) * dx + (py - ay) * dy) / (dx * dx + dy * dy)))
    return math.hypot(px - ax - t * dx, py - ay - t * dy)
islands = []
for _ in range(random.randint(0, 4)):
    for attempt in range(50):
        r = random.uniform(0.3, 1.2) * D
        x = random.uniform(min(xs), max(xs)); y = random.uniform(min(ys), max(ys))
        if not inside(x, y, outer): continue
        m = min(dseg(x, y, outer[i - 1], outer[i]) for i in range(len(outer)))
        if m < r + random.uniform(0.1, 1.5) * D * 0.3: continue
        if any(math.hypot(x - ix, y - iy) < r + ir + 0.5 for ix, iy, ir in islands): continue
        islands.append((x, y, r)); break
isl = []
for x, y, r in islands:
    if random.random() < 0.5:
        isl.append([[x + r * math.cos(2 * math.pi * k / 40), y + r * math.sin(2 * math.pi * k / 40)] for k in range(40)])
    else:
        s = r * 0.7
        isl.append([[x - s, y - s], [x + s, y - s], [x + s, y + s], [x - s, y + s]])
json.dump({"outer": outer, "islands": isl}, open(out, "w"))
f = random.choice([0.05, 0.08, 0.1, 0.15, 0.2, 0.3, 0.4])
print(D, round(D * f, 3), kind, len(isl))
