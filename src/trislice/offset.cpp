// seed 001 Eq. (1): convolutional offset of slice families.
#include "swarf/trislice/offset.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <span>
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

std::vector<PolygonSet> convolve_slices(const SliceFamily& family, long first_index,
                                        std::size_t count, double r_mm,
                                        const ConvolutionOptions& options, const Context& ctx) {
  std::vector<PolygonSet> out(count);
  const double r = std::fabs(r_mm);
  const double ds = family.pitch_mm;
  const long base = std::lround(family.first_level / ds);
  const long nr = static_cast<long>(std::floor(r / ds + 1e-9));
  const long n = static_cast<long>(family.size());
  const long m = std::max(1, options.neighbour_stride);
  const long K = nr / m;  // neighbours at distances k m, k = 0..K (as convolve_slice)
  const bool grow = r_mm >= 0.0;
  OffsetOptions oo;
  oo.arc_tolerance_mm = options.arc_tolerance_mm;
  // Windows of levels bound the cache: (window + 2 K m) slices x (K + 1) offsets.
  const long window = 512;
  for (long w0 = 0; w0 < static_cast<long>(count); w0 += window) {
    const long w1 = std::min(static_cast<long>(count), w0 + window) - 1;
    const long t0 = first_index - base + w0, t1 = first_index - base + w1;  // slice indices
    // A level i is computed at all (shrinkage: every slice within r must exist).
    auto live = [&](long i) { return grow || (i - nr >= 0 && i + nr < n); };
    const long jlo = std::max(0L, t0 - K * m), jhi = std::min(n - 1, t1 + K * m);
    if (jlo > jhi) continue;
    const std::size_t nj = static_cast<std::size_t>(jhi - jlo + 1);
    const std::size_t nk = static_cast<std::size_t>(K + 1);
    std::vector<PolygonSet> cache(nj * nk);
    parallel_for(nj, ctx.threads, [&](std::size_t q) {
      if (ctx.cancelled()) return;
      const long j = jlo + static_cast<long>(q);
      const PolygonSet& given = family.slices[static_cast<std::size_t>(j)];
      if (given.empty()) return;
      const PolygonSet s =
          options.simplify_mm > 0.0 ? simplified(given, options.simplify_mm) : given;
      for (long k = 0; k <= K; ++k) {
        const long a = j - k * m, b = j + k * m;
        if (!((a >= t0 && a <= t1 && live(a)) || (b >= t0 && b <= t1 && live(b)))) continue;
        const double dz = static_cast<double>(k * m) * ds;
        const double rho = std::sqrt(std::max(0.0, r * r - dz * dz));  // seed 001 Eq. (1)
        cache[q * nk + static_cast<std::size_t>(k)] = offset(s, grow ? rho : -rho, oo);
      }
    });
    auto at = [&](long j, long k) -> const PolygonSet& {
      return cache[static_cast<std::size_t>(j - jlo) * nk + static_cast<std::size_t>(k)];
    };
    parallel_for(static_cast<std::size_t>(w1 - w0 + 1), ctx.threads, [&](std::size_t q) {
      if (ctx.cancelled()) return;
      const long i = t0 + static_cast<long>(q);
      PolygonSet& res = out[static_cast<std::size_t>(w0) + q];
      std::vector<PolygonSet> parts;
      if (grow) {  // the same parts in the same order as convolve_slice
        for (long j = i - K * m; j <= i + nr; j += m) {
          if (j < 0 || j >= n || family.slices[static_cast<std::size_t>(j)].empty()) continue;
          parts.push_back(at(j, std::labs(i - j) / m));
        }
        res = unite(std::span<const PolygonSet>(parts));
        return;
      }
      if (!live(i)) return;
      for (long k = 0; k <= nr; k += m) {
        const long js[2] = {i - k, i + k};
        for (int side = 0; side < (k == 0 ? 1 : 2); ++side) {
          const long j = js[side];
          if (family.slices[static_cast<std::size_t>(j)].empty()) return;
          parts.push_back(at(j, k / m));
          if (parts.back().empty()) return;
        }
      }
      res = intersect(std::span<const PolygonSet>(parts));
    });
    if (ctx.cancelled()) return {};
  }
  return out;
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
