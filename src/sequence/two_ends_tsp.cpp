// Seed 003 section 2.4.3 / 2.5: GA plus local search for the two-ends-per-region TSP, and
// the exact optimum by Held-Karp for small instances (the yardstick of the tests).
#include "swarf/sequence/two_ends_tsp.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <string>

namespace swarf {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// A move must gain more than this to be accepted, so that rounding cannot make the local
// search cycle.
constexpr double kGainEps = 1e-9;
// Distinct tours of the final population the local search starts from.
constexpr std::size_t kLocalSearchStarts = 8;
// Instances up to this size get or-opt chains of any length.
constexpr std::size_t kLongChainsUpTo = 16;
// Work budget of the kicks of the iterated local search, in units of n^3 (one descent).
constexpr double kKickWork = 4e6;

// Own mappings from the 64-bit engine (mt19937_64's sequence is fixed by the standard, the
// std:: distributions are not), so tours are identical across standard libraries.
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : engine_(seed) {}
  std::size_t below(std::size_t n) { return static_cast<std::size_t>(engine_() % n); }
  double unit() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

 private:
  std::mt19937_64 engine_;
};

double start_of(const TwoEndsInstance& in, int end) {
  return in.start_cost.empty() ? 0.0 : in.start_cost[static_cast<std::size_t>(end)];
}
double end_of(const TwoEndsInstance& in, int end) {
  return in.end_cost.empty() ? 0.0 : in.end_cost[static_cast<std::size_t>(end)];
}

// Entry and exit end of region r with orientation o.
int entry(int r, int o) {
  return 2 * r + o;
}
int exit_end(int r, int o) {
  return 2 * r + 1 - o;
}

// Two-state dynamic programme over the positions of `order`: the cheapest orientations for
// this order. Writes them to `flipped` when it is not null. O(n), no allocation beyond
// `back` (reused by the caller).
double best_orientations(const TwoEndsInstance& in, const std::vector<int>& order,
                         std::vector<std::uint8_t>* flipped, std::vector<std::uint8_t>& back) {
  const std::size_t n = order.size();
  if (n == 0) return 0.0;
  back.resize(2 * n);
  double c0 = start_of(in, entry(order[0], 0));
  double c1 = start_of(in, entry(order[0], 1));
  for (std::size_t t = 1; t < n; ++t) {
    const int r = order[t - 1], s = order[t];
    double n0 = kInf, n1 = kInf;
    for (int o = 0; o < 2; ++o) {
      const double base = o == 0 ? c0 : c1;
      const double to0 = base + in.at(exit_end(r, o), entry(s, 0));
      const double to1 = base + in.at(exit_end(r, o), entry(s, 1));
      if (to0 < n0) {
        n0 = to0;
        back[2 * t] = static_cast<std::uint8_t>(o);
      }
      if (to1 < n1) {
        n1 = to1;
        back[2 * t + 1] = static_cast<std::uint8_t>(o);
      }
    }
    c0 = n0;
    c1 = n1;
  }
  const int last = order[n - 1];
  c0 += end_of(in, exit_end(last, 0));
  c1 += end_of(in, exit_end(last, 1));
  int o = c1 < c0 ? 1 : 0;
  const double best = o == 1 ? c1 : c0;
  if (flipped != nullptr) {
    flipped->assign(static_cast<std::size_t>(in.regions), 0);
    for (std::size_t t = n; t-- > 0;) {
      (*flipped)[static_cast<std::size_t>(order[t])] = static_cast<std::uint8_t>(o);
      if (t > 0) o = back[2 * t + static_cast<std::size_t>(o)];
    }
  }
  return best;
}

// Partially matched crossover (Goldberg and Lingle): the child takes parent a's genes in
// [lo, hi] and parent b's elsewhere, conflicts resolved through the a<->b mapping of the
// segment, so no region appears twice.
std::vector<int> pmx(const std::vector<int>& a, const std::vector<int>& b, std::size_t lo,
                     std::size_t hi, std::vector<int>& pos_a) {
  const std::size_t n = a.size();
  std::vector<int> child(n, -1);
  for (std::size_t i = 0; i < n; ++i)
    pos_a[static_cast<std::size_t>(a[i])] = static_cast<int>(i);
  for (std::size_t i = lo; i <= hi; ++i)
    child[i] = a[i];
  for (std::size_t i = 0; i < n; ++i) {
    if (i >= lo && i <= hi) continue;
    int v = b[i];
    for (;;) {
      const auto p = static_cast<std::size_t>(pos_a[static_cast<std::size_t>(v)]);
      if (p < lo || p > hi) break;
      v = b[p];
    }
    child[i] = v;
  }
  return child;
}

