// Exact vertex and fold-edge contacts for the tri-slice scans (mesh_contacts.h).
#include "trislice/mesh_contacts.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "swarf/core/ball_contact.h"
#include "swarf/core/grid_walk.h"

namespace swarf::trislice_detail {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Edges whose two faces lie on the same side of them in the xy projection (or one face is
// vertical there), and edges with one face or more than two: the mesh's outline as seen from
// above, where a dropped ball can rest on an edge beside a drop. Vertical edges are left out
// (a ball rests on their ends, which are vertices).
std::vector<std::array<std::uint32_t, 2>> fold_edges(const Mesh& mesh) {
  struct Use {
    std::uint32_t lo, hi, opposite;
  };
  std::vector<Use> uses;
  uses.reserve(3 * mesh.size());
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = t[static_cast<std::size_t>(k)];
      const std::uint32_t b = t[static_cast<std::size_t>((k + 1) % 3)];
      const std::uint32_t c = t[static_cast<std::size_t>((k + 2) % 3)];
      if (a != b) uses.push_back({std::min(a, b), std::max(a, b), c});
    }
  std::sort(uses.begin(), uses.end(), [](const Use& x, const Use& y) {
    return x.lo != y.lo ? x.lo < y.lo : (x.hi != y.hi ? x.hi < y.hi : x.opposite < y.opposite);
  });
  std::vector<std::array<std::uint32_t, 2>> out;
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    while (j < uses.size() && uses[j].lo == uses[i].lo && uses[j].hi == uses[i].hi)
      ++j;
    const Vec3 a = mesh.vertices[uses[i].lo], b = mesh.vertices[uses[i].hi];
    const Vec2 e = b.xy() - a.xy();
    const double len2 = norm_sq(e);
    bool fold = j - i != 2;
    if (!fold && len2 > 0.0) {
      const double s1 = cross(e, mesh.vertices[uses[i].opposite].xy() - a.xy());
      const double s2 = cross(e, mesh.vertices[uses[i + 1].opposite].xy() - a.xy());
      // |s| / |e| is the opposite vertex's distance from the edge's line: under 1e-9 of the
      // edge's length, the face stands vertical.
      const double flat = 1e-9 * len2;
      fold = s1 * s2 > 0.0 || std::fabs(s1) <= flat || std::fabs(s2) <= flat;
    }
    if (fold && len2 > 1e-18) out.push_back({uses[i].lo, uses[i].hi});
    i = j;
  }
  return out;
}

}  // namespace

