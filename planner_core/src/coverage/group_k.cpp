#include "swarm/planner/coverage/group_k.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <numeric>
#include <utility>

#include "swarm/planner/grid/rng.hpp"

namespace swarm::planner {

std::vector<Obstacle> find_obstacles(const OccupancyGrid& map) {
  std::vector<Obstacle> out;
  std::vector<std::uint8_t> seen(map.size(), 0);
  std::vector<int> stack;
  for (int i = 0; i < static_cast<int>(map.size()); ++i) {
    if (map.at(i) == CellState::Free || seen[static_cast<std::size_t>(i)]) continue;
    Obstacle o;
    bool touches_border = false;
    seen[static_cast<std::size_t>(i)] = 1;
    stack.assign(1, i);
    o.lo = o.hi = map.cell_of(i);
    while (!stack.empty()) {
      const Cell c = map.cell_of(stack.back());
      stack.pop_back();
      o.cells.push_back(c);
      o.lo = {std::min(o.lo.x, c.x), std::min(o.lo.y, c.y)};
      o.hi = {std::max(o.hi.x, c.x), std::max(o.hi.y, c.y)};
      touches_border |= c.x == 0 || c.y == 0 || c.x == map.width() - 1 || c.y == map.height() - 1;
      for (int k = 0; k < 8; ++k) {
        const Cell n{c.x + kNeighbourDx[k], c.y + kNeighbourDy[k]};
        if (!map.in_bounds(n) || map.at(n) == CellState::Free) continue;
        const auto ni = static_cast<std::size_t>(map.index(n));
        if (seen[ni]) continue;
        seen[ni] = 1;
        stack.push_back(static_cast<int>(ni));
      }
    }
    if (touches_border) continue;
    std::sort(o.cells.begin(), o.cells.end());
    out.push_back(std::move(o));
  }
  return out;
}

ComplexityParts box_complexity(const OccupancyGrid& map, Cell lo, Cell hi) {
  assert(lo.x <= hi.x && lo.y <= hi.y);
  const auto blocked = [&](int x, int y) {
    return x >= lo.x && x <= hi.x && y >= lo.y && y <= hi.y && !map.is_free({x, y});
  };
  ComplexityParts p;
  const int w = hi.x - lo.x + 1;
  const int h = hi.y - lo.y + 1;
  int black = 0;
  for (int y = lo.y; y <= hi.y; ++y) {
    for (int x = lo.x; x <= hi.x; ++x) black += blocked(x, y);
  }
  // Lattice point (x, y) is the corner shared by cells (x - 1, y - 1), (x, y - 1), (x - 1, y), (x, y).
  for (int y = lo.y; y <= hi.y + 1; ++y) {
    for (int x = lo.x; x <= hi.x + 1; ++x) {
      const bool sw = blocked(x - 1, y - 1), se = blocked(x, y - 1), nw = blocked(x - 1, y), ne = blocked(x, y);
      const int n = sw + se + nw + ne;
      if (n == 1 || n == 3 || (n == 2 && sw == ne)) ++p.vertices;
    }
  }
  p.blocked_fraction = static_cast<double>(black) / (w * h);
  p.possible_vertices = (w + 1) * (h + 1);
  p.complexity = (p.blocked_fraction + static_cast<double>(p.vertices) / p.possible_vertices) / 2;
  return p;
}

namespace {

// Squared gaps between every pair of obstacles, over their border cells.
std::vector<std::vector<std::int64_t>> obstacle_gaps(const OccupancyGrid& map, const std::vector<Obstacle>& obstacles) {
  std::vector<std::vector<Cell>> border(obstacles.size());
  for (std::size_t o = 0; o < obstacles.size(); ++o) {
    for (const Cell c : obstacles[o].cells) {
      bool edge = false;
      for (int k = 0; k < 8 && !edge; ++k) edge = map.is_free({c.x + kNeighbourDx[k], c.y + kNeighbourDy[k]});
      if (edge) border[o].push_back(c);
    }
  }
  const std::size_t n = obstacles.size();
  std::vector<std::vector<std::int64_t>> gap(n, std::vector<std::int64_t>(n, 0));
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = a + 1; b < n; ++b) {
      std::int64_t best = std::numeric_limits<std::int64_t>::max();
      for (const Cell p : border[a]) {
        for (const Cell q : border[b]) {
          const std::int64_t dx = p.x - q.x, dy = p.y - q.y;
          best = std::min(best, dx * dx + dy * dy);
        }
      }
      gap[a][b] = gap[b][a] = best;
    }
  }
  return gap;
}

