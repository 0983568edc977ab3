#include "swarf/pocket/pocket_input.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <span>
#include <sstream>
#include <utility>

#include <nlohmann/json.hpp>

#include "pocket/geometry.h"
#include "pocket/pocket_input_internal.h"

namespace swarf {

namespace {

// snprintf rather than string concatenation: GCC 12 warns falsely (-Wrestrict) on the latter.
std::string fmt(Vec2 p) {
  char b[64];
  std::snprintf(b, sizeof b, "(%.6g, %.6g)", p.x, p.y);
  return b;
}

std::string ring_name(std::size_t i) {
  return i == 0 ? std::string("outer boundary") : "island " + std::to_string(i);
}

// Inputs larger than this are rejected rather than checked for hours (and the fuzzer
// stays fast); real pockets have a few thousand points.
constexpr std::size_t kMaxPoints = 200000;

// Islands that overlap or touch each other or the outer boundary (a boss drawn across the
// wall, two bosses drawn as overlapping circles): the pocket is the outer ring's inside
// minus the union of the islands, by Clipper on its 1e-5 mm grid. Each part the islands
// cut the pocket into is cleared (the adaptive pocket enters each where no cleared way
// leads); the largest part's outer ring comes first. What was merged is said in the notes.
Result<Pocket> merged_pocket(const std::vector<Ring>& rings,
                             const std::vector<std::pair<std::size_t, std::size_t>>& pairs,
                             const std::string& src) {
  std::vector<PolygonSet> islands;
  for (std::size_t i = 1; i < rings.size(); ++i)
    islands.push_back(normalized(PolygonSet{{rings[i]}}));
  const PolygonSet region =
      subtract(normalized(PolygonSet{{rings[0]}}), unite(std::span<const PolygonSet>(islands)));
  std::vector<PolygonSet> parts = connected_parts(region);
  if (parts.empty()) return bad_input(src + ": the islands cover the whole pocket");
  std::stable_sort(parts.begin(), parts.end(),
                   [](const PolygonSet& a, const PolygonSet& b) { return area(a) > area(b); });
  Pocket p;
  p.source = src;
  for (PolygonSet& part : parts) {
    for (Ring& r : part.rings)
      p.region.rings.push_back(std::move(r));
  }
  std::string walls, overlaps;
  int n_walls = 0;
  for (const auto& [a, b] : pairs) {
    std::string& list = a == 0 ? walls : overlaps;
    n_walls += a == 0 ? 1 : 0;
    list += (list.empty() ? "" : ", ") +
            (a == 0 ? std::to_string(b) : std::to_string(a) + " and " + std::to_string(b));
  }
  if (n_walls == 1) {
    p.notes.push_back(src + ": island " + walls +
                      " crosses or touches the outer boundary: the wall follows it");
  } else if (n_walls > 1) {
    p.notes.push_back(src + ": islands " + walls +
                      " cross or touch the outer boundary: the wall follows them");
  }
  if (!overlaps.empty())
    p.notes.push_back(src + ": islands " + overlaps + " overlap or touch: cut round as one");
  if (parts.size() > 1) {
    p.notes.push_back(src + ": the islands divide the pocket into " + std::to_string(parts.size()) +
                      " separate areas, each entered on its own");
  }
  return p;
}

}  // namespace

Result<Pocket> make_pocket(Ring outer, std::vector<Ring> islands, std::string_view source) {
  const std::string src(source);
  std::vector<Ring> rings;
  rings.push_back(std::move(outer));
  for (Ring& r : islands)
    rings.push_back(std::move(r));
  std::size_t total = 0;
  for (std::size_t i = 0; i < rings.size(); ++i) {
    for (std::size_t k = 0; k < rings[i].size(); ++k)
      if (!std::isfinite(rings[i][k].x) || !std::isfinite(rings[i][k].y))
        return bad_input(src + ": " + ring_name(i) + ": point " + std::to_string(k) +
                         " has a non-finite coordinate");
    rings[i] = pocket::cleaned_ring(rings[i], 1e-9);
    total += rings[i].size();
    if (rings[i].size() < 3)
      return bad_input(src + ": " + ring_name(i) + ": fewer than 3 distinct points");
  }
  if (total > kMaxPoints)
    return bad_input(src + ": " + std::to_string(total) + " points, more than the " +
                     std::to_string(kMaxPoints) + " accepted");
  const pocket::RingContacts contacts = pocket::find_ring_contacts(rings);
  if (const auto& x = contacts.self_crossing) {
    return bad_input(src + ": " + ring_name(x->ring_a) + " intersects itself: edge " +
                     std::to_string(x->edge_a) + " meets edge " + std::to_string(x->edge_b) +
                     " at " + fmt(x->point));
  }
  for (std::size_t i = 0; i < rings.size(); ++i) {
    if (std::abs(pocket::ring_area(rings[i])) < 1e-9)
      return bad_input(src + ": " + ring_name(i) + ": encloses no area");
  }
  const auto touch = [&](std::size_t a, std::size_t b) {
    return std::binary_search(contacts.pairs.begin(), contacts.pairs.end(),
                              std::pair{std::min(a, b), std::max(a, b)});
  };
  // Rings that do not touch: one vertex tells on which side of the other a whole ring lies.
  for (std::size_t i = 1; i < rings.size(); ++i) {
    if (!touch(0, i) && !pocket::point_in_ring(rings[0], rings[i][0])) {
      return bad_input(src + ": " + ring_name(i) + " at " + fmt(rings[i][0]) +
                       " lies outside the outer boundary");
    }
    for (std::size_t j = 1; j < rings.size(); ++j) {
      if (j != i && !touch(i, j) && pocket::point_in_ring(rings[j], rings[i][0])) {
        return bad_input(src + ": " + ring_name(i) + " lies inside " + ring_name(j) +
                         " (a pocket inside a boss needs its own job)");
      }
    }
  }
  if (!contacts.pairs.empty()) return merged_pocket(rings, contacts.pairs, src);
  Pocket p;
  p.source = src;
  for (std::size_t i = 0; i < rings.size(); ++i) {
    const bool ccw = pocket::ring_area(rings[i]) > 0.0;
    if (ccw != (i == 0)) std::reverse(rings[i].begin(), rings[i].end());
    p.region.rings.push_back(std::move(rings[i]));
  }
  return p;
}

namespace pocket {

namespace {

// One outline of a drawing and the loops inside it: the largest loop is the outer boundary,
// the others islands.
Result<Pocket> pocket_from_outline(Ring outer_loop, std::vector<Ring> islands,
                                   std::string_view source) {
  auto p = make_pocket(outer_loop, islands, source);
  if (!p.ok() || p->notes.empty()) return p;
  const PolygonSet outline = normalized(PolygonSet{{outer_loop}});
  // A drawing's loops have no roles but their sizes. A loop inside the outline, touching it
  // or another loop, is a boss; one that crosses the outline, partly outside it, may as well
  // be part of the pocket drawn as a second shape as a boss on the wall: refused rather than
  // guessed (JSON names its islands, and there such an island is merged).
  for (std::size_t i = 0; i < islands.size(); ++i) {
    const PolygonSet loop = normalized(PolygonSet{{islands[i]}});
    if (area(subtract(loop, outline)) > 1e-6 && area(intersect(loop, outline)) > 1e-6) {
      return bad_input(std::string(source) + ": island " + std::to_string(i + 1) +
                       " (a closed loop of the drawing) crosses the outer boundary (the largest "
                       "loop): a boss on the wall or part of the pocket? Draw the outline as one "
                       "loop, or name the islands in a JSON pocket");
    }
  }
  return p;
}

}  // namespace

// A drawing may hold several outlines side by side (separate pockets drawn together): a
// loop that lies outside every larger loop, and neither crosses nor touches one, starts an
// outline of its own; every other loop is an island of the largest outline it lies in or
// meets (the checks of one outline then refuse what is not an island). Several outlines
// are one region in several parts, largest first, each entered on its own.
Result<Pocket> pocket_from_loops(std::vector<Ring> loops, std::string_view source) {
  if (loops.empty()) return bad_input(std::string(source) + ": no closed outline found");
  std::stable_sort(loops.begin(), loops.end(), [](const Ring& a, const Ring& b) {
    return std::abs(ring_area(a)) > std::abs(ring_area(b));
  });
  struct Outline {
    Ring outer;
    PolygonSet shape;
    std::vector<Ring> islands;
  };
  std::vector<Outline> outlines;
  for (std::size_t k = 0; k < loops.size(); ++k) {
    Ring& loop = loops[k];
    const PolygonSet shape = normalized(PolygonSet{{loop}});
    Outline* in = nullptr;
    for (std::size_t j = 0; j < outlines.size() && in == nullptr; ++j) {
      Outline& o = outlines[j];
      // A loop of fewer than 3 points, or one beside such an outline, goes with it: the
      // checks of one outline name it (found by the fuzzer: an empty loop).
      if (loop.size() < 3 || o.outer.size() < 3 || point_in_ring(o.outer, loop.front()) ||
          area(intersect(shape, o.shape)) > 1e-9) {
        in = &o;
      } else if (!find_ring_contacts({cleaned_ring(o.outer, 1e-9), cleaned_ring(loop, 1e-9)})
                      .pairs.empty()) {
        return bad_input(std::string(source) + ": a closed loop of the drawing (the " +
                         std::to_string(k + 1) + ". largest) touches outline " +
                         std::to_string(j + 1) +
                         " from outside: draw the two as one outline, or as outlines apart");
      }
    }
    if (in != nullptr) {
      in->islands.push_back(std::move(loop));
    } else {
      outlines.push_back({loop, shape, {}});
    }
  }
  if (outlines.size() == 1) {
    return pocket_from_outline(std::move(outlines[0].outer), std::move(outlines[0].islands),
                               source);
  }
  Pocket all;
  all.source = std::string(source);
  for (Outline& o : outlines) {
    auto p = pocket_from_outline(std::move(o.outer), std::move(o.islands), source);
    if (!p) return p.status();
    all.region.rings.insert(all.region.rings.end(), p->region.rings.begin(), p->region.rings.end());
    all.notes.insert(all.notes.end(), p->notes.begin(), p->notes.end());
  }
  all.notes.push_back(std::string(source) + ": " + std::to_string(outlines.size()) +
                      " separate outlines (none inside another), each cleared on its own");
  return all;
}

}  // namespace pocket

namespace {

Result<Ring> json_ring(const nlohmann::json& j, const std::string& where) {
  if (!j.is_array()) return bad_input(where + ": expected an array of [x, y] points");
  Ring r;
  for (std::size_t k = 0; k < j.size(); ++k) {
    const auto& p = j[k];
    if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number())
      return bad_input(where + ": point " + std::to_string(k) + " is not [x, y] numbers");
    r.push_back({p[0].get<double>(), p[1].get<double>()});
  }
  return r;
}

}  // namespace

