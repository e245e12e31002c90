#include "swarm/planner/coverage/darp.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <cstdio>
#include <set>

#include "darp_engine.hpp"
#include "division_repair.hpp"
#include "swarm/planner/coverage/region_graph.hpp"

namespace swarm::planner {
namespace {

using detail::DarpEngine;
using detail::DarpSpace;
using detail::DivisionScore;

DarpResult bad_input(std::string message) {
  DarpResult r;
  r.status = DarpStatus::BadInput;
  r.message = std::move(message);
  return r;
}

// What is wrong with the request, or "" when nothing is.
std::string check_request(const OccupancyGrid& map, const DarpRequest& req, const OccupancyGrid& region) {
  if (req.robots.empty()) return "no robots to divide the region among";
  if (!req.region.empty() && req.region.size() != map.size()) {
    return "region mask has " + std::to_string(req.region.size()) + " cells, the map " +
           std::to_string(map.size());
  }
  if (!req.weights.empty() && req.weights.size() != req.robots.size()) {
    return std::to_string(req.weights.size()) + " weights for " + std::to_string(req.robots.size()) +
           " robots";
  }
  for (std::size_t i = 0; i < req.weights.size(); ++i) {
    if (!(req.weights[i] > 0) || !std::isfinite(req.weights[i])) {
      return "weight of robot " + std::to_string(i) + " must be a positive number (got " +
             std::to_string(req.weights[i]) + ")";
    }
  }
  std::set<Cell> seen;
  for (std::size_t i = 0; i < req.robots.size(); ++i) {
    const Cell c = req.robots[i];
    if (!map.in_bounds(c)) {
      return "robot " + std::to_string(i) + " at " + to_string(c) + " is outside the " +
             std::to_string(map.width()) + " x " + std::to_string(map.height()) + " map";
    }
    if (!map.is_free(c)) return "robot " + std::to_string(i) + " at " + to_string(c) + " is not on a free cell";
    if (!region.is_free(c)) {
      return "robot " + std::to_string(i) + " at " + to_string(c) + " is not on a cell of the region";
    }
    if (!seen.insert(c).second) {
      return "robots " + std::to_string(std::distance(req.robots.begin(),
                                                      std::find(req.robots.begin(), req.robots.end(), c))) +
             " and " + std::to_string(i) + " are both at " + to_string(c);
    }
  }
  return "";
}

// The reachable part of the region, its pieces and the robots' shares.
// (Robots stand on distinct cells of their pieces, so no piece has more robots than cells.)
DarpSpace make_space(const OccupancyGrid& region, const DarpRequest& req, std::vector<int>& robots,
                     int& unreachable) {
  const RegionGraph all = RegionGraph::build(region);
  int count = 0;
  const std::vector<int> label = components(all, count);
  std::vector<int> robots_in(count, 0);
  for (const Cell& c : req.robots) ++robots_in[label[all.index_of(c)]];
  OccupancyGrid reachable = region;
  unreachable = 0;
  for (int i = 0; i < all.size(); ++i) {
    if (robots_in[label[i]] > 0) continue;
    reachable.set(all.cells[i], CellState::Occupied);
    ++unreachable;
  }
  DarpSpace s;
  s.graph = RegionGraph::build(reachable);
  // Pieces renumbered 0..pieces-1 in the order of their first cell.
  std::vector<int> renumber(count, -1);
  std::vector<int> piece_size;
  s.piece.resize(s.graph.size());
  for (int i = 0; i < s.graph.size(); ++i) {
    const int l = label[all.index_of(s.graph.cells[i])];
    if (renumber[l] < 0) {
      renumber[l] = s.pieces++;
      piece_size.push_back(0);
    }
    s.piece[i] = renumber[l];
    ++piece_size[renumber[l]];
  }
  const int n = static_cast<int>(req.robots.size());
  s.weights = req.weights.empty() ? std::vector<double>(n, 1.0) : req.weights;
  std::vector<double> piece_weight(s.pieces, 0.0);
  for (int r = 0; r < n; ++r) {
    robots.push_back(s.graph.index_of(req.robots[r]));
    s.robot_piece.push_back(s.piece[robots.back()]);
    piece_weight[s.robot_piece[r]] += s.weights[r];
  }
  for (int r = 0; r < n; ++r) {
    s.shares.push_back(piece_size[s.robot_piece[r]] * s.weights[r] / piece_weight[s.robot_piece[r]]);
  }
  return s;
}

double alpha_of(const DarpEngine& e, const DarpSpace& s) { return imbalance(e.counts(), s.weights); }

std::string format_cells(double cells) {
  char text[32];
  std::snprintf(text, sizeof text, "%g cell%s", cells, cells == 1 ? "" : "s");
  return text;
}

}  // namespace

const char* to_string(DarpStatus status) {
  switch (status) {
    case DarpStatus::Converged: return "converged";
    case DarpStatus::Failed: return "failed";
    case DarpStatus::Stopped: return "stopped";
    case DarpStatus::BadInput: return "bad-input";
    case DarpStatus::Impossible: return "impossible";
  }
  return "?";
}

const char* to_string(DarpDistance distance) {
  return distance == DarpDistance::Geodesic ? "geodesic" : "euclidean";
}

const char* to_string(DarpInit init) {
  switch (init) {
    case DarpInit::Given: return "given";
    case DarpInit::Random: return "random";
    case DarpInit::KMeans: return "kmeans";
    case DarpInit::BfsKMeans: return "bfs-kmeans";
  }
  return "?";
}

const char* to_string(DivisionMethod method) { return method == DivisionMethod::Auto ? "auto" : "darp"; }

std::optional<DivisionMethod> parse_division_method(const std::string& text) {
  for (DivisionMethod m : {DivisionMethod::Darp, DivisionMethod::Auto}) {
    if (text == to_string(m)) return m;
  }
  return std::nullopt;
}

std::optional<DarpDistance> parse_darp_distance(const std::string& text) {
  for (DarpDistance d : {DarpDistance::Euclidean, DarpDistance::Geodesic}) {
    if (text == to_string(d)) return d;
  }
  return std::nullopt;
}

std::optional<DarpInit> parse_darp_init(const std::string& text) {
  for (DarpInit i : {DarpInit::Given, DarpInit::Random, DarpInit::KMeans, DarpInit::BfsKMeans}) {
    if (text == to_string(i)) return i;
  }
  return std::nullopt;
}

double jain_index(const std::vector<double>& loads) {
  double sum = 0, sum_sq = 0;
  for (double x : loads) sum += x, sum_sq += x * x;
  if (loads.empty() || sum_sq <= 0) return 1.0;
  return sum * sum / (static_cast<double>(loads.size()) * sum_sq);
}

double imbalance(const std::vector<int>& cells, const std::vector<double>& weights) {
  std::vector<double> loads;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    loads.push_back(cells[i] / (weights.empty() ? 1.0 : weights[i]));
  }
  return 1.0 - jain_index(loads);
}