ObstacleGroup make_group(const OccupancyGrid& map, const std::vector<Obstacle>& obstacles,
                         std::vector<int> members, std::vector<ObstacleLink> links) {
  ObstacleGroup g;
  std::sort(members.begin(), members.end());
  std::sort(links.begin(), links.end(), [](const ObstacleLink& x, const ObstacleLink& y) {
    return std::pair(x.a, x.b) < std::pair(y.a, y.b);
  });
  g.obstacles = std::move(members);
  g.links = std::move(links);
  g.lo = obstacles[static_cast<std::size_t>(g.obstacles.front())].lo;
  g.hi = obstacles[static_cast<std::size_t>(g.obstacles.front())].hi;
  for (int o : g.obstacles) {
    const Obstacle& ob = obstacles[static_cast<std::size_t>(o)];
    g.lo = {std::min(g.lo.x, ob.lo.x), std::min(g.lo.y, ob.lo.y)};
    g.hi = {std::max(g.hi.x, ob.hi.x), std::max(g.hi.y, ob.hi.y)};
  }
  g.parts = box_complexity(map, g.lo, g.hi);
  return g;
}

// The connected parts of `members` under `links`, each with its links, in lowest-member order.
std::vector<std::pair<std::vector<int>, std::vector<ObstacleLink>>> components(
    const std::vector<int>& members, const std::vector<ObstacleLink>& links) {
  std::vector<int> root(members.size());
  std::iota(root.begin(), root.end(), 0);
  const auto slot = [&](int obstacle) {
    return static_cast<int>(std::lower_bound(members.begin(), members.end(), obstacle) - members.begin());
  };
  const auto find = [&](int i) {
    while (root[static_cast<std::size_t>(i)] != i) i = root[static_cast<std::size_t>(i)] = root[static_cast<std::size_t>(root[static_cast<std::size_t>(i)])];
    return i;
  };
  for (const ObstacleLink& l : links) {
    const int a = find(slot(l.a)), b = find(slot(l.b));
    root[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
  }
  std::vector<std::pair<std::vector<int>, std::vector<ObstacleLink>>> out;
  std::vector<int> part_of(members.size(), -1);
  for (std::size_t i = 0; i < members.size(); ++i) {
    const auto r = static_cast<std::size_t>(find(static_cast<int>(i)));
    if (part_of[r] < 0) {
      part_of[r] = static_cast<int>(out.size());
      out.emplace_back();
    }
    out[static_cast<std::size_t>(part_of[r])].first.push_back(members[i]);
  }
  for (const ObstacleLink& l : links) {
    out[static_cast<std::size_t>(part_of[static_cast<std::size_t>(find(slot(l.a)))])].second.push_back(l);
  }
  return out;
}

std::int64_t group_gap(const std::vector<std::vector<std::int64_t>>& gap, const ObstacleGroup& g,
                       const ObstacleGroup& h, ObstacleLink* closest) {
  std::int64_t best = std::numeric_limits<std::int64_t>::max();
  for (int a : g.obstacles) {
    for (int b : h.obstacles) {
      const std::int64_t d = gap[static_cast<std::size_t>(a)][static_cast<std::size_t>(b)];
      if (d < best) {
        best = d;
        if (closest != nullptr) *closest = {std::min(a, b), std::max(a, b), d};
      }
    }
  }
  return best;
}

std::int64_t box_gap_sq(const ObstacleGroup& g, const ObstacleGroup& h) {
  const std::int64_t dx = std::max({0, h.lo.x - g.hi.x, g.lo.x - h.hi.x});
  const std::int64_t dy = std::max({0, h.lo.y - g.hi.y, g.lo.y - h.hi.y});
  return dx * dx + dy * dy;
}

bool by_first_obstacle(const ObstacleGroup& a, const ObstacleGroup& b) {
  return a.obstacles.front() < b.obstacles.front();
}

}  // namespace

