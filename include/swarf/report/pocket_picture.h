// The adaptive pocket's engagement picture (seed 000 Fig. 2 right) for reports.
#pragma once

#include "swarf/pocket/adaptive.h"
#include "swarf/report/image.h"

namespace swarf {

/// The cut material coloured by the engagement of the step that removed it: blue low, red
/// high (2 x target), material left red-brown, walls dark, entry grey; north up. One picture
/// pixel per simulation pixel up to `max_side` on the longer side; a larger map (a large
/// pocket: up to 60 million simulation pixels) is shown at one pixel per k x k block, the
/// block's centre cell, except that material left anywhere in a block shows in it (a residue
/// must not vanish from the picture).
Image pocket_engagement_picture(const AdaptiveResult& result, int max_side = 4096);

}  // namespace swarf
