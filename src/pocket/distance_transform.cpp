#include "pocket/distance_transform.h"

#include <algorithm>
#include <cmath>

namespace swarf::pocket {

namespace {

constexpr float kInf = 1e20f;

// 1D squared distance transform of f (Felzenszwalb-Huttenlocher, Algorithm 1), in place.
// Doubles inside: float loses the parabola intersections for images of a few thousand pixels.
void dt1d(float* f, int n, std::ptrdiff_t stride, std::vector<double>& d, std::vector<int>& v,
          std::vector<double>& z) {
  int k = 0;
  v[0] = 0;
  z[0] = -kInf;
  z[1] = kInf;
  auto F = [&](int q) { return static_cast<double>(f[q * stride]); };
  for (int q = 1; q < n; ++q) {
    if (F(q) >= kInf) continue;
    if (F(v[k]) >= kInf) {  // only infinite parabolas so far: replace
      v[k] = q;
      continue;
    }
    double s = 0.0;
    for (;;) {
      const int p = v[k];
      s = ((F(q) + static_cast<double>(q) * q) - (F(p) + static_cast<double>(p) * p)) /
          (2.0 * (q - p));
      if (s <= z[k] && k > 0) {
        --k;
        continue;
      }
      break;
    }
    ++k;
    v[k] = q;
    z[k] = s;
    z[k + 1] = kInf;
  }
  if (F(v[0]) >= kInf) {
    for (int q = 0; q < n; ++q)
      d[q] = kInf;
  } else {
    k = 0;
    for (int q = 0; q < n; ++q) {
      while (z[k + 1] < q)
        ++k;
      const double dq = q - v[k];
      d[q] = dq * dq + F(v[k]);
    }
  }
  for (int q = 0; q < n; ++q)
    f[q * stride] = static_cast<float>(d[q]);
}

}  // namespace

std::vector<float> squared_distance_transform(const BitImage& features, bool feature_value) {
  const int w = features.width(), h = features.height();
  const std::size_t wz = static_cast<std::size_t>(w);
  std::vector<float> f(wz * static_cast<std::size_t>(h));
  // Columns: for a binary image the 1D transform is the squared distance to the nearest
  // feature in the column, found by one sweep down and one up, a row at a time (in memory
  // order, unlike a column-wise parabola pass). Exact: whole numbers, kept exactly in float.
  // The sweep down leaves its distances in f itself (whole numbers below 2^24, and kFar, a
  // power of two: exact in float), so the image is written twice and no second one is
  // allocated (on the benchmark L its clearing and page faults were about half of the whole
  // run's page faults).
  constexpr int kFar = 1 << 28;
  std::vector<int> run(wz, kFar);
  for (int j = 0; j < h; ++j) {
    float* row = f.data() + static_cast<std::size_t>(j) * wz;
    for (int i = 0; i < w; ++i) {
      int& r = run[static_cast<std::size_t>(i)];
      r = features.get(i, j) == feature_value ? 0 : std::min(kFar, r + 1);
      row[i] = static_cast<float>(r);
    }
  }
  std::fill(run.begin(), run.end(), kFar);
  for (int j = h - 1; j >= 0; --j) {
    float* row = f.data() + static_cast<std::size_t>(j) * wz;
    for (int i = 0; i < w; ++i) {
      const int down = static_cast<int>(row[i]);
      int& r = run[static_cast<std::size_t>(i)];
      r = down == 0 ? 0 : std::min(kFar, r + 1);
      const int d = std::min(r, down);
      row[i] = d >= kFar ? kInf : static_cast<float>(static_cast<double>(d) * d);
    }
  }
  const int n = w;
  std::vector<double> d(static_cast<std::size_t>(n));
  std::vector<int> v(static_cast<std::size_t>(n));
  std::vector<double> z(static_cast<std::size_t>(n) + 1);
  // Rows: a feature pixel (0) stays 0, and no parabola from beyond one is lowest past it
  // (from q' < p < q, (q - q')^2 + f(q') > (q - p)^2), so each run of other pixels is
  // transformed on its own with the features that bound it: the same minima, and the rows'
  // long feature runs (outside the pocket, islands) cost one comparison a pixel.
  for (int j = 0; j < h; ++j) {
    float* row = f.data() + static_cast<std::size_t>(j) * wz;
    for (int a = 0; a < w;) {
      if (row[a] == 0.0f) {
        ++a;
        continue;
      }
      int b = a;
      while (b + 1 < w && row[b + 1] != 0.0f)
        ++b;
      const int lo = std::max(0, a - 1), hi = std::min(w - 1, b + 1);
      dt1d(row + lo, hi - lo + 1, 1, d, v, z);
      a = b + 2;
    }
  }
  return f;
}

std::vector<int> disk_half_widths(double radius_px) {
  if (radius_px < 0.0) return {};
  // Compared in the same double arithmetic as a threshold on the exact transform's squared
  // values.
  const double r2 = radius_px * radius_px;
  const int reach = static_cast<int>(std::floor(radius_px)) + 1;
  std::vector<int> half(static_cast<std::size_t>(2 * reach + 1), -1);
  for (int dy = -reach; dy <= reach; ++dy) {
    const double rest = r2 - static_cast<double>(dy) * dy;
    if (rest < 0.0) continue;
    int dx = static_cast<int>(std::sqrt(rest));
    while (static_cast<double>(dx + 1) * (dx + 1) + static_cast<double>(dy) * dy <= r2)
      ++dx;
    while (dx >= 0 && static_cast<double>(dx) * dx + static_cast<double>(dy) * dy > r2)
      --dx;
    const int row = dy + reach;
    half[static_cast<std::size_t>(row)] = dx;
  }
  return half;
}

bool near_set_pixel(const BitImage& img, const std::vector<int>& half, int i, int j, int x0, int y0,
                    int x1, int y1) {
  const int reach = static_cast<int>(half.size() / 2);
  x0 = std::max(x0, 0);
  y0 = std::max(y0, 0);
  x1 = std::min(x1, img.width() - 1);
  y1 = std::min(y1, img.height() - 1);
  for (int dy = -reach; dy <= reach; ++dy) {
    const int row = dy + reach;
    const int dx = half[static_cast<std::size_t>(row)];
    const int jj = j + dy;
    if (dx < 0 || jj < y0 || jj > y1) continue;
    const int lo = std::max(x0, i - dx), hi = std::min(x1, i + dx);
    if (lo <= hi && img.first_set(jj, lo, hi) >= 0) return true;
  }
  return false;
}

BitImage dilate_by_disk(const BitImage& img, double radius_px) {
  const int w = img.width(), h = img.height();
  BitImage out(w, h);
  if (radius_px < 0.0) return out;
  const std::vector<int> half = disk_half_widths(radius_px);
  const int reach = static_cast<int>(half.size() / 2);
  const int nw = img.words_per_row();
  auto word = [&](int j, int wd) {
    return j < 0 || j >= h || wd < 0 || wd >= nw ? std::uint64_t{0} : img.word(j, wd);
  };
  for (int j = 0; j < h; ++j)
    for (int wd = 0; wd < nw; ++wd) {
      const std::uint64_t b = word(j, wd);
      out.set_word(j, wd, out.word(j, wd) | b);
      // Set pixels whose four neighbours are all set (outside the image counts as unset)
      // need no disk: their neighbours' disks cover theirs.
      const std::uint64_t left = (b << 1) | (word(j, wd - 1) >> 63);
      const std::uint64_t right = (b >> 1) | (word(j, wd + 1) << 63);
      std::uint64_t edge = b & ~(left & right & word(j - 1, wd) & word(j + 1, wd));
      for (; edge != 0; edge &= edge - 1) {
        const int i = wd * 64 + __builtin_ctzll(edge);
        for (int dy = -reach; dy <= reach; ++dy) {
          const int row = dy + reach;
          const int dx = half[static_cast<std::size_t>(row)];
          const int jj = j + dy;
          if (dx < 0 || jj < 0 || jj >= h) continue;
          out.set_span(jj, std::max(0, i - dx), std::min(w - 1, i + dx));
        }
      }
    }
  return out;
}

std::vector<int> medial_axis(const std::vector<float>& squared_d, int width, int height,
                             double min_d) {
  std::vector<int> out;
  const double slack = 0.8;
  const double reach[2] = {slack, slack * std::sqrt(2.0)};  // edge, diagonal neighbours
  const double min_sq = min_d * min_d;
  for (int j = 1; j + 1 < height; ++j)
    for (int i = 1; i + 1 < width; ++i) {
      const std::size_t idx = static_cast<std::size_t>(j) * width + i;
      const double sq = static_cast<double>(squared_d[idx]);
      if (sq < min_sq || squared_d[idx] >= kInf) continue;
      const double dp = std::sqrt(sq);
      // q swallows p when d(q) >= d(p) + slack |p - q|; compared squared (both sides >= 0).
      bool ridge = true;
      for (int dj = -1; dj <= 1 && ridge; ++dj)
        for (int di = -1; di <= 1; ++di) {
          if (di == 0 && dj == 0) continue;
          const double need = dp + reach[di != 0 && dj != 0 ? 1 : 0];
          const std::ptrdiff_t q =
              static_cast<std::ptrdiff_t>(idx) + static_cast<std::ptrdiff_t>(dj) * width + di;
          if (static_cast<double>(squared_d[static_cast<std::size_t>(q)]) >= need * need) {
            ridge = false;
            break;
          }
        }
      if (ridge) out.push_back(static_cast<int>(idx));
    }
  return out;
}

}  // namespace swarf::pocket