// Section 2.5 mutations: swap two genes, shift one gene to another place, flip (reverse) a
// stretch.
void mutate(std::vector<int>& g, Rng& rng) {
  const std::size_t n = g.size();
  if (n < 2) return;
  std::size_t i = rng.below(n), j = rng.below(n);
  if (i == j) j = (i + 1) % n;
  switch (rng.below(3)) {
    case 0:
      std::swap(g[i], g[j]);
      break;
    case 1: {
      const int v = g[i];
      g.erase(g.begin() + static_cast<std::ptrdiff_t>(i));
      g.insert(g.begin() + static_cast<std::ptrdiff_t>(std::min(j, n - 1)), v);
      break;
    }
    default:
      if (i > j) std::swap(i, j);
      std::reverse(g.begin() + static_cast<std::ptrdiff_t>(i),
                   g.begin() + static_cast<std::ptrdiff_t>(j) + 1);
      break;
  }
}

}  // namespace

TwoEndsInstance make_two_ends_instance(
    int regions, const std::function<double(int from_end, int to_end)>& cost) {
  TwoEndsInstance in;
  in.regions = regions;
  const int m = 2 * regions;
  in.cost.assign(static_cast<std::size_t>(m) * static_cast<std::size_t>(m), 0.0);
  for (int p = 0; p < m; ++p) {
    for (int q = 0; q < m; ++q) {
      if (p / 2 != q / 2) in.cost[static_cast<std::size_t>(p * m + q)] = cost(p, q);
    }
  }
  return in;
}

TwoEndsInstance make_two_ends_instance(const std::vector<Vec3>& end_points, double lift_penalty,
                                       const std::function<bool(int, int)>& needs_lift) {
  return make_two_ends_instance(static_cast<int>(end_points.size() / 2), [&](int p, int q) {
    const double d =
        distance(end_points[static_cast<std::size_t>(p)], end_points[static_cast<std::size_t>(q)]);
    return d + ((needs_lift && needs_lift(p, q)) ? lift_penalty : 0.0);
  });
}

double tour_cost(const TwoEndsInstance& in, const std::vector<int>& order,
                 const std::vector<std::uint8_t>& flipped) {
  if (order.empty()) return 0.0;
  auto o = [&](int r) { return static_cast<int>(flipped[static_cast<std::size_t>(r)]); };
  double c = start_of(in, entry(order[0], o(order[0])));
  for (std::size_t t = 1; t < order.size(); ++t) {
    c += in.at(exit_end(order[t - 1], o(order[t - 1])), entry(order[t], o(order[t])));
  }
  return c + end_of(in, exit_end(order.back(), o(order.back())));
}

void orient_optimally(const TwoEndsInstance& in, TwoEndsTour& tour) {
  std::vector<std::uint8_t> back;
  tour.cost = best_orientations(in, tour.order, &tour.flipped, back);
}

Status validate(const SequenceOptions& o) {
  if (o.population != 0 && (o.population < 4 || o.population > 10000)) {
    return bad_parameter("sequence population " + std::to_string(o.population) +
                         " must be 0 (automatic) or in [4, 10000]");
  }
  if (o.max_generations < 0 || o.stall_generations < 1) {
    return bad_parameter("sequence generations must be >= 0 and stall generations >= 1");
  }
  if (!(o.crossover_rate >= 0.0 && o.crossover_rate <= 1.0) ||
      !(o.mutation_rate >= 0.0 && o.mutation_rate <= 1.0)) {
    return bad_parameter("sequence crossover and mutation rates must lie in [0, 1]");
  }
  if (o.elite < 0) return bad_parameter("sequence elite count must be >= 0");
  if (o.kicks < 0) return bad_parameter("sequence kicks must be >= 0");
  return {};
}

TwoEndsTour nearest_neighbour_tour(const TwoEndsInstance& in) {
  TwoEndsTour tour;
  const int n = in.regions;
  std::vector<std::uint8_t> used(static_cast<std::size_t>(n), 0);
  int at_end = -1;
  for (int step = 0; step < n; ++step) {
    double best = kInf;
    int best_end = -1;
    for (int q = 0; q < 2 * n; ++q) {
      if (used[static_cast<std::size_t>(q / 2)]) continue;
      const double c = at_end < 0 ? start_of(in, q) : in.at(at_end, q);
      if (c < best || best_end < 0) {
        best = c;
        best_end = q;
      }
    }
    const int r = best_end / 2;
    used[static_cast<std::size_t>(r)] = 1;
    tour.order.push_back(r);
    at_end = best_end ^ 1;  // leave at the other end
  }
  orient_optimally(in, tour);
  return tour;
}