Result<Pocket> parse_pocket_json(std::string_view text, std::string_view source) {
  const std::string src(source);
  nlohmann::json j = nlohmann::json::parse(text.begin(), text.end(), nullptr, false);
  if (j.is_discarded()) return bad_input(src + ": not valid JSON");
  if (!j.is_object() || !j.contains("outer"))
    return bad_input(src + ": expected an object with an \"outer\" array of [x, y] points");
  auto outer = json_ring(j["outer"], src + ": outer");
  if (!outer) return outer.status();
  std::vector<Ring> islands;
  if (j.contains("islands")) {
    const auto& is = j["islands"];
    if (!is.is_array()) return bad_input(src + ": \"islands\" must be an array of rings");
    for (std::size_t i = 0; i < is.size(); ++i) {
      auto r = json_ring(is[i], src + ": island " + std::to_string(i + 1));
      if (!r) return r.status();
      islands.push_back(std::move(r.value()));
    }
  }
  return make_pocket(std::move(outer.value()), std::move(islands), source);
}

Result<Pocket> read_pocket(const std::string& path, const CurveInputOptions& options) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Status(Error::kIo, path + ": cannot open the pocket file");
  std::ostringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  std::string ext;
  if (const auto dot = path.rfind('.'); dot != std::string::npos) ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == "json") return parse_pocket_json(text, path);
  if (ext == "svg") return parse_pocket_svg(text, path, options);
  if (ext == "dxf") return parse_pocket_dxf(text, path, options);
  return bad_input(path + ": unknown pocket format '" + ext + "' (expected .json, .svg or .dxf)");
}

}  // namespace swarf
