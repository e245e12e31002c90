#include "swarm/planner/tours/tour.hpp"

#include <algorithm>
#include <cassert>
#include <cstdint>
#include <map>
#include <utility>

#include "swarm/planner/explore/frontier.hpp"
#include "swarm/planner/grid/motion.hpp"

namespace swarm::planner {

const char* variant_name(TourVariant v) {
  switch (v) {
    case TourVariant::kNna: return "nna";
    case TourVariant::kDistance: return "distance";
    case TourVariant::kDistanceAngle: return "distance-angle";
  }
  return "?";
}

std::optional<TourVariant> parse_variant(const std::string& name) {
  for (TourVariant v : {TourVariant::kNna, TourVariant::kDistance, TourVariant::kDistanceAngle}) {
    if (name == variant_name(v)) return v;
  }
  return std::nullopt;
}

const char* search_name(TourOptions::Search s) {
  switch (s) {
    case TourOptions::Search::kGa: return "ga";
    case TourOptions::Search::kGaPolished: return "ga-polished";
    case TourOptions::Search::kExact: return "exact";
  }
  return "?";
}

std::optional<TourOptions::Search> parse_search(const std::string& name) {
  for (auto s : {TourOptions::Search::kGa, TourOptions::Search::kGaPolished, TourOptions::Search::kExact}) {
    if (name == search_name(s)) return s;
  }
  return std::nullopt;
}

std::vector<TourIssue> check_tour_problem(const OccupancyGrid& map, const TourProblem& problem) {
  std::vector<TourIssue> issues;
  const bool start_ok = map.in_bounds(problem.start) && map.is_free(problem.start);
  if (!map.in_bounds(problem.start)) issues.push_back({TourIssue::kStartOutside, -1});
  else if (!map.is_free(problem.start)) issues.push_back({TourIssue::kStartBlocked, -1});
  const std::vector<std::uint8_t> reach =
      start_ok ? reachable_mask(map, {problem.start}, MotionModel::eight()) : std::vector<std::uint8_t>{};
  // Outside, blocked, or (with a usable start) unreachable: the first that applies.
  const auto place = [&](Cell c, TourIssue::Kind outside, TourIssue::Kind blocked,
                         TourIssue::Kind unreachable) -> std::optional<TourIssue::Kind> {
    if (!map.in_bounds(c)) return outside;
    if (!map.is_free(c)) return blocked;
    if (start_ok && !reach[static_cast<std::size_t>(map.index(c))]) return unreachable;
    return std::nullopt;
  };
  for (std::size_t d = 0; d < problem.destinations.size(); ++d) {
    if (auto k = place(problem.destinations[d], TourIssue::kDestinationOutside,
                       TourIssue::kDestinationBlocked, TourIssue::kDestinationUnreachable)) {
      issues.push_back({*k, static_cast<int>(d)});
    }
  }
  for (std::size_t o = 0; o < problem.objects.size(); ++o) {
    const TourObject& obj = problem.objects[o];
    if (auto k = place(obj.cell, TourIssue::kObjectOutside, TourIssue::kObjectBlocked,
                       TourIssue::kObjectUnreachable)) {
      issues.push_back({*k, static_cast<int>(o)});
    } else if (obj.type < 0 || obj.type >= static_cast<int>(problem.destinations.size())) {
      issues.push_back({TourIssue::kObjectNoDestination, static_cast<int>(o)});
    }
  }
  return issues;
}

std::string describe(const TourIssue& issue) {
  const std::string obj = "object " + std::to_string(issue.index);
  const std::string dest = "destination " + std::to_string(issue.index);
  switch (issue.kind) {
    case TourIssue::kStartOutside: return "the start is outside the map";
    case TourIssue::kStartBlocked: return "the start is on a blocked cell";
    case TourIssue::kObjectOutside: return obj + " is outside the map";
    case TourIssue::kObjectBlocked: return obj + " is on a blocked cell";
    case TourIssue::kObjectNoDestination: return obj + "'s type has no destination";
    case TourIssue::kObjectUnreachable: return obj + " cannot be reached from the start";
    case TourIssue::kDestinationOutside: return dest + " is outside the map";
    case TourIssue::kDestinationBlocked: return dest + " is on a blocked cell";
    case TourIssue::kDestinationUnreachable: return dest + " cannot be reached from the start";
  }
  return "?";
}

std::vector<Cell> TourPlan::cells() const {
  std::vector<Cell> out;
  for (const TourLeg& leg : legs) {
    out.insert(out.end(), leg.cells.begin() + (out.empty() ? 0 : 1), leg.cells.end());
  }
  return out;
}

namespace {

std::int64_t squared_distance(Cell a, Cell b) {
  const std::int64_t dx = a.x - b.x;
  const std::int64_t dy = a.y - b.y;
  return dx * dx + dy * dy;
}

// The remaining object nearest `from` (Euclidean; `remaining` is ascending, so ties go to the
// lower number).
int nearest_object(const TourProblem& p, const std::vector<int>& remaining, Cell from) {
  int best = remaining.front();
  for (int o : remaining) {
    if (squared_distance(from, p.objects[static_cast<std::size_t>(o)].cell) <
        squared_distance(from, p.objects[static_cast<std::size_t>(best)].cell)) {
      best = o;
    }
  }
  return best;
}

// Objects the plan can hold: on a free, reachable cell, with a usable destination.
std::vector<int> usable_objects(const TourProblem& p, const std::vector<TourIssue>& issues) {
  std::vector<char> bad_object(p.objects.size(), 0);
  std::vector<char> bad_destination(p.destinations.size(), 0);
  bool bad_start = false;
  for (const TourIssue& i : issues) {
    switch (i.kind) {
      case TourIssue::kStartOutside:
      case TourIssue::kStartBlocked: bad_start = true; break;
      case TourIssue::kDestinationOutside:
      case TourIssue::kDestinationBlocked:
      case TourIssue::kDestinationUnreachable: bad_destination[static_cast<std::size_t>(i.index)] = 1; break;
      default: bad_object[static_cast<std::size_t>(i.index)] = 1; break;
    }
  }
  std::vector<int> out;
  if (bad_start) return out;
  for (std::size_t o = 0; o < p.objects.size(); ++o) {
    if (!bad_object[o] && !bad_destination[static_cast<std::size_t>(p.objects[o].type)]) {
      out.push_back(static_cast<int>(o));
    }
  }
  return out;
}

}  // namespace

namespace {

// The robot stands on its start cell, so it is passable whatever the map says.
OccupancyGrid with_start_free(const OccupancyGrid& map, Cell start) {
  OccupancyGrid m = map;
  if (m.in_bounds(start)) m.set(start, CellState::Free);
  return m;
}

}  // namespace

TourPlan plan_tour(const OccupancyGrid& given_map, const TourProblem& problem, const TourOptions& options,
                   const std::function<bool()>& stop) {
  const OccupancyGrid map = with_start_free(given_map, problem.start);
  TourPlan plan;
  std::vector<int> remaining = usable_objects(problem, check_tour_problem(map, problem));
  for (std::size_t o = 0, r = 0; o < problem.objects.size(); ++o) {
    if (r < remaining.size() && remaining[r] == static_cast<int>(o)) ++r;
    else plan.skipped.push_back(static_cast<int>(o));
  }
  if (!plan.skipped.empty()) plan.status = TourStatus::kPartial;

  const OrderObjective objective = options.variant == TourVariant::kDistanceAngle
                                       ? OrderObjective::kDistanceThenRotation
                                       : OrderObjective::kDistance;
  Cell at = problem.start;
  int heading = problem.start_heading;
  bool stopped = false;
  for (int run_index = 0; !remaining.empty(); ++run_index) {
    const int first = nearest_object(problem, remaining, at);
    const int type = problem.objects[static_cast<std::size_t>(first)].type;
    const Cell destination = problem.destinations[static_cast<std::size_t>(type)];
    std::vector<int> mine;
    std::vector<Cell> stops{at};
    for (int o : remaining) {
      if (problem.objects[static_cast<std::size_t>(o)].type != type) continue;
      mine.push_back(o);
      stops.push_back(problem.objects[static_cast<std::size_t>(o)].cell);
    }
    stops.push_back(destination);

    // The other types' waiting objects are obstacles, except on a cell this run must use.
    OccupancyGrid blocked = map;
    bool any_blocked = false;
    if (options.other_types_block) {
      for (int o : remaining) {
        const Cell c = problem.objects[static_cast<std::size_t>(o)].cell;
        if (problem.objects[static_cast<std::size_t>(o)].type == type ||
            std::find(stops.begin(), stops.end(), c) != stops.end()) {
          continue;
        }
        blocked.set(c, CellState::Occupied);
        any_blocked = true;
      }
    }
    const LegTable legs(any_blocked ? blocked : map, any_blocked ? &map : nullptr, stops);
    assert(legs.complete());

    std::vector<int> prefix;
    if (options.variant == TourVariant::kNna) {
      prefix.push_back(1 + static_cast<int>(std::find(mine.begin(), mine.end(), first) - mine.begin()));
    }
    OrderSearch search;
    if (stopped) {
      search.order = greedy_order(legs, prefix);
      search.cost = order_cost(legs, search.order, heading);
    } else if (options.search == TourOptions::Search::kExact &&
               legs.objects() - static_cast<int>(prefix.size()) <= kExactMaxFreeObjects) {
      search = reference_order(legs, heading, prefix, {}, objective);
    } else {
      Rng rng(mix_seed(options.seed, run_index));
      search = order_ga(legs, heading, prefix, objective, options.ga, rng, stop);
      stopped = search.stopped;
      if (options.search != TourOptions::Search::kGa) {
        OrderSearch polished = polish_order(legs, heading, prefix.size(), search.order, objective);
        search.order = std::move(polished.order);
        search.cost = polished.cost;
      }
    }

    TourRun run;
    run.type = type;
    run.generations = search.generations;
    if (options.compute_reference) {
      run.reference = reference_order(legs, heading, prefix, search.order);
      for (int& s : run.reference->order) s = mine[static_cast<std::size_t>(s - 1)];  // stops -> objects
    }
    int from = 0;
    std::vector<int> stops_in_order = search.order;
    stops_in_order.push_back(legs.objects() + 1);
    for (int s : stops_in_order) {
      const Leg& l = legs.leg(from, s);
      TourLeg leg;
      leg.cells = l.cells;
      leg.length = l.length;
      leg.through_objects = l.through_objects;
      if (l.first_heading) {
        leg.rotation = turn_eighths(heading, *l.first_heading) + l.inner_turns;
        heading = *l.last_heading;
      }
      if (s <= legs.objects()) {
        const int object = mine[static_cast<std::size_t>(s - 1)];
        leg.stop = {TourStop::kPickUp, object, type, stops[static_cast<std::size_t>(s)]};
        run.order.push_back(object);
      } else {
        leg.stop = {TourStop::kDrop, -1, type, destination};
      }
      run.length += leg.length;
      run.rotation += leg.rotation;
      plan.legs.push_back(std::move(leg));
      from = s;
    }
    assert(run.length == search.cost.length && run.rotation == search.cost.rotation);
    plan.length += run.length;
    plan.rotation += run.rotation;
    plan.runs.push_back(std::move(run));

    std::erase_if(remaining, [&](int o) { return problem.objects[static_cast<std::size_t>(o)].type == type; });
    at = destination;
    heading = problem.heading_after_drop;
  }
  if (stopped && plan.status == TourStatus::kComplete) plan.status = TourStatus::kStopped;
  return plan;
}

std::string check_tour(const OccupancyGrid& given_map, const TourProblem& problem, const TourPlan& plan) {
  const OccupancyGrid map = with_start_free(given_map, problem.start);
  const auto n = problem.objects.size();
  std::vector<char> skipped(n, 0), picked(n, 0), done_type(problem.destinations.size(), 0);
  for (int s : plan.skipped) {
    if (s < 0 || static_cast<std::size_t>(s) >= n) return "skipped object " + std::to_string(s) + " does not exist";
    skipped[static_cast<std::size_t>(s)] = 1;
  }
  std::multimap<std::pair<int, int>, int> objects_at;  // cell -> objects
  for (std::size_t o = 0; o < n; ++o) objects_at.insert({{problem.objects[o].cell.x, problem.objects[o].cell.y}, static_cast<int>(o)});
  const auto waiting = [&](std::size_t o) { return !skipped[o] && !picked[o]; };

  const MotionModel motion = MotionModel::eight();
  Cell at = problem.start;
  int heading = problem.start_heading;
  int current = -1;  // the type being collected
  Cell run_origin = at;  // where the current type's run began (the planner keeps it open)
  GridLength total;
  int rotation = 0;
  for (std::size_t k = 0; k < plan.legs.size(); ++k) {
    const TourLeg& leg = plan.legs[k];
    const std::string where = "leg " + std::to_string(k) + ": ";
    if (leg.cells.empty() || leg.cells.front() != at) return where + "does not start where the robot is";
    if (leg.cells.back() != leg.stop.cell) return where + "does not end at its stop";
    const int t = leg.stop.type;
    if (t < 0 || static_cast<std::size_t>(t) >= problem.destinations.size()) return where + "unknown type";
    if (current == -1) {
      std::vector<int> left;
      for (std::size_t o = 0; o < n; ++o) {
        if (waiting(o)) left.push_back(static_cast<int>(o));
      }
      if (left.empty()) return where + "no object is left to collect";
      if (problem.objects[static_cast<std::size_t>(nearest_object(problem, left, at))].type != t) {
        return where + "type " + std::to_string(t) + " is not the type of the nearest object";
      }
      if (done_type[static_cast<std::size_t>(t)]) return where + "type " + std::to_string(t) + " collected twice";
      current = t;
      run_origin = at;
    } else if (t != current) {
      return where + "switches type before dropping type " + std::to_string(current);
    }
    for (std::size_t i = 1; i < leg.cells.size(); ++i) {
      const Cell a = leg.cells[i - 1];
      const Cell b = leg.cells[i];
      const MoveCheck c = motion.check(map, a, b);
      if (c != MoveCheck::Ok) return where + "step " + std::to_string(i) + " is " + to_string(c);
      if (leg.through_objects) continue;
      bool other = false, own = b == problem.destinations[static_cast<std::size_t>(t)] || b == run_origin;
      auto [lo, hi] = objects_at.equal_range({b.x, b.y});
      for (auto it = lo; it != hi; ++it) {
        const auto o = static_cast<std::size_t>(it->second);
        if (!waiting(o)) continue;
        (problem.objects[o].type == t ? own : other) = true;
      }
      if (other && !own) return where + "step " + std::to_string(i) + " enters another type's object";
    }
    if (grid_length(leg.cells) != leg.length) return where + "length does not match its cells";
    std::optional<int> after;
    if (rotation_eighths(leg.cells, heading, &after) != leg.rotation) return where + "rotation does not match its cells";
    heading = *after;
    if (leg.stop.kind == TourStop::kPickUp) {
      const int o = leg.stop.object;
      if (o < 0 || static_cast<std::size_t>(o) >= n) return where + "picks up an unknown object";
      const auto ou = static_cast<std::size_t>(o);
      if (!waiting(ou)) return where + "object " + std::to_string(o) + " is skipped or already picked up";
      if (problem.objects[ou].type != t || problem.objects[ou].cell != leg.stop.cell) {
        return where + "object " + std::to_string(o) + " is not of this type or not here";
      }
      picked[ou] = 1;
    } else {
      if (leg.stop.cell != problem.destinations[static_cast<std::size_t>(t)]) return where + "drops away from the destination";
      for (std::size_t o = 0; o < n; ++o) {
        if (waiting(o) && problem.objects[o].type == t) return where + "drops before object " + std::to_string(o) + " is collected";
      }
      done_type[static_cast<std::size_t>(t)] = 1;
      current = -1;
      heading = problem.heading_after_drop;
    }
    total += leg.length;
    rotation += leg.rotation;
    at = leg.cells.back();
  }
  if (current != -1) return "the tour ends before dropping type " + std::to_string(current);
  for (std::size_t o = 0; o < n; ++o) {
    if (waiting(o)) return "object " + std::to_string(o) + " is never picked up";
  }
  if (total != plan.length || rotation != plan.rotation) return "the totals do not add up";
  GridLength runs;
  for (const TourRun& r : plan.runs) runs += r.length;
  if (runs != plan.length) return "the runs do not add up to the total";
  return "";
}

Cell put_down_cell(const OccupancyGrid& map, Cell at, const std::vector<Cell>& robots) {
  std::vector<std::uint8_t> seen(map.size(), 0);
  std::vector<Cell> frontier{at};
  seen[map.index(at)] = 1;
  for (std::size_t i = 0; i < frontier.size() && i < 4096; ++i) {
    const Cell c = frontier[i];
    if (c != at && std::find(robots.begin(), robots.end(), c) == robots.end()) return c;
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const Cell n{c.x + dx, c.y + dy};
        if (!map.in_bounds(n) || !map.is_free(n) || seen[map.index(n)]) continue;
        seen[map.index(n)] = 1;
        frontier.push_back(n);
      }
    }
  }
  return at;
}

}  // namespace swarm::planner
