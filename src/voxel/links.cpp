// Seed 003 2.4.3 link searches: the parts that need no cell predicate.
#include "voxel/links.h"

#include <algorithm>
#include <vector>

namespace swarf::voxel_detail {

// Heights a layer's threshold is compared with by the link tests (base heights, and the
// cell reach for the paper's rule), sorted, distinct.
std::vector<double> compared_heights(const Reach& reach) {
  std::vector<double> v = reach.base;
  if (reach.rule == OffsetRule::kPaperSquare)
    v.insert(v.end(), reach.centre.begin(), reach.centre.end());
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

}  // namespace swarf::voxel_detail