void improve_two_ends_tour(const TwoEndsInstance& in, TwoEndsTour& tour) {
  const std::size_t n = tour.order.size();
  std::vector<std::uint8_t> back;
  tour.cost = best_orientations(in, tour.order, &tour.flipped, back);
  if (n < 2) return;
  std::vector<int> cand(n);
  bool improved = true;
  while (improved) {
    improved = false;
    // 2-opt: reverse order[i..j]. Orientations are re-optimised by the DP, which covers
    // "flip every region inside" as well as any other choice.
    for (std::size_t i = 0; i + 1 < n && !improved; ++i) {
      for (std::size_t j = i + 1; j < n; ++j) {
        cand = tour.order;
        std::reverse(cand.begin() + static_cast<std::ptrdiff_t>(i),
                     cand.begin() + static_cast<std::ptrdiff_t>(j) + 1);
        const double c = best_orientations(in, cand, nullptr, back);
        if (c < tour.cost - kGainEps) {
          tour.order = cand;
          tour.cost = best_orientations(in, tour.order, &tour.flipped, back);
          improved = true;
          break;
        }
      }
    }
    if (improved) continue;
    // Or-opt: move a chain of 1..3 regions elsewhere, as it is or reversed; on small
    // instances chains of any length (a segment insertion, the 3-opt move that keeps
    // directions), which the asymmetric costs of one-way lift-offs need.
    const std::size_t max_chain = n <= kLongChainsUpTo ? n - 1 : 3;
    for (std::size_t len = 1; len <= max_chain && len < n && !improved; ++len) {
      for (std::size_t i = 0; i + len <= n && !improved; ++i) {
        std::vector<int> rest;
        rest.reserve(n);
        for (std::size_t t = 0; t < n; ++t) {
          if (t < i || t >= i + len) rest.push_back(tour.order[t]);
        }
        for (std::size_t k = 0; k <= rest.size() && !improved; ++k) {
          if (k == i) continue;  // the same place
          for (int rev = 0; rev < 2; ++rev) {
            cand.assign(rest.begin(), rest.begin() + static_cast<std::ptrdiff_t>(k));
            const auto first = tour.order.begin() + static_cast<std::ptrdiff_t>(i);
            const auto last = first + static_cast<std::ptrdiff_t>(len);
            if (rev == 0) {
              cand.insert(cand.end(), first, last);
            } else {
              cand.insert(cand.end(), std::make_reverse_iterator(last),
                          std::make_reverse_iterator(first));
            }
            cand.insert(cand.end(), rest.begin() + static_cast<std::ptrdiff_t>(k), rest.end());
            const double c = best_orientations(in, cand, nullptr, back);
            if (c < tour.cost - kGainEps) {
              tour.order = cand;
              tour.cost = best_orientations(in, tour.order, &tour.flipped, back);
              improved = true;
              break;
            }
          }
        }
      }
    }
  }
}