Grouping group_obstacles(const OccupancyGrid& map, const GroupKConfig& config) {
  Grouping out;
  out.area_margin = config.area_margin;
  out.obstacles = find_obstacles(map);
  const std::size_t n = out.obstacles.size();
  if (n < 2) return out;
  const auto gap = obstacle_gaps(map, out.obstacles);

  // Basic_Group: each obstacle's link to its nearest; linked obstacles are a group.
  std::vector<ObstacleLink> links;
  for (std::size_t a = 0; a < n; ++a) {
    std::size_t best = a == 0 ? 1 : 0;
    for (std::size_t b = 0; b < n; ++b) {
      if (b != a && gap[a][b] < gap[a][best]) best = b;
    }
    const ObstacleLink l{static_cast<int>(std::min(a, best)), static_cast<int>(std::max(a, best)), gap[a][best]};
    if (std::find(links.begin(), links.end(), l) == links.end()) links.push_back(l);
  }
  std::vector<int> all(n);
  std::iota(all.begin(), all.end(), 0);
  for (auto& [members, part_links] : components(all, links)) {
    out.basic.push_back(make_group(map, out.obstacles, std::move(members), std::move(part_links)));
  }

  // Release_Group: drop the longest link while C < k; parts with a link are checked again.
  Rng rng(config.seed);
  std::vector<ObstacleGroup> todo(out.basic.rbegin(), out.basic.rend());  // a stack, first on top
  while (!todo.empty()) {
    ObstacleGroup g = std::move(todo.back());
    todo.pop_back();
    if (g.complexity() >= config.k) {
      out.released.push_back(std::move(g));
      continue;
    }
    std::int64_t longest = 0;
    for (const ObstacleLink& l : g.links) longest = std::max(longest, l.gap_sq);
    std::vector<std::size_t> ties;
    for (std::size_t i = 0; i < g.links.size(); ++i) {
      if (g.links[i].gap_sq == longest) ties.push_back(i);
    }
    const std::size_t drop = ties.size() == 1 ? ties.front() : ties[rng.below(ties.size())];
    g.links.erase(g.links.begin() + static_cast<std::ptrdiff_t>(drop));
    auto parts = components(g.obstacles, g.links);
    for (auto it = parts.rbegin(); it != parts.rend(); ++it) {
      if (it->second.empty()) continue;  // one obstacle: no group any more
      todo.push_back(make_group(map, out.obstacles, std::move(it->first), std::move(it->second)));
    }
  }
  std::sort(out.released.begin(), out.released.end(), by_first_obstacle);

  // Merge_Group: one pass, each group with its nearest if the union is complex enough.
  std::vector<ObstacleGroup> groups = out.released;
  std::vector<char> alive(groups.size(), 1);
  for (std::size_t i = 0; i < groups.size(); ++i) {
    if (!alive[i]) continue;
    std::optional<std::size_t> nearest;
    std::int64_t best = 0;
    ObstacleLink bridge;
    for (std::size_t j = 0; j < groups.size(); ++j) {
      if (j == i || !alive[j]) continue;
      ObstacleLink l;
      const std::int64_t d = group_gap(gap, groups[i], groups[j], &l);
      if (!nearest || d < best) nearest = j, best = d, bridge = l;
    }
    if (!nearest) continue;
    std::vector<int> members = groups[i].obstacles;
    members.insert(members.end(), groups[*nearest].obstacles.begin(), groups[*nearest].obstacles.end());
    std::vector<ObstacleLink> joined = groups[i].links;
    joined.insert(joined.end(), groups[*nearest].links.begin(), groups[*nearest].links.end());
    joined.push_back(bridge);
    ObstacleGroup v = make_group(map, out.obstacles, std::move(members), std::move(joined));
    if (v.complexity() >= config.k) {
      groups[i] = std::move(v);
      alive[*nearest] = 0;
    }
  }
  for (std::size_t i = 0; i < groups.size(); ++i) {
    if (alive[i]) out.groups.push_back(std::move(groups[i]));
  }
  std::sort(out.groups.begin(), out.groups.end(), by_first_obstacle);

  // Order: increasing C; among equal C the one nearest the previous group.
  std::vector<int> left(out.groups.size());
  std::iota(left.begin(), left.end(), 0);
  while (!left.empty()) {
    double lowest = std::numeric_limits<double>::infinity();
    for (int g : left) lowest = std::min(lowest, out.groups[static_cast<std::size_t>(g)].complexity());
    std::optional<std::size_t> pick;
    for (std::size_t k = 0; k < left.size(); ++k) {
      const ObstacleGroup& g = out.groups[static_cast<std::size_t>(left[k])];
      if (g.complexity() > lowest + 1e-12) continue;
      if (!pick) {
        pick = k;
      } else if (!out.order.empty()) {
        const ObstacleGroup& prev = out.groups[static_cast<std::size_t>(out.order.back())];
        if (box_gap_sq(prev, g) < box_gap_sq(prev, out.groups[static_cast<std::size_t>(left[*pick])])) pick = k;
      }
    }
    out.order.push_back(left[*pick]);
    left.erase(left.begin() + static_cast<std::ptrdiff_t>(*pick));
  }
  return out;
}

