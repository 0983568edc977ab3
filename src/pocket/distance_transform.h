// Exact Euclidean distance transform (Felzenszwalb and Huttenlocher 2012: lower envelope of
// parabolas, two separable passes, linear time) and the discrete medial axis of seed 000
// section 4.2 (ridge pixels of the transform).
#pragma once

#include <vector>

#include "pocket/pixel_stock.h"

namespace swarf::pocket {

/// Squared distance, in pixels^2, from every pixel centre to the nearest pixel whose bit
/// in `features` equals `feature_value`. Exact for pixel centres. 1e20 where there is none.
std::vector<float> squared_distance_transform(const BitImage& features, bool feature_value);

/// Ridge pixels of a distance field d (pixels): p is kept when no 8-neighbour q has
/// d(q) >= d(p) + 0.8 |p - q|, i.e. no neighbour's maximal disk swallows p's (Blum's
/// maximal-disk criterion with slack for the grid). Only pixels with d >= min_d qualify.
std::vector<int> medial_axis(const std::vector<float>& squared_d, int width, int height,
                             double min_d);

}  // namespace swarf::pocket