Result<TwoEndsTour> solve_two_ends_ga(const TwoEndsInstance& in, const SequenceOptions& opt) {
  SWARF_RETURN_IF_ERROR(validate(opt));
  const int n = in.regions;
  if (n < 0 || in.cost.size() != static_cast<std::size_t>(4 * n * n)) {
    return bad_parameter("two-ends TSP: cost matrix size does not match the region count");
  }
  TwoEndsTour best;
  if (n == 0) return best;
  if (n <= 2) {  // every order can be tried
    for (int r = 0; r < n; ++r)
      best.order.push_back(r);
    orient_optimally(in, best);
    if (n == 2) {
      TwoEndsTour other{{1, 0}, {}, 0.0};
      orient_optimally(in, other);
      if (other.cost < best.cost) best = other;
    }
    return best;
  }

  const auto nn = static_cast<std::size_t>(n);
  const std::size_t pop = opt.population > 0
                              ? static_cast<std::size_t>(opt.population)
                              : std::clamp<std::size_t>(4 * nn, 20, 100);  // section 2.5: 20-100
  Rng rng(opt.seed);
  std::vector<std::uint8_t> back;
  struct Individual {
    std::vector<int> genes;
    double cost;
  };
  auto make = [&](std::vector<int> genes) {
    const double c = best_orientations(in, genes, nullptr, back);
    return Individual{std::move(genes), c};
  };

  // Initial population: greedy tours, the discovery order and random
  // permutations (own Fisher-Yates for portability).
  // The "heuristic" of the paper's heuristic-GA: the nearest-neighbour tour, improved by
  // the local search, is one member of the first generation, so the GA can only do better.
  std::vector<Individual> population;
  TwoEndsTour greedy = nearest_neighbour_tour(in);
  population.push_back(make(greedy.order));
  if (opt.local_search) {
    improve_two_ends_tour(in, greedy);
    population.push_back(make(greedy.order));
  }
  std::vector<int> identity(nn);
  std::iota(identity.begin(), identity.end(), 0);
  population.push_back(make(identity));
  while (population.size() < pop) {
    std::vector<int> g = identity;
    for (std::size_t i = nn - 1; i > 0; --i)
      std::swap(g[i], g[rng.below(i + 1)]);
    population.push_back(make(std::move(g)));
  }

  auto by_cost = [](const Individual& a, const Individual& b) { return a.cost < b.cost; };
  std::stable_sort(population.begin(), population.end(), by_cost);
  double best_cost = population.front().cost;
  int stall = 0;
  std::vector<int> pos_a(nn);
  // Rank selection (section 2.5): the individual of rank k (0 = best) is drawn with a
  // probability proportional to pop - k.
  const std::size_t rank_total = pop * (pop + 1) / 2;
  auto select = [&]() -> const Individual& {
    std::size_t ticket = rng.below(rank_total);
    for (std::size_t k = 0; k < pop; ++k) {
      const std::size_t w = pop - k;
      if (ticket < w) return population[k];
      ticket -= w;
    }
    return population.back();
  };

  std::vector<Individual> next;
  for (int gen = 0; gen < opt.max_generations && stall < opt.stall_generations; ++gen) {
    next.clear();
    for (std::size_t e = 0; e < std::min<std::size_t>(static_cast<std::size_t>(opt.elite), pop);
         ++e) {
      next.push_back(population[e]);
    }
    while (next.size() < pop) {
      const Individual& a = select();
      const Individual& b = select();
      std::vector<int> child;
      if (rng.unit() < opt.crossover_rate) {
        std::size_t lo = rng.below(nn), hi = rng.below(nn);
        if (lo > hi) std::swap(lo, hi);
        child = pmx(a.genes, b.genes, lo, hi, pos_a);
      } else {
        child = a.genes;
      }
      if (rng.unit() < opt.mutation_rate) mutate(child, rng);
      // Keep the population diverse: a child identical to its first parent is mutated
      // (premature convergence was the GA's main weakness on 10+ regions).
      if (child == a.genes) mutate(child, rng);
      next.push_back(make(std::move(child)));
    }
    population.swap(next);
    std::stable_sort(population.begin(), population.end(), by_cost);
    if (population.front().cost < best_cost - kGainEps) {
      best_cost = population.front().cost;
      stall = 0;
    } else {
      ++stall;
    }
  }

  // Local search from the best few distinct tours of the last generation (the paper's
  // GA alone stalls a few percent above the optimum; descending from several GA tours is
  // cheap and closes most of that gap).
  best.order = population.front().genes;
  orient_optimally(in, best);
  if (opt.local_search) {
    improve_two_ends_tour(in, best);
    std::size_t tried = 1;
    for (std::size_t k = 1; k < population.size() && tried < kLocalSearchStarts; ++k) {
      if (population[k].genes == population[k - 1].genes) continue;
      TwoEndsTour t{population[k].genes, {}, 0.0};
      improve_two_ends_tour(in, t);
      ++tried;
      if (t.cost < best.cost - kGainEps) best = std::move(t);
    }
    // Iterated local search: kick the best tour (a double bridge, or a random reversal for
    // short tours), descend again, keep it if better. Local optima of 2-opt/or-opt on
    // asymmetric costs (lift-offs one way only) can sit 10% above the optimum; the kicks
    // get out of them. The number of kicks is bounded by an n^3 work budget.
    const double work = static_cast<double>(nn) * static_cast<double>(nn) * static_cast<double>(nn);
    const std::size_t kicks = static_cast<std::size_t>(
        std::min(static_cast<double>(opt.kicks), kKickWork / std::max(1.0, work)));
    for (std::size_t it = 0; it < kicks; ++it) {
      TwoEndsTour t = best;
      if (nn >= 8) {
        // Double bridge: A B C D -> A C B D.
        std::size_t cut[3] = {1 + rng.below(nn - 1), 1 + rng.below(nn - 1), 1 + rng.below(nn - 1)};
        std::sort(cut, cut + 3);
        if (cut[0] == cut[1] || cut[1] == cut[2]) continue;
        std::vector<int> g;
        g.reserve(nn);
        for (std::size_t x = 0; x < cut[0]; ++x)
          g.push_back(t.order[x]);
        for (std::size_t x = cut[1]; x < cut[2]; ++x)
          g.push_back(t.order[x]);
        for (std::size_t x = cut[0]; x < cut[1]; ++x)
          g.push_back(t.order[x]);
        for (std::size_t x = cut[2]; x < nn; ++x)
          g.push_back(t.order[x]);
        t.order = std::move(g);
      } else {
        mutate(t.order, rng);
        mutate(t.order, rng);
      }
      improve_two_ends_tour(in, t);
      if (t.cost < best.cost - kGainEps) best = std::move(t);
    }
  }
  return best;
}