std::vector<CellMask> group_k_parts(const OccupancyGrid& map, const Grouping& grouping, const CellMask& region) {
  assert(region.size() == map.size());
  std::vector<CellMask> parts(grouping.order.size() + 1, CellMask(map.size(), 0));
  CellMask taken(map.size(), 0);
  for (std::size_t p = 0; p < grouping.order.size(); ++p) {
    const ObstacleGroup& g = grouping.groups[static_cast<std::size_t>(grouping.order[p])];
    const int m = grouping.area_margin;
    for (int y = std::max(0, g.lo.y - m); y <= std::min(map.height() - 1, g.hi.y + m); ++y) {
      for (int x = std::max(0, g.lo.x - m); x <= std::min(map.width() - 1, g.hi.x + m); ++x) {
        const auto i = static_cast<std::size_t>(map.index({x, y}));
        if (!region[i] || taken[i]) continue;
        taken[i] = 1;
        parts[p + 1][i] = 1;
      }
    }
  }
  for (std::size_t i = 0; i < map.size(); ++i) parts[0][i] = region[i] && !taken[i];
  return parts;
}

GroupKCoverage group_k(const OccupancyGrid& map, const Grouping& grouping, const CellMask& region,
                       Cell start, const PlowOptions& plow) {
  GroupKCoverage out;
  out.grouping = grouping;
  const std::vector<CellMask> parts = group_k_parts(map, grouping, region);
  CellMask covered(map.size(), 0);
  out.path.cells.push_back(start);
  for (std::size_t p = 0; p < parts.size(); ++p) {
    out.parts.push_back({p == 0 ? -1 : grouping.order[p - 1], out.path.cells.size() - 1});
    (void)plow_part(map, parts[p], covered, out.path.cells, plow);
  }
  for (std::size_t i = 0; i < map.size(); ++i) {
    if (region[i] && !covered[i]) out.path.missed.push_back(map.cell_of(static_cast<int>(i)));
  }
  return out;
}

GroupKCoverage group_k(const OccupancyGrid& map, const CellMask& region, Cell start,
                       const GroupKConfig& config) {
  return group_k(map, group_obstacles(map, config), region, start, config.plow);
}

}  // namespace swarm::planner