MeshContacts::MeshContacts(const Mesh& mesh, double radius_mm) {
  Box2 box;
  for (const Vec3& v : mesh.vertices)
    box.add(v.xy());
  if (box.empty()) return;
  // Vertices. Cells of R / 8: a cell's nearest distance then bounds its vertices' reach
  // closely. On a finely faceted smooth mesh every vertex comes within micrometres of the best
  // contact, so only that bound prunes (65,000-triangle sphere, ø20 ball: finishing 0.9 s with
  // R / 2, 0.53 s with R / 8 or R / 16, 0.48 s without vertices). At most 1024 cells a side.
  cell_ = std::max({radius_mm / 8.0, box.size().x / 1024.0, box.size().y / 1024.0, 1e-3});
  origin_ = box.min;
  nx_ = static_cast<int>(box.size().x / cell_) + 1;
  ny_ = static_cast<int>(box.size().y / cell_) + 1;
  auto cell_index = [&](Vec2 q) {
    const int i = std::clamp(static_cast<int>((q.x - origin_.x) / cell_), 0, nx_ - 1);
    const int j = std::clamp(static_cast<int>((q.y - origin_.y) / cell_), 0, ny_ - 1);
    return static_cast<std::size_t>(j) * static_cast<std::size_t>(nx_) +
           static_cast<std::size_t>(i);
  };
  const std::size_t ncell = static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_);
  start_.assign(ncell + 1, 0);
  std::vector<std::size_t> cell_of(mesh.vertices.size());
  for (std::size_t k = 0; k < mesh.vertices.size(); ++k) {
    cell_of[k] = cell_index(mesh.vertices[k].xy());
    ++start_[cell_of[k] + 1];
  }
  for (std::size_t c = 0; c < ncell; ++c)
    start_[c + 1] += start_[c];
  pts_.resize(mesh.vertices.size());
  std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
  for (std::size_t k = 0; k < mesh.vertices.size(); ++k)
    pts_[fill[cell_of[k]]++] = mesh.vertices[k];
  cellmax_.assign(ncell, -kInf);
  for (std::size_t c = 0; c < ncell; ++c) {
    auto b = pts_.begin() + start_[c], e = pts_.begin() + start_[c + 1];
    std::sort(b, e, [](const Vec3& x, const Vec3& y) {
      return x.z != y.z ? x.z > y.z : (x.x != y.x ? x.x < y.x : x.y < y.y);
    });
    if (b != e) cellmax_[c] = b->z;
  }

  // Fold edges, in cells of R / 4 (few edges: a ring or two per level of the outline), each
  // listed in the cells it crosses (row by row, with a margin so that rounding never drops
  // one), highest end first.
  for (const auto& ab : fold_edges(mesh)) {
    Edge g{mesh.vertices[ab[0]], mesh.vertices[ab[1]], {}, 0.0};
    g.box.add(g.a.xy());
    g.box.add(g.b.xy());
    g.zmax = std::max(g.a.z, g.b.z);
    edges_.push_back(g);
  }
  std::sort(edges_.begin(), edges_.end(), [](const Edge& x, const Edge& y) {
    if (x.zmax != y.zmax) return x.zmax > y.zmax;
    const std::array<double, 6> kx{x.a.x, x.a.y, x.a.z, x.b.x, x.b.y, x.b.z};
    const std::array<double, 6> ky{y.a.x, y.a.y, y.a.z, y.b.x, y.b.y, y.b.z};
    return kx < ky;
  });
  if (edges_.empty()) return;
  ecell_ = std::max({radius_mm / 4.0, box.size().x / 1024.0, box.size().y / 1024.0, 1e-3});
  eorigin_ = box.min;
  enx_ = static_cast<int>(box.size().x / ecell_) + 1;
  eny_ = static_cast<int>(box.size().y / ecell_) + 1;
  const std::size_t necell = static_cast<std::size_t>(enx_) * static_cast<std::size_t>(eny_);
  const CellGrid grid{eorigin_, ecell_, enx_, eny_};
  auto cells = [&](const Edge& g, auto&& fn) {
    for_cells_on_segment(grid, g.a.xy(), g.b.xy(), fn);
  };
  estart_.assign(necell + 1, 0);
  for (const Edge& g : edges_)
    cells(g, [&](std::size_t c) { ++estart_[c + 1]; });
  for (std::size_t c = 0; c < necell; ++c)
    estart_[c + 1] += estart_[c];
  eitems_.resize(estart_.back());
  std::vector<std::uint32_t> efill(estart_.begin(), estart_.end() - 1);
  // Edges are sorted highest first, so each cell's list comes out in that order too.
  for (std::size_t k = 0; k < edges_.size(); ++k)
    cells(edges_[k], [&](std::size_t c) { eitems_[efill[c]++] = static_cast<std::uint32_t>(k); });
  ecellmax_.assign(necell, -kInf);
  for (std::size_t c = 0; c < necell; ++c)
    if (estart_[c] < estart_[c + 1]) ecellmax_[c] = edges_[eitems_[estart_[c]]].zmax;
}

double MeshContacts::centre_height(Vec2 p, double R, double best) const {
  return edge_height(p, R, vertex_height(p, R, best));
}

