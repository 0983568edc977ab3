// Simulation outputs: the force waveform as CSV and SVG (as seed 001 Fig. 18-19), per-move
// results, and the machined stock's height map as CSV and PNG.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>

#include "swarf/report/image.h"
#include "swarf/report/plot.h"
#include "swarf/sim/simulate.h"

namespace swarf::sim {

namespace {

// std::to_chars: several times faster than printf for the hundreds of thousands of rows of a
// waveform, and locale-independent.
void append_fixed(std::string& out, double v, int digits) {
  char buf[64];
  const auto res = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, digits);
  out.append(buf, res.ptr);
}

}  // namespace

std::string forces_csv(const SimulationResult& r) {
  std::string out = "t_s,fx_n,fy_n,fz_n,f_n,move\n";
  out.reserve(out.size() + r.samples.size() * 48);
  for (const ForceSample& s : r.samples) {
    append_fixed(out, s.t_s, 6);
    for (double v : {s.force_n.x, s.force_n.y, s.force_n.z, norm(s.force_n)}) {
      out += ',';
      append_fixed(out, v, 3);
    }
    out += ',';
    out += std::to_string(s.move + 1);
    out += '\n';
  }
  return out;
}

std::string moves_csv(const SimulationResult& r) {
  std::string out =
      "move,t_start_s,t_end_s,removed_mm3,peak_force_n,mean_force_n,engaged_arc_deg,collision\n";
  char buf[200];
  for (std::size_t i = 0; i < r.moves.size(); ++i) {
    const MoveResult& m = r.moves[i];
    std::snprintf(buf, sizeof buf, "%zu,%.6f,%.6f,%.6f,%.3f,%.3f,%.1f,%d\n", i + 1, m.t_start_s,
                  m.t_end_s, m.removed_mm3, m.peak_force_n, m.mean_force_n, m.engaged_arc_deg,
                  m.collision ? 1 : 0);
    out += buf;
  }
  return out;
}

std::string forces_svg(const SimulationResult& r, const std::string& title,
                       std::size_t max_points) {
  Series sx{"Fx", {}, {}, "#d62728"}, sy{"Fy", {}, {}, "#2ca02c"}, sz{"Fz", {}, {}, "#1f77b4"};
  const std::size_t n = r.samples.size();
  // Peak-preserving decimation: each bucket contributes its lowest and highest sample, so the
  // envelope of the waveform survives even when the plot has fewer pixels than samples.
  const std::size_t buckets = std::max<std::size_t>(1, max_points / 2);
  const std::size_t per = std::max<std::size_t>(1, (n + buckets - 1) / buckets);
  auto emit = [](Series& s, const std::vector<ForceSample>& v, std::size_t a, std::size_t b,
                 int axis) {
    if (b - a <= 2) {
      for (std::size_t i = a; i < b; ++i) {
        s.x.push_back(v[i].t_s);
        s.y.push_back(v[i].force_n[axis]);
      }
      return;
    }
    std::size_t lo = a, hi = a;
    for (std::size_t i = a; i < b; ++i) {
      if (v[i].force_n[axis] < v[lo].force_n[axis]) lo = i;
      if (v[i].force_n[axis] > v[hi].force_n[axis]) hi = i;
    }
    for (std::size_t i : {std::min(lo, hi), std::max(lo, hi)}) {
      s.x.push_back(v[i].t_s);
      s.y.push_back(v[i].force_n[axis]);
    }
  };
  for (std::size_t a = 0; a < n; a += per) {
    const std::size_t b = std::min(n, a + per);
    emit(sx, r.samples, a, b, 0);
    emit(sy, r.samples, a, b, 1);
    emit(sz, r.samples, a, b, 2);
  }
  return line_chart_svg({sx, sy, sz}, title, "time, s", "force on the tool, N");
}

