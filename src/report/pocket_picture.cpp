#include "swarf/report/pocket_picture.h"

#include <algorithm>
#include <cstdint>

namespace swarf {

Image pocket_engagement_picture(const AdaptiveResult& r, int max_side) {
  const CutMap& m = r.cut_map;
  const int side = std::max(1, max_side);
  const int k = std::max(1, (std::max(m.width, m.height) + side - 1) / side);
  const int w = (m.width + k - 1) / k, h = (m.height + k - 1) / k;
  Image img(w, h, Rgb{40, 40, 40});
  auto cell = [&](int i, int j) {
    return m.cells[static_cast<std::size_t>(j) * static_cast<std::size_t>(m.width) +
                   static_cast<std::size_t>(i)];
  };
  for (int bj = 0; bj < h; ++bj)
    for (int bi = 0; bi < w; ++bi) {
      const int i0 = bi * k, j0 = bj * k;
      const int i1 = std::min(m.width, i0 + k), j1 = std::min(m.height, j0 + k);
      std::uint32_t c = cell((i0 + i1 - 1) / 2, (j0 + j1 - 1) / 2);
      for (int j = j0; j < j1 && c != 1; ++j)
        for (int i = i0; i < i1; ++i)
          if (cell(i, j) == 1) c = 1;
      Rgb& px = img.at(bi, h - 1 - bj);
      if (c == 1) {
        px = Rgb{150, 60, 40};
      } else if (c == 2 || (c >= 3 && c - 3 < r.steps.size() && r.steps[c - 3].plunged)) {
        px = Rgb{200, 200, 200};  // the entries, and the necks plunged through
      } else if (c >= 3 && c - 3 < r.steps.size()) {
        px = heat_color(r.steps[c - 3].engagement_deg / (2.0 * r.target_engagement_deg));
      }
    }
  return img;
}

}  // namespace swarf
