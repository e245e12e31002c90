#include "swarm/planner/mapf/warehouse.hpp"

#include <charconv>
#include <deque>
#include <numeric>

#include "swarm/planner/grid/rng.hpp"

namespace swarm::planner::mapf {
namespace {

// Fisher-Yates with rng.hpp, so the order is the same on every standard library.
template <class T>
void shuffle(std::vector<T>& v, Rng& rng) {
  for (std::size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[rng.below(i)]);
}

}  // namespace

OccupancyGrid warehouse_map(int rows, int cols, double resolution_m) {
  OccupancyGrid g(2 * cols + 1, 2 * rows + 1, resolution_m, 0.0, 0.0, CellState::Occupied);
  for (int y = 1; y < g.height() - 1; ++y) {
    for (int x = 1; x < g.width() - 1; ++x) {
      if (x % 2 == 1 || y % 2 == 1) g.set(Cell{x, y}, CellState::Free);  // blocks at (even, even)
    }
  }
  return g;
}

std::optional<WarehouseSize> parse_warehouse_name(const std::string& name) {
  const std::string prefix = "warehouse-";
  if (name.rfind(prefix, 0) != 0) return std::nullopt;
  const std::string rest = name.substr(prefix.size());
  const std::size_t x = rest.find('x');
  if (x == std::string::npos) return std::nullopt;
  WarehouseSize s;
  const auto parse = [](const std::string& t, int& out) {
    const auto [p, ec] = std::from_chars(t.data(), t.data() + t.size(), out);
    return ec == std::errc() && p == t.data() + t.size() && !t.empty() && out >= 1 && out <= 100;
  };
  if (!parse(rest.substr(0, x), s.rows) || !parse(rest.substr(x + 1), s.cols)) return std::nullopt;
  return s;
}

std::optional<WarehouseSize> warehouse_size_of(const OccupancyGrid& map) {
  if (map.width() < 3 || map.height() < 3 || map.width() % 2 == 0 || map.height() % 2 == 0) return std::nullopt;
  const WarehouseSize s{(map.height() - 1) / 2, (map.width() - 1) / 2};
  const OccupancyGrid w = warehouse_map(s.rows, s.cols);
  for (int i = 0; i < static_cast<int>(map.size()); ++i) {
    if ((map.at(i) == CellState::Free) != (w.at(i) == CellState::Free)) return std::nullopt;
  }
  return s;
}

Instance random_warehouse_instance(int rows, int cols, int robots, std::uint64_t seed) {
  Instance in;
  in.map = warehouse_map(rows, cols);
  in.rules = Rules::paper_warehouse();
  const int n = rows * cols;
  Rng rng(mix_seed(seed, 0x77617265ULL));
  std::vector<int> starts(static_cast<std::size_t>(n));
  std::iota(starts.begin(), starts.end(), 0);
  shuffle(starts, rng);
  starts.resize(static_cast<std::size_t>(robots));
  // Goals: a random permutation of the intersections, redrawn until no robot starts on its goal
  // (a derangement restricted to the chosen starts; few draws for any sensible size).
  std::vector<int> goals(static_cast<std::size_t>(n));
  bool ok = false;
  while (!ok && n >= 2) {
    std::iota(goals.begin(), goals.end(), 0);
    shuffle(goals, rng);
    ok = true;
    for (int r = 0; r < robots; ++r) ok = ok && goals[static_cast<std::size_t>(r)] != starts[static_cast<std::size_t>(r)];
  }
  for (int r = 0; r < robots; ++r) {
    const int s = starts[static_cast<std::size_t>(r)];
    const int g = goals[static_cast<std::size_t>(r)];
    in.starts.push_back(warehouse_intersection(s / cols, s % cols));
    in.goals.push_back(warehouse_intersection(g / cols, g % cols));
  }
  return in;
}

std::optional<Instance> random_instance(const OccupancyGrid& map, int agents, std::uint64_t seed) {
  // Connected areas (4-connected), so that every goal is reachable from its start.
  std::vector<int> area(map.size(), -1);
  std::vector<std::vector<int>> members;
  for (int i = 0; i < static_cast<int>(map.size()); ++i) {
    if (map.at(i) != CellState::Free || area[static_cast<std::size_t>(i)] >= 0) continue;
    const int id = static_cast<int>(members.size());
    members.emplace_back();
    std::deque<int> todo{i};
    area[static_cast<std::size_t>(i)] = id;
    while (!todo.empty()) {
      const int c = todo.front();
      todo.pop_front();
      members.back().push_back(c);
      MotionModel::four().for_each_neighbour(map, map.cell_of(c), [&](Cell n, double) {
        int& a = area[static_cast<std::size_t>(map.index(n))];
        if (a < 0) {
          a = id;
          todo.push_back(map.index(n));
        }
      });
    }
  }
  Rng rng(mix_seed(seed, 0x72616e64ULL));
  std::vector<int> cells;
  for (int i = 0; i < static_cast<int>(map.size()); ++i) {
    if (area[static_cast<std::size_t>(i)] >= 0 && members[static_cast<std::size_t>(area[static_cast<std::size_t>(i)])].size() >= 2) cells.push_back(i);
  }
  if (static_cast<int>(cells.size()) < agents) return std::nullopt;
  shuffle(cells, rng);
  Instance in;
  in.map = map;
  std::vector<char> goal_taken(map.size(), 0);
  for (int a = 0; a < agents; ++a) {
    const int s = cells[static_cast<std::size_t>(a)];
    const auto& pool = members[static_cast<std::size_t>(area[static_cast<std::size_t>(s)])];
    int g = -1;
    for (int tries = 0; tries < 64 && g < 0; ++tries) {
      const int c = pool[rng.below(pool.size())];
      if (c != s && !goal_taken[static_cast<std::size_t>(c)]) g = c;
    }
    for (std::size_t k = 0; g < 0 && k < pool.size(); ++k) {  // a crowded area: the first free one
      if (pool[k] != s && !goal_taken[static_cast<std::size_t>(pool[k])]) g = pool[k];
    }
    if (g < 0) return std::nullopt;
    goal_taken[static_cast<std::size_t>(g)] = 1;
    in.starts.push_back(map.cell_of(s));
    in.goals.push_back(map.cell_of(g));
  }
  return in;
}

}  // namespace swarm::planner::mapf
