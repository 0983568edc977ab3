// Exact Euclidean distance transform (Felzenszwalb and Huttenlocher 2012: lower envelope of
// parabolas, two separable passes, linear time), the dilation by a disk, and the discrete
// medial axis of seed 000 section 4.2 (ridge pixels of the transform).
#pragma once

#include <vector>

#include "pocket/pixel_stock.h"

namespace swarf::pocket {

/// Squared distance, in pixels^2, from every pixel centre to the nearest pixel whose bit
/// in `features` equals `feature_value`. Exact for pixel centres. 1e20 where there is none.
std::vector<float> squared_distance_transform(const BitImage& features, bool feature_value);

/// The pixels within `radius_px` of a set pixel of img (centre to centre, squared distance
/// <= radius_px^2): the same set as thresholding squared_distance_transform(img, true) at
/// radius_px^2, found by stamping disks on the set's boundary pixels only (the nearest set
/// pixel to an unset one always has an unset 4-neighbour). Linear in the boundary's length
/// times the disk's rows: a few percent of a full transform for a tool-sized radius.
BitImage dilate_by_disk(const BitImage& img, double radius_px);

/// The half widths of that disk's rows, dy = -reach .. reach at index dy + reach (reach =
/// floor(radius_px) + 1): the largest whole dx with dx^2 + dy^2 <= radius_px^2, -1 for a
/// row the disk misses. Empty for a negative radius.
std::vector<int> disk_half_widths(double radius_px);

/// Whether pixel (i, j) is in dilate_by_disk(img, radius) with img's set pixels taken only
/// inside [x0, x1] x [y0, y1] (`half` from disk_half_widths(radius)): the same answer for one
/// pixel, scanning its disk's rows, where a search asks about few of a window's pixels.
bool near_set_pixel(const BitImage& img, const std::vector<int>& half, int i, int j, int x0, int y0,
                    int x1, int y1);

/// Ridge pixels of a distance field d (pixels): p is kept when no 8-neighbour q has
/// d(q) >= d(p) + 0.8 |p - q|, i.e. no neighbour's maximal disk swallows p's (Blum's
/// maximal-disk criterion with slack for the grid). Only pixels with d >= min_d qualify.
std::vector<int> medial_axis(const std::vector<float>& squared_d, int width, int height,
                             double min_d);

}  // namespace swarf::pocket
