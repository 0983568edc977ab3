// Helpers shared by the tri-slice path strategies (surface_paths.cpp: scans, waterline.cpp:
// contours).
#pragma once

#include <string>

#include "swarf/core/status.h"
#include "swarf/tool/tool.h"
#include "swarf/toolpath/toolpath.h"
#include "swarf/trislice/model.h"

namespace swarf::trislice_detail {

/// The tool is valid and a ball end mill (seed 001's paths are for one).
Status need_ball(const Tool& tool);
/// `given` when finite, else 5 mm above the model's top (or `extra_top`, if higher).
double clearance_of(double given, const TriSliceModel& model, double extra_top);
/// An empty toolpath named `name` for `tool`, with its clearance plane.
Toolpath new_toolpath(const Tool& tool, std::string name, double clearance);

}  // namespace swarf::trislice_detail
