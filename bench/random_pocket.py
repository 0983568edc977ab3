#!/usr/bin/env python3
"""A random pocket for the benchmarks (bench/pocket_random.sh, bench/compare_freecad_random.sh):
a star, polygon, rectangle, circle or L outline up to 120 mm with 0-4 round or square islands
(some nearer each other or a wall than the tool), a flat end mill of 3-20 mm and a stepover of
5-40 % of its diameter. Seeds from 2000 on give part-like outlines instead (part_like below),
seeds from 3000 on islands that overlap and cross the wall (careless below).
The same seed gives the same pocket.

  python3 bench/random_pocket.py SEED OUT.json    prints: diameter stepover shape islands
"""
import json, math, random, sys
seed, out = int(sys.argv[1]), sys.argv[2]
random.seed(seed)


def arc(cx, cy, r, a0, a1, n):
    """n + 1 points on the circle from angle a0 to a1 (degrees)."""
    return [[cx + r * math.cos(math.radians(a0 + (a1 - a0) * k / n)),
             cy + r * math.sin(math.radians(a0 + (a1 - a0) * k / n))] for k in range(n + 1)]


def rounded_rect(x0, y0, x1, y1, r):
    """Counter-clockwise rectangle with corner radius r (0: sharp corners)."""
    r = min(r, 0.5 * (x1 - x0), 0.5 * (y1 - y0))
    if r <= 1e-9:
        return [[x0, y0], [x1, y0], [x1, y1], [x0, y1]]
    n = 12
    return (arc(x1 - r, y0 + r, r, -90, 0, n) + arc(x1 - r, y1 - r, r, 0, 90, n) +
            arc(x0 + r, y1 - r, r, 90, 180, n) + arc(x0 + r, y0 + r, r, 180, 270, n))


def part_like():
    """Seeds from 2000 on: outlines as machined parts have them (kept apart so that the
    pockets of the older seeds stay the same): a rounded rectangle whose corner radius is
    below, at or above the tool's, a U whose legs are channels 1.05-3 tool diameters wide, a
    ring round a boss, or a plate with bosses and slots, some of them a little more than a
    tool diameter from a wall or from each other."""
    D = random.choice([3, 4, 6, 8, 10, 12, 16, 20])
    R = 0.5 * D
    kind = random.choice(["rrect", "u", "ring", "bosses"])
    rc = R * random.choice([0.0, 0.3, 0.8, 1.0, 1.02, 1.5, 2.5])
    W = min(120.0, D * random.uniform(5, 14))
    H = min(120.0, W * random.uniform(0.4, 1.0))
    islands = []
    if kind == "rrect":
        outer = rounded_rect(0, 0, W, H, rc)
    elif kind == "u":
        leg = D * random.uniform(1.05, 3.0)
        leg2 = D * random.uniform(1.05, 3.0)
        base = D * random.uniform(1.05, 3.0)
        W = max(W, leg + leg2 + D)
        H = max(H, base + 2 * D)
        outer = [[0, 0], [W, 0], [W, H], [W - leg2, H], [W - leg2, base], [leg, base],
                 [leg, H], [0, H]]
    elif kind == "ring":
        gap = [D * random.uniform(1.02, 3.0) for _ in range(4)]
        W = max(W, gap[0] + gap[1] + 2 * D)
        H = max(H, gap[2] + gap[3] + 2 * D)
        outer = rounded_rect(0, 0, W, H, rc)
        isl_r = R * random.choice([0.0, 0.5, 1.0, 2.0])
        islands.append(rounded_rect(gap[0], gap[2], W - gap[1], H - gap[3], isl_r)[::-1])
    else:
        outer = rounded_rect(0, 0, W, H, rc)
        placed = []  # (x0, y0, x1, y1) boxes of the islands so far
        for _ in range(random.randint(1, 5)):
            for attempt in range(60):
                if random.random() < 0.5:
                    rad = D * random.uniform(0.3, 1.5)
                    w = h = 2 * rad
                else:
                    w, h = D * random.uniform(0.5, 4.0), D * random.uniform(0.5, 1.5)
                    if random.random() < 0.5:
                        w, h = h, w
                # Gaps to the walls and to the other islands: often just over a tool
                # diameter, now and then less (material the tool cannot reach).
                def gap():
                    u = random.random()
                    return D * (random.uniform(0.3, 1.0) if u < 0.15 else
                                random.uniform(1.02, 1.3) if u < 0.6 else random.uniform(1.3, 3.0))
                g, g2 = gap(), gap()
                x0 = random.uniform(0, W - w)
                y0 = random.uniform(0, H - h)
                if random.random() < 0.5:
                    x0 = random.choice([g, W - w - g])
                if x0 < 0.3 or y0 < 0.3 or x0 + w > W - 0.3 or y0 + h > H - 0.3:
                    continue
                # Keep clear of rounded corners: the box must lie inside the outline.
                box = (x0, y0, x0 + w, y0 + h)
                if rc > 0 and any(math.hypot(cx - px, cy - py) > rc - 0.3
                                  for cx, cy in [(rc, rc), (W - rc, rc), (rc, H - rc), (W - rc, H - rc)]
                                  for px, py in [(max(box[0], min(cx, box[2])), max(box[1], min(cy, box[3])))]
                                  if (px < rc or px > W - rc) and (py < rc or py > H - rc)):
                    continue
                if any(box[0] < b[2] + g2 and b[0] < box[2] + g2 and box[1] < b[3] + g2 and
                       b[1] < box[3] + g2 for b in placed):
                    continue
                placed.append(box)
                if w == h and random.random() < 0.7:
                    islands.append(arc(x0 + w / 2, y0 + h / 2, w / 2, 360, 0, 40)[:-1])
                else:
                    islands.append(rounded_rect(*box, min(w, h) / 2 * random.choice([0, 0.5, 1]))[::-1])
                break
    # The corner test above reads the box point nearest each arc's centre, which lets a box
    # whose vertex sticks out of a rounded corner through: seed 2201 put an island across
    # the outline (swarf refuses such a pocket). Such islands are dropped here, after every
    # random draw, so that the pockets of all other seeds stay the same.
    def inside_outer(x, y):
        c = False
        for k in range(len(outer)):
            (ax, ay), (bx, by) = outer[k - 1], outer[k]
            if (ay > y) != (by > y) and x < ax + (y - ay) * (bx - ax) / (by - ay):
                c = not c
        return c
    islands = [i for i in islands if all(inside_outer(x, y) for x, y in i)]
    json.dump({"outer": outer, "islands": islands}, open(out, "w"))
    f = random.choice([0.05, 0.08, 0.1, 0.15, 0.2, 0.3, 0.4])
    print(D, round(D * f, 3), kind, len(islands))


