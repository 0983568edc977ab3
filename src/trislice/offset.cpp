// seed 001 Eq. (1): convolutional offset of slice families.
#include "swarf/trislice/offset.h"

#include <cmath>
#include <string>

#include "swarf/core/parallel.h"

namespace swarf {

long lattice_index(const SliceFamily& family, std::size_t j) {
  return std::lround(family.first_level / family.pitch_mm) + static_cast<long>(j);
}

PolygonSet convolve_slice(const SliceFamily& family, long level_index, double r_mm,
                          const ConvolutionOptions& options) {
  const double r = std::fabs(r_mm);
  const double ds = family.pitch_mm;
  const long base = std::lround(family.first_level / ds);
  const long i = level_index - base;  // index into family.slices (may be outside)
  const long nr = static_cast<long>(std::floor(r / ds + 1e-9));
  const long n = static_cast<long>(family.size());
  OffsetOptions oo;
  oo.arc_tolerance_mm = options.arc_tolerance_mm;
  if (r_mm >= 0.0) {
    std::vector<PolygonSet> parts;
    const long m = std::max(1, options.neighbour_stride);
    for (long j = i - (nr / m) * m; j <= i + nr; j += m) {
      if (j < 0 || j >= n) continue;
      const PolygonSet& s = family.slices[static_cast<std::size_t>(j)];
      if (s.empty()) continue;
      const double dz = static_cast<double>(i - j) * ds;
      const double rho = std::sqrt(std::max(0.0, r * r - dz * dz));  // seed 001 Eq. (1)
      parts.push_back(offset(s, rho, oo));
    }
    return unite(std::span<const PolygonSet>(parts));
  }
  // Shrinkage: every slice within r must contain the shrunk disc; one missing slice (beyond
  // the family or empty) empties the result.
  if (i - nr < 0 || i + nr >= n) return {};
  std::vector<PolygonSet> parts;
  // Nearest slices first: they are the most restrictive, so the running intersection
  // shrinks fast and later steps are cheap.
  const long m = std::max(1, options.neighbour_stride);
  for (long k = 0; k <= nr; k += m) {
    const long js[2] = {i - k, i + k};
    for (int side = 0; side < (k == 0 ? 1 : 2); ++side) {
      const long j = js[side];
      const PolygonSet& s = family.slices[static_cast<std::size_t>(j)];
      if (s.empty()) return {};
      const double dz = static_cast<double>(i - j) * ds;
      const double rho = std::sqrt(std::max(0.0, r * r - dz * dz));  // seed 001 Eq. (1)
      parts.push_back(offset(s, -rho, oo));
      if (parts.back().empty()) return {};
    }
  }
  return intersect(std::span<const PolygonSet>(parts));
}

Result<SliceFamily> offset_family(const SliceFamily& family, double r_mm,
                                  const ConvolutionOptions& options, const Context& ctx) {
  if (!std::isfinite(r_mm)) return bad_parameter("convolutional offset: non-finite radius");
  if (!(family.pitch_mm > 0.0))
    return bad_parameter("convolutional offset: pitch must be positive");
  if (!(options.arc_tolerance_mm > 0.0))
    return bad_parameter("convolutional offset: arc tolerance must be positive");
  SliceFamily out;
  out.axis = family.axis;
  out.pitch_mm = family.pitch_mm;
  const long extra = r_mm > 0.0 ? static_cast<long>(std::ceil(r_mm / family.pitch_mm - 1e-9)) : 0;
  const long base = std::lround(family.first_level / family.pitch_mm) - extra;
  out.first_level = static_cast<double>(base) * family.pitch_mm;
  out.slices.resize(family.size() + 2 * static_cast<std::size_t>(extra));
  parallel_for(out.slices.size(), ctx.threads, [&](std::size_t j) {
    if (ctx.cancelled()) return;
    out.slices[j] = convolve_slice(family, base + static_cast<long>(j), r_mm, options);
  });
  if (ctx.cancelled()) return Status{Error::kCancelled, "convolutional offset: cancelled"};
  return out;
}

Result<TriSliceModel> offset_model(const TriSliceModel& model, double r_mm,
                                   const ConvolutionOptions& options, const Context& ctx) {
  TriSliceModel out;
  out.pitch_mm = model.pitch_mm;
  out.bounds = model.bounds.inflated(r_mm);
  for (int a = 0; a < 3; ++a) {
    auto fam = offset_family(model.families[static_cast<std::size_t>(a)], r_mm, options, ctx);
    if (!fam.ok()) return fam.status();
    out.families[static_cast<std::size_t>(a)] = std::move(fam).value();
    ctx.report("convolutional offset", (a + 1) / 3.0);
  }
  return out;
}

PolygonSet inflate_at_level(const SliceFamily& family, double level, double r_mm,
                            const ConvolutionOptions& options) {
  std::vector<PolygonSet> parts;
  OffsetOptions oo;
  oo.arc_tolerance_mm = options.arc_tolerance_mm;
  for (std::size_t j = 0; j < family.size(); ++j) {
    const double dz = level - family.level(j);
    if (std::fabs(dz) > r_mm || family.slices[j].empty()) continue;
    parts.push_back(offset(family.slices[j], std::sqrt(r_mm * r_mm - dz * dz), oo));
  }
  return unite(std::span<const PolygonSet>(parts));
}

}  // namespace swarf
