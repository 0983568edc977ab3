// Sequencing of regions that each have two ends (seed 003 section 2.4.3): a travelling
// salesman problem in which every "city" is a region entered at one end and left at the
// other, and an orientation bit per region says which end is the entry. Generic: it knows
// nothing of voxels or toolpaths, only costs between region ends.
//
// Ends are numbered 2*i (end "a" of region i) and 2*i + 1 (end "b"). A region visited with
// orientation 0 is entered at a and left at b; with orientation 1 entered at b, left at a.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "swarf/core/status.h"
#include "swarf/core/vec.h"

namespace swarf {

/// The costs of one instance. cost(p, q) is the price of travelling from the end p where a
/// region is left to the end q where the next region is entered (p and q in [0, 2n)).
struct TwoEndsInstance {
  int regions = 0;
  /// Row-major (2n) x (2n) matrix; entries with p, q of the same region are never used.
  std::vector<double> cost;
  /// Price of entering at end q first (from the tool's start position); empty = all 0.
  std::vector<double> start_cost;
  /// Price of finishing at end p (going home afterwards); empty = all 0.
  std::vector<double> end_cost;

  double at(int from_end, int to_end) const {
    return cost[static_cast<std::size_t>(from_end) * static_cast<std::size_t>(2 * regions) +
                static_cast<std::size_t>(to_end)];
  }
};

/// Builds an instance from a caller-given cost between ends.
TwoEndsInstance make_two_ends_instance(int regions,
                                       const std::function<double(int from_end, int to_end)>& cost);
/// Builds an instance from end points: Euclidean distance plus `lift_penalty` when
/// needs_lift(p, q) says the straight link p -> q is not allowed (needs_lift may be empty).
TwoEndsInstance make_two_ends_instance(const std::vector<Vec3>& end_points, double lift_penalty,
                                       const std::function<bool(int, int)>& needs_lift = {});

/// A tour: the regions in visiting order and each region's orientation bit.
struct TwoEndsTour {
  std::vector<int> order;
  std::vector<std::uint8_t> flipped;  ///< indexed by region: 1 = entered at end b
  double cost = 0.0;

  int entry_end(int region) const { return 2 * region + (flipped[region] ? 1 : 0); }
  int exit_end(int region) const { return 2 * region + (flipped[region] ? 0 : 1); }
};

/// Cost of `order` with the orientations of `flipped` (start, links and end costs).
double tour_cost(const TwoEndsInstance& instance, const std::vector<int>& order,
                 const std::vector<std::uint8_t>& flipped);

/// Best orientations for a fixed order, by dynamic programming over the two states of each
/// position (exact; the paper's Eq. (3.5) picks each k greedily). Fills tour.flipped and
/// tour.cost.
void orient_optimally(const TwoEndsInstance& instance, TwoEndsTour& tour);

struct SequenceOptions {
  /// GA population; 0 = chosen from the size, 20 to 100 as in section 2.5.
  int population = 0;
  int max_generations = 1000;  ///< section 2.5
  /// Early stop: generations without improvement of the best tour.
  int stall_generations = 200;
  double crossover_rate = 0.9;
  double mutation_rate = 0.8;
  int elite = 2;             ///< best tours copied unchanged into the next generation
  bool local_search = true;  ///< 2-opt and or-opt with orientation flips after the GA
  /// Kicks of the iterated local search after the descent (fewer on large instances: at
  /// most about 4e6 / n^3).
  int kicks = 300;
  std::uint64_t seed = 1;
};

Status validate(const SequenceOptions& options);

/// Seed 003 section 2.4.3/2.5: genetic algorithm (rank selection, partially matched
/// crossover, swap / shift / flip mutation), then local search. Deterministic for a seed.
Result<TwoEndsTour> solve_two_ends_ga(const TwoEndsInstance& instance,
                                      const SequenceOptions& options = {});

/// Improves a tour in place by 2-opt (segment reversal, which also flips the orientation
/// of every region inside) and or-opt (moving a chain of 1 to 3 regions, reversed or not)
/// until no move helps; orientations are re-optimised after every accepted move.
void improve_two_ends_tour(const TwoEndsInstance& instance, TwoEndsTour& tour);

/// Greedy nearest-neighbour tour: from the start, always the cheapest unvisited entry.
TwoEndsTour nearest_neighbour_tour(const TwoEndsInstance& instance);

/// Regions up to which solve_two_ends uses the exact solver (about 1 ms there).
inline constexpr int kExactUpTo = 10;

/// What a caller wants: the exact optimum up to kExactUpTo regions, the GA plus local
/// search above.
Result<TwoEndsTour> solve_two_ends(const TwoEndsInstance& instance,
                                   const SequenceOptions& options = {});

/// Largest instance solve_two_ends_exact accepts.
inline constexpr int kMaxExactRegions = 16;

/// The optimum by dynamic programming over subsets (Held-Karp with the orientation as part
/// of the state): O(2^n n^2) time. kBadParameter above kMaxExactRegions.
Result<TwoEndsTour> solve_two_ends_exact(const TwoEndsInstance& instance);

}  // namespace swarf