Status write_height_map_png(const std::string& path, const HeightMap& map, int ppc) {
  ppc = std::max(1, ppc);
  float lo = std::numeric_limits<float>::infinity(), hi = -lo;
  for (float z : map.top) {
    if (std::isnan(z)) continue;
    lo = std::min(lo, z);
    hi = std::max(hi, z);
  }
  Image img(map.nx * ppc, map.ny * ppc);
  for (int iy = 0; iy < map.ny; ++iy) {
    for (int ix = 0; ix < map.nx; ++ix) {
      const float z = map.top[static_cast<std::size_t>(iy) * map.nx + ix];
      Rgb c{255, 255, 255};
      if (!std::isnan(z)) c = heat_color(hi > lo ? (z - lo) / (hi - lo) : 1.0);
      for (int dy = 0; dy < ppc; ++dy) {
        for (int dx = 0; dx < ppc; ++dx) {
          img.at(ix * ppc + dx, (map.ny - 1 - iy) * ppc + dy) = c;  // row 0 is the top (max y)
        }
      }
    }
  }
  return write_png(path, img);
}

std::string height_map_csv(const HeightMap& map) {
  std::string out = "x_mm,y_mm,z_mm\n";
  char buf[96];
  for (int iy = 0; iy < map.ny; ++iy) {
    for (int ix = 0; ix < map.nx; ++ix) {
      const float z = map.top[static_cast<std::size_t>(iy) * map.nx + ix];
      if (std::isnan(z)) continue;
      std::snprintf(buf, sizeof buf, "%.4f,%.4f,%.4f\n", map.x0 + (ix + 0.5) * map.cell_mm,
                    map.y0 + (iy + 0.5) * map.cell_mm, z);
      out += buf;
    }
  }
  return out;
}

Mesh height_map_mesh(const HeightMap& map, double floor_z) {
  Mesh m;
  const int nx = map.nx, ny = map.ny;
  if (nx < 2 || ny < 2) return m;
  const auto idx = [&](int i, int j, int layer) {  // layer 0 top, 1 bottom
    return static_cast<std::uint32_t>((layer * ny + j) * nx + i);
  };
  for (int layer = 0; layer < 2; ++layer) {
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        const float z = map.top[static_cast<std::size_t>(j) * nx + i];
        const double h = layer == 1 || std::isnan(z) ? floor_z : std::max<double>(z, floor_z);
        m.vertices.push_back(
            {map.x0 + (i + 0.5) * map.cell_mm, map.y0 + (j + 0.5) * map.cell_mm, h});
      }
    }
  }
  // Counter-clockwise seen from outside: the top up, the bottom down, the walls outwards.
  for (int j = 0; j + 1 < ny; ++j) {
    for (int i = 0; i + 1 < nx; ++i) {
      const auto a = idx(i, j, 0), b = idx(i + 1, j, 0), c = idx(i + 1, j + 1, 0),
                 d = idx(i, j + 1, 0);
      m.triangles.push_back({a, b, c});
      m.triangles.push_back({a, c, d});
      const auto ab = idx(i, j, 1), bb = idx(i + 1, j, 1), cb = idx(i + 1, j + 1, 1),
                 db = idx(i, j + 1, 1);
      m.triangles.push_back({ab, cb, bb});
      m.triangles.push_back({ab, db, cb});
    }
  }
  for (int i = 0; i + 1 < nx; ++i) {
    // y = min wall faces -y; y = max wall faces +y.
    m.triangles.push_back({idx(i, 0, 1), idx(i + 1, 0, 1), idx(i + 1, 0, 0)});
    m.triangles.push_back({idx(i, 0, 1), idx(i + 1, 0, 0), idx(i, 0, 0)});
    m.triangles.push_back({idx(i + 1, ny - 1, 1), idx(i, ny - 1, 1), idx(i, ny - 1, 0)});
    m.triangles.push_back({idx(i + 1, ny - 1, 1), idx(i, ny - 1, 0), idx(i + 1, ny - 1, 0)});
  }
  for (int j = 0; j + 1 < ny; ++j) {
    // x = min wall faces -x; x = max wall faces +x.
    m.triangles.push_back({idx(0, j + 1, 1), idx(0, j, 1), idx(0, j, 0)});
    m.triangles.push_back({idx(0, j + 1, 1), idx(0, j, 0), idx(0, j + 1, 0)});
    m.triangles.push_back({idx(nx - 1, j, 1), idx(nx - 1, j + 1, 1), idx(nx - 1, j + 1, 0)});
    m.triangles.push_back({idx(nx - 1, j, 1), idx(nx - 1, j + 1, 0), idx(nx - 1, j, 0)});
  }
  return m;
}

}  // namespace swarf::sim
