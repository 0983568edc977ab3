// The adaptive pocket's summary figures (seed 000's quality measures: cutting and air
// length, time, engagement mean / p5 / p95, share within +-20 %, largest deviation) and its
// per-step table.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <utility>
#include <vector>

#include "pocket/adaptive_internal.h"
#include "swarf/pocket/adaptive.h"

namespace swarf {

AdaptiveSummary summarize(const AdaptiveResult& r, const AdaptiveParams& p) {
  AdaptiveSummary s;
  std::vector<std::pair<double, double>> eng;  // angle, length
  const double cut_px = pocket::cut_threshold_px(r.target_engagement_px);
  for (const AdaptiveStep& st : r.steps) {
    if (st.plunged) {
      // Plunged through, then passed in the air: neither a cut nor a link of the path.
      s.plunged_length_mm += st.length_mm;
    } else if (st.engagement_px > cut_px) {
      s.cutting_length_mm += st.length_mm;
      eng.push_back({st.engagement_deg, st.length_mm});
      s.max_deviation_deg = std::max(s.max_deviation_deg, st.deviation_deg);
      if (std::abs(st.engagement_deg - r.target_engagement_deg) <= 0.2 * r.target_engagement_deg)
        s.within_20pct += st.length_mm;
    } else {
      s.air_length_mm += st.length_mm;
    }
  }
  const double layers = std::max(1, r.layers);
  s.time_s = ((s.cutting_length_mm + s.plunged_length_mm) / p.feed_mm_min +
              (s.air_length_mm + s.plunged_length_mm) / pocket::link_feed_mm_min(p)) *
             layers * 60.0;
  if (s.cutting_length_mm > 0) s.within_20pct /= s.cutting_length_mm;
  if (!eng.empty()) {
    double sum = 0.0;
    for (auto [a, l] : eng)
      sum += a * l;
    s.engagement_mean_deg = sum / s.cutting_length_mm;
    std::sort(eng.begin(), eng.end());
    auto pct = [&](double q) {
      double acc = 0.0;
      for (auto [a, l] : eng) {
        acc += l;
        if (acc >= q * s.cutting_length_mm) return a;
      }
      return eng.back().first;
    };
    s.engagement_p5_deg = pct(0.05);
    s.engagement_p95_deg = pct(0.95);
  }
  return s;
}

std::string summary_line(const AdaptiveSummary& s) {
  char b[320];
  std::snprintf(b, sizeof b,
                "cutting %.1f mm, air %.1f mm, time %.1f s, engagement mean/p5/p95 "
                "%.1f/%.1f/%.1f deg (%.0f %% within +-20 %%), max deviation %.1f deg",
                s.cutting_length_mm, s.air_length_mm, s.time_s, s.engagement_mean_deg,
                s.engagement_p5_deg, s.engagement_p95_deg, 100.0 * s.within_20pct,
                s.max_deviation_deg);
  return b;
}

std::string steps_csv(const AdaptiveResult& r) {
  std::ostringstream o;
  o << "index,x,y,kind,engagement_px,engagement_deg,deviation_deg,length_mm\n";
  char b[256];
  for (std::size_t k = 0; k < r.steps.size(); ++k) {
    const AdaptiveStep& s = r.steps[k];
    const char* kind = s.plunged                       ? "neck"
                       : s.kind == StepKind::kCut      ? "cut"
                       : s.kind == StepKind::kBoundary ? "boundary"
                                                       : "link";
    std::snprintf(b, sizeof b, "%zu,%.4f,%.4f,%s,%d,%.2f,%.2f,%.4f\n", k, s.position.x,
                  s.position.y, kind, s.engagement_px, s.engagement_deg, s.deviation_deg,
                  s.length_mm);
    o << b;
  }
  return o.str();
}

}  // namespace swarf
