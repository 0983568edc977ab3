#!/usr/bin/env python3
"""Runs FreeCAD's adaptive clearing (libarea's Adaptive2d, the engine of FreeCAD's Path/CAM
Adaptive operation) on a Swarf pocket JSON and writes its toolpath as G-code, so that the
same independent sweep (bench/pocket_sweep.cpp) can judge both generators.

  python3 bench/freecad_adaptive.py POCKET.json TOOL_DIAMETER STEPOVER_FRACTION OUT.nc \
      [--no-finishing-profile] [--tolerance 0.1] [--depth 6]

Needs Debian's freecad-python3 (not a dependency of Swarf: benchmark only). Prints one line:
the Adaptive2d.Execute wall and CPU time and the path's lengths. The helix entry and the
circle at its bottom are written as arcs (entry moves for the sweep, as Swarf's own helix),
cutting moves as G1 at depth, links as G0.
"""
import json
import math
import sys
import time

sys.path.append("/usr/lib/freecad-python3/lib")
sys.path.append("/usr/lib/freecad/lib")
import FreeCAD  # noqa: E402,F401  (loads the module search paths)
import area  # noqa: E402


def main():
    args = sys.argv[1:]
    if len(args) < 4:
        sys.exit(__doc__)
    pocket_path, diameter, stepover, out_path = args[0], float(args[1]), float(args[2]), args[3]
    finishing = "--no-finishing-profile" not in args
    tolerance = float(args[args.index("--tolerance") + 1]) if "--tolerance" in args else 0.1
    depth = float(args[args.index("--depth") + 1]) if "--depth" in args else 6.0
    with open(pocket_path) as f:
        pocket = json.load(f)
    rings = [pocket["outer"]] + pocket.get("islands", [])
    paths = [[list(map(float, p)) for p in ring] + [list(map(float, ring[0]))] for ring in rings]
    xs = [p[0] for p in pocket["outer"]]
    ys = [p[1] for p in pocket["outer"]]
    m = diameter
    stock = [[[min(xs) - m, min(ys) - m], [max(xs) + m, min(ys) - m], [max(xs) + m, max(ys) + m],
              [min(xs) - m, max(ys) + m], [min(xs) - m, min(ys) - m]]]

    a2d = area.Adaptive2d()
    a2d.stepOverFactor = stepover
    a2d.toolDiameter = diameter
    a2d.helixRampDiameter = 0.0
    a2d.keepToolDownDistRatio = 3.0
    a2d.stockToLeave = 0.0
    a2d.tolerance = tolerance
    a2d.forceInsideOut = False
    a2d.finishingProfile = finishing
    a2d.opType = area.AdaptiveOperationType.ClearingInside
    w0, c0 = time.perf_counter(), time.process_time()
    results = a2d.Execute(stock, paths, lambda tpaths: False)
    wall, cpu = time.perf_counter() - w0, time.process_time() - c0

    z, clear, feed = -depth, 5.0, 1000.0
    out = ["%", "(FreeCAD Adaptive2d on %s)" % pocket_path, "G21 G90 G17", "G0 Z%.4f" % clear]
    cut_len = link_len = 0.0
    for region in results:
        cx, cy = region.HelixCenterPoint[0], region.HelixCenterPoint[1]
        sx, sy = region.StartPoint[0], region.StartPoint[1]
        r = math.hypot(sx - cx, sy - cy)
        if r > 0.001:
            out.append("G0 X%.4f Y%.4f" % (cx + r, cy))
            out.append("G1 Z0 F300")
            drop = math.pi * r * math.tan(math.radians(5.0))  # per half turn, 5 degrees
            n = max(2, math.ceil(depth / drop))
            n += n % 2
            for k in range(1, n + 1):
                x, i = (cx - r, -r) if k % 2 == 1 else (cx + r, r)
                out.append("G2 X%.4f Y%.4f Z%.4f I%.4f J0 F300" % (x, cy, -depth * k / n, i))
            # one more circle at depth, as FreeCAD's own post does
            out.append("G2 X%.4f Y%.4f I%.4f J0" % (cx - r, cy, -r))
            out.append("G2 X%.4f Y%.4f I%.4f J0" % (cx + r, cy, r))
            lx, ly = cx + r, cy
        else:
            out.append("G0 X%.4f Y%.4f" % (sx, sy))
            out.append("G1 Z%.4f F300" % z)
            lx, ly = sx, sy
        at_depth = True
        for motion, pts in region.AdaptivePaths:
            for p in pts:
                x, y = p[0], p[1]
                d = math.hypot(x - lx, y - ly)
                if motion == area.AdaptiveMotionType.Cutting:
                    if not at_depth:
                        out.append("G1 Z%.4f F300" % z)
                        at_depth = True
                    out.append("G1 X%.4f Y%.4f F%.0f" % (x, y, feed))
                    cut_len += d
                elif motion == area.AdaptiveMotionType.LinkClear:
                    out.append("G0 X%.4f Y%.4f" % (x, y))
                    link_len += d
                else:  # LinkNotClear: over the top
                    if at_depth:
                        out.append("G0 Z%.4f" % clear)
                        at_depth = False
                    out.append("G0 X%.4f Y%.4f" % (x, y))
                    link_len += d
                lx, ly = x, y
        out.append("G0 Z%.4f" % clear)
    out += ["M2", "%"]
    with open(out_path, "w") as f:
        f.write("\n".join(out) + "\n")
    print("freecad_adaptive: regions %d, Execute wall %.3f s, cpu %.3f s, cutting %.0f mm, "
          "links %.0f mm, finishing profile %s" % (len(results), wall, cpu, cut_len, link_len,
                                                     "on" if finishing else "off"))


if __name__ == "__main__":
    main()