double MeshContacts::vertex_height(Vec2 p, double R, double best) const {
  if (nx_ == 0) return best;
  const double R2 = R * R;
  const int i0 = std::max(0, static_cast<int>(std::floor((p.x - R - origin_.x) / cell_)));
  const int i1 = std::min(nx_ - 1, static_cast<int>(std::floor((p.x + R - origin_.x) / cell_)));
  const int j0 = std::max(0, static_cast<int>(std::floor((p.y - R - origin_.y) / cell_)));
  const int j1 = std::min(ny_ - 1, static_cast<int>(std::floor((p.y + R - origin_.y) / cell_)));
  for (int j = j0; j <= j1; ++j) {
    for (int i = i0; i <= i1; ++i) {
      const std::size_t c =
          static_cast<std::size_t>(j) * static_cast<std::size_t>(nx_) + static_cast<std::size_t>(i);
      if (cellmax_[c] + R <= best) continue;
      const double cx = origin_.x + i * cell_, cy = origin_.y + j * cell_;
      const double dx = std::max({cx - p.x, 0.0, p.x - cx - cell_});
      const double dy = std::max({cy - p.y, 0.0, p.y - cy - cell_});
      const double dmin2 = dx * dx + dy * dy;
      if (dmin2 > R2) continue;
      const double reach = std::sqrt(R2 - dmin2);  // the most a vertex of the cell adds
      for (std::uint32_t k = start_[c]; k < start_[c + 1]; ++k) {
        const Vec3& v = pts_[k];
        if (v.z + reach <= best) break;  // highest first
        const double d2 = (v.x - p.x) * (v.x - p.x) + (v.y - p.y) * (v.y - p.y);
        if (d2 > R2) continue;
        best = std::max(best, v.z + std::sqrt(R2 - d2));
      }
    }
  }
  return best;
}

double MeshContacts::edge_height(Vec2 p, double R, double best) const {
  if (enx_ == 0) return best;
  const double R2 = R * R;
  const int i0 = std::max(0, static_cast<int>(std::floor((p.x - R - eorigin_.x) / ecell_)));
  const int i1 = std::min(enx_ - 1, static_cast<int>(std::floor((p.x + R - eorigin_.x) / ecell_)));
  const int j0 = std::max(0, static_cast<int>(std::floor((p.y - R - eorigin_.y) / ecell_)));
  const int j1 = std::min(eny_ - 1, static_cast<int>(std::floor((p.y + R - eorigin_.y) / ecell_)));
  for (int j = j0; j <= j1; ++j) {
    const double cy = eorigin_.y + j * ecell_;
    const double dy = std::max({cy - p.y, 0.0, p.y - cy - ecell_});
    for (int i = i0; i <= i1; ++i) {
      const std::size_t c = static_cast<std::size_t>(j) * static_cast<std::size_t>(enx_) +
                            static_cast<std::size_t>(i);
      if (ecellmax_[c] + R <= best) continue;
      const double cx = eorigin_.x + i * ecell_;
      const double dx = std::max({cx - p.x, 0.0, p.x - cx - ecell_});
      const double dmin2 = dx * dx + dy * dy;
      if (dmin2 > R2) continue;
      const double reach = std::sqrt(R2 - dmin2);
      for (std::uint32_t k = estart_[c]; k < estart_[c + 1]; ++k) {
        const Edge& g = edges_[eitems_[k]];
        if (g.zmax + reach <= best) break;  // highest first
        // An edge crossing several cells is tried only in the one holding its point nearest
        // to p (it crosses that cell, so it is listed there, and the cell is as near and as
        // high as any).
        const Vec2 a = g.a.xy(), e = g.b.xy() - a;
        const double len2 = norm_sq(e);
        const double t = len2 > 0.0 ? std::clamp(dot(p - a, e) / len2, 0.0, 1.0) : 0.0;
        const Vec2 q = a + e * t;
        const int ci =
            std::clamp(static_cast<int>(std::floor((q.x - eorigin_.x) / ecell_)), 0, enx_ - 1);
        const int cj =
            std::clamp(static_cast<int>(std::floor((q.y - eorigin_.y) / ecell_)), 0, eny_ - 1);
        if (ci != i || cj != j) continue;
        const double d2 = norm_sq(q - p);
        if (d2 > R2 || g.zmax + std::sqrt(R2 - d2) <= best) continue;
        best = std::max(best, ball_on_segment_centre(g.a, g.b, p, R));
      }
    }
  }
  return best;
}

}  // namespace swarf::trislice_detail