def careless():
    """Seeds from 3000 on: bosses drawn carelessly, as real drawings have them: round and
    rectangular islands that overlap each other, cross the wall, lie along it edge to edge or
    run right across the pocket (swarf merges them: the pocket is the outline minus their
    union), on a rectangle, sharp or rounded. No island lies wholly inside another."""
    D = random.choice([3, 4, 6, 8, 10, 12, 16, 20])
    R = 0.5 * D
    W = min(120.0, D * random.uniform(6, 14))
    H = min(120.0, W * random.uniform(0.5, 1.0))
    rc = R * random.choice([0.0, 1.02, 2.5])
    outer = rounded_rect(0, 0, W, H, rc)
    islands, boxes = [], []
    for _ in range(random.randint(1, 5)):
        w, h = D * random.uniform(0.6, 3.0), D * random.uniform(0.6, 3.0)
        x0, y0 = random.uniform(-0.3 * w, W - 0.7 * w), random.uniform(-0.3 * h, H - 0.7 * h)
        u = random.random()
        if u < 0.15:
            x0 = random.choice([0.0, W - w])  # edge on the wall
        elif u < 0.25:
            y0, h = -D, H + 2 * D  # right across
        box = (x0, y0, x0 + w, y0 + h)
        cx, cy = 0.5 * (box[0] + box[2]), 0.5 * (box[1] + box[3])
        inside = lambda b, x, y: b[0] < x < b[2] and b[1] < y < b[3]
        if not (0 < cx < W and 0 < cy < H) or any(
                inside(b, cx, cy) or inside(box, 0.5 * (b[0] + b[2]), 0.5 * (b[1] + b[3]))
                for b in boxes):
            continue
        boxes.append(box)
        if random.random() < 0.4 and u >= 0.25:
            r = 0.5 * min(w, h)
            islands.append(arc(cx, cy, r, 360, 0, 40)[:-1])
        else:
            islands.append(rounded_rect(*box, 0.0)[::-1])
    json.dump({"outer": outer, "islands": islands}, open(out, "w"))
    f = random.choice([0.05, 0.08, 0.1, 0.15, 0.2, 0.3, 0.4])
    print(D, round(D * f, 3), "careless", len(islands))


if seed >= 3000:
    careless()
    sys.exit(0)
if seed >= 2000:
    part_like()
    sys.exit(0)
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