DarpResult divide_areas(const OccupancyGrid& map, const DarpRequest& request, const DarpConfig& config,
                        const std::function<bool()>& should_stop) {
  const auto t0 = std::chrono::steady_clock::now();
  if (!request.region.empty() && request.region.size() != map.size()) {
    return bad_input("region mask has " + std::to_string(request.region.size()) + " cells, the map " +
                     std::to_string(map.size()));
  }
  const OccupancyGrid region = region_grid(map, request.region);
  if (std::string why = check_request(map, request, region); !why.empty()) return bad_input(why);

  std::vector<int> robots;
  int unreachable = 0;
  const DarpSpace space = make_space(region, request, robots, unreachable);

  // alpha0: the first division from the robots' own cells. For Given it is the run itself.
  auto engine = std::make_unique<DarpEngine>(space, robots, config, 0);
  DarpResult out;
  out.alpha0 = alpha_of(*engine, space);
  int abandoned = 0;  // probes whose starts were not kept (BfsKMeans)
  std::uint64_t stream = 1;
  switch (config.init) {
    case DarpInit::Given:
      break;
    case DarpInit::Random: {
      Rng rng(mix_seed(config.seed, 0x5eed));
      engine = std::make_unique<DarpEngine>(space, detail::random_starts(space, robots, config.distance, rng),
                                            config, stream);
      out.alpha_reinit.push_back(alpha_of(*engine, space));
      break;
    }
    case DarpInit::KMeans:
      engine = std::make_unique<DarpEngine>(space, detail::kmeans_starts(space, robots, config), config, stream);
      out.alpha_reinit.push_back(alpha_of(*engine, space));
      break;
    case DarpInit::BfsKMeans:
      if (config.reinit_always || out.alpha0 > config.alpha_threshold) {
        for (int k = 0; k < config.max_reinitialisations; ++k) {
          if (should_stop && should_stop()) break;
          std::vector<int> next = detail::bfs_kmeans_starts(space, engine->starts(), config.bfs_kmeans_steps);
          engine = std::make_unique<DarpEngine>(space, std::move(next), config, stream++);
          ++abandoned;
          out.alpha_reinit.push_back(alpha_of(*engine, space));
          if (out.alpha_reinit.back() <= config.alpha_threshold) break;
        }
      }
      break;
  }

  std::vector<int> best;
  DivisionScore best_score;
  const bool repair = config.method == DivisionMethod::Auto;
  const int budget = repair ? std::min(config.max_iterations, config.auto_darp_iterations) : config.max_iterations;
  out.status = engine->run(std::max(0, budget - abandoned), should_stop, best, best_score);
  out.iterations = engine->updates() + abandoned;
  std::vector<int> starts = engine->starts();
  if (repair && out.status != DarpStatus::Converged) {
    auto deviation = [&](const std::vector<int>& owner) {
      std::vector<int> held(space.robots(), 0);
      for (int r : owner) ++held[r];
      double most = 0;
      for (int r = 0; r < space.robots(); ++r) most = std::max(most, std::abs(held[r] - space.shares[r]));
      return most;
    };
    detail::RepairOutcome done = detail::repair_division(space, best, starts, robots, config.tolerance_cells);
    // Should the repair of DARP's division get stuck, it starts again from fresh first divisions
    // (K-Means starts, then random ones) and keeps the best.
    Rng rng(mix_seed(config.seed, 0x4e5));
    for (int attempt = 0; !done.goal && attempt < config.repair_restarts; ++attempt) {
      const DarpEngine fresh(space,
                             attempt == 0 ? detail::kmeans_starts(space, robots, config)
                                          : detail::random_starts(space, robots, config.distance, rng),
                             config, stream + 1 + attempt);
      std::vector<int> owner(fresh.owner().begin(), fresh.owner().end());
      std::vector<int> from = fresh.starts();
      const detail::RepairOutcome again = detail::repair_division(space, owner, from, robots, config.tolerance_cells);
      if (again.goal || deviation(owner) < deviation(best)) best = std::move(owner), starts = std::move(from), done = again;
    }
    out.finished_by = "repair";
    out.repair_moves = done.moves;
    out.starts_moved = starts != engine->starts();
    best_score = {};
    best_score.max_deviation = deviation(best);
    if (done.goal) {
      out.status = DarpStatus::Converged;
    } else if (std::string why = detail::no_balanced_division(space, config.tolerance_cells); !why.empty()) {
      out.status = DarpStatus::Impossible;
      out.message = "no division within " + format_cells(config.tolerance_cells) + " of every share exists: " + why;
    } else {
      out.status = DarpStatus::Failed;
      out.message = "no division within " + format_cells(config.tolerance_cells) +
                    " of every share found (and no proof that none exists)";
    }
  }

  const RegionGraph& g = space.graph;
  const int n = space.robots();
  out.assignment.assign(map.size(), kOutsideRegion);
  for (int i = 0; i < static_cast<int>(map.size()); ++i) {
    if (region.at(i) == CellState::Free) out.assignment[i] = kUnreachable;
  }
  out.cells.assign(n, 0);
  for (int i = 0; i < g.size(); ++i) {
    out.assignment[map.index(g.cells[i])] = best[i];
    ++out.cells[best[i]];
  }
  for (int s : starts) out.starts.push_back(g.cells[s]);
  out.shares = space.shares;
  out.final_imbalance = imbalance(out.cells, space.weights);
  out.max_deviation = best_score.max_deviation;
  out.split_regions = best_score.split;
  out.unreachable_cells = unreachable;
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace swarm::planner
