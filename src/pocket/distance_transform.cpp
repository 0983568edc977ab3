#include "pocket/distance_transform.h"

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
  std::vector<float> f(static_cast<std::size_t>(w) * h);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i)
      f[static_cast<std::size_t>(j) * w + i] = features.get(i, j) == feature_value ? 0.f : kInf;
  const int n = std::max(w, h);
  std::vector<double> d(n);
  std::vector<int> v(n);
  std::vector<double> z(n + 1);
  for (int i = 0; i < w; ++i)
    dt1d(f.data() + i, h, w, d, v, z);  // columns
  for (int j = 0; j < h; ++j)
    dt1d(f.data() + static_cast<std::size_t>(j) * w, w, 1, d, v, z);
  return f;
}

std::vector<int> medial_axis(const std::vector<float>& squared_d, int width, int height,
                             double min_d) {
  std::vector<int> out;
  const double slack = 0.8;
  for (int j = 1; j + 1 < height; ++j)
    for (int i = 1; i + 1 < width; ++i) {
      const std::size_t idx = static_cast<std::size_t>(j) * width + i;
      const double dp = std::sqrt(static_cast<double>(squared_d[idx]));
      if (dp < min_d || squared_d[idx] >= kInf) continue;
      bool ridge = true;
      for (int dj = -1; dj <= 1 && ridge; ++dj)
        for (int di = -1; di <= 1; ++di) {
          if (di == 0 && dj == 0) continue;
          const double dq = std::sqrt(static_cast<double>(squared_d[idx + dj * width + di]));
          if (dq >= dp + slack * std::sqrt(static_cast<double>(di * di + dj * dj))) {
            ridge = false;
            break;
          }
        }
      if (ridge) out.push_back(static_cast<int>(idx));
    }
  return out;
}

}  // namespace swarf::pocket