Result<TwoEndsTour> solve_two_ends(const TwoEndsInstance& in, const SequenceOptions& opt) {
  SWARF_RETURN_IF_ERROR(validate(opt));
  if (in.regions <= kExactUpTo) return solve_two_ends_exact(in);
  return solve_two_ends_ga(in, opt);
}

Result<TwoEndsTour> solve_two_ends_exact(const TwoEndsInstance& in) {
  const int n = in.regions;
  if (n > kMaxExactRegions) {
    return bad_parameter("exact two-ends TSP: " + std::to_string(n) + " regions exceed " +
                         std::to_string(kMaxExactRegions));
  }
  TwoEndsTour tour;
  if (n <= 0) return tour;
  // dp[(mask * n + r) * 2 + o]: cheapest way to visit `mask`, ending in region r left with
  // orientation o.
  const std::size_t states = (std::size_t{1} << n) * static_cast<std::size_t>(n) * 2;
  std::vector<double> dp(states, kInf);
  std::vector<std::uint8_t> parent(states, 0xff);
  auto idx = [n](std::size_t mask, int r, int o) {
    return (mask * static_cast<std::size_t>(n) + static_cast<std::size_t>(r)) * 2 +
           static_cast<std::size_t>(o);
  };
  for (int r = 0; r < n; ++r) {
    for (int o = 0; o < 2; ++o)
      dp[idx(std::size_t{1} << r, r, o)] = start_of(in, entry(r, o));
  }
  const std::size_t full = (std::size_t{1} << n) - 1;
  for (std::size_t mask = 1; mask <= full; ++mask) {
    for (int r = 0; r < n; ++r) {
      if (!(mask >> r & 1)) continue;
      for (int o = 0; o < 2; ++o) {
        const double c = dp[idx(mask, r, o)];
        if (c == kInf) continue;
        for (int s = 0; s < n; ++s) {
          if (mask >> s & 1) continue;
          const std::size_t m2 = mask | (std::size_t{1} << s);
          for (int o2 = 0; o2 < 2; ++o2) {
            const double c2 = c + in.at(exit_end(r, o), entry(s, o2));
            double& slot = dp[idx(m2, s, o2)];
            if (c2 < slot) {
              slot = c2;
              parent[idx(m2, s, o2)] = static_cast<std::uint8_t>(r * 2 + o);
            }
          }
        }
      }
    }
  }
  double best = kInf;
  int br = 0, bo = 0;
  for (int r = 0; r < n; ++r) {
    for (int o = 0; o < 2; ++o) {
      const double c = dp[idx(full, r, o)] + end_of(in, exit_end(r, o));
      if (c < best) {
        best = c;
        br = r;
        bo = o;
      }
    }
  }
  tour.flipped.assign(static_cast<std::size_t>(n), 0);
  std::size_t mask = full;
  int r = br, o = bo;
  for (;;) {
    tour.order.push_back(r);
    tour.flipped[static_cast<std::size_t>(r)] = static_cast<std::uint8_t>(o);
    const std::uint8_t p = parent[idx(mask, r, o)];
    mask &= ~(std::size_t{1} << r);
    if (p == 0xff) break;
    r = p / 2;
    o = p % 2;
  }
  std::reverse(tour.order.begin(), tour.order.end());
  tour.cost = best;
  return tour;
}

}  // namespace swarf
