// Parameters shared by the two 2.5D pocket operations (`pocket` and `contour`): layers, stock
// to leave, heights and feeds, in the order their help lists them.
#pragma once

#include <string>
#include <vector>

#include "cli/operation.h"

namespace swarf::cli {

/// `entry` names the entry moves in the help ("helix", "helix and ramp").
inline std::vector<Param> pocket_layer_params(const std::string& entry) {
  return {
      Param{"conventional", ParamType::kBool, false, "conventional instead of climb milling",
            false},
      number_param("depth", 6.0, "pocket depth below the top, mm"),
      number_param("stepdown", 0.0, "depth per layer, mm (0 = whole depth)"),
      number_param("floor_stock", 0.0, "stock left on the floor, mm"),
      number_param("wall_stock", 0.0, "stock left on walls and islands, mm"),
      number_param("top_z", 0.0, "top of the stock, mm"),
      number_param("clearance_z", 5.0, "rapid plane, mm"),
      number_param("feed", 1000.0, "cutting feed, mm/min"),
      number_param("ramp_feed", 0.0, entry + " feed along the path, mm/min (0 = the cutting feed)"),
      number_param("ramp_angle", 3.0, entry + " descent angle, degrees"),
  };
}

/// `first`, then the shared ones, then `last`.
inline std::vector<Param> with_pocket_layer_params(std::vector<Param> first,
                                                   const std::string& entry,
                                                   const std::vector<Param>& last) {
  const std::vector<Param> shared = pocket_layer_params(entry);
  first.insert(first.end(), shared.begin(), shared.end());
  first.insert(first.end(), last.begin(), last.end());
  return first;
}

}  // namespace swarf::cli
