// The paper's world (docs/papers.md section 3): warehouse blocks in a grid pattern, with passages
// between them and intersections where passages cross; and random instances on any map.
//
// As a grid (a "doubled" lattice): R x C intersections at cells (2j + 1, 2i + 1), i < R, j < C,
// joined by one-cell passage middles; the blocks between them and a one-cell border are walls.
// So the map is (2C + 1) x (2R + 1) cells, and going from one intersection to the next takes 2
// time steps, as in the paper. The paper's test map is "5 x 8" (R = 5 rows, C = 8 columns of
// intersections: 17 x 11 cells); its rules are Rules::paper_warehouse() (instance.hpp).
//
//   const OccupancyGrid map = warehouse_map(5, 8);
//   Instance in = random_warehouse_instance(5, 8, 20, /*seed=*/3);   // 20 robots, paper rules
//   Instance any = random_instance(some_map, 50, /*seed=*/1);          // standard rules
//
// Thread-safe (pure functions). Random draws go through rng.hpp.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "swarm/planner/mapf/instance.hpp"

namespace swarm::planner::mapf {

// The warehouse lattice of `rows` x `cols` intersections (both >= 1).
[[nodiscard]] OccupancyGrid warehouse_map(int rows, int cols, double resolution_m = 0.2);

// The cell of intersection (row i, column j).
[[nodiscard]] inline Cell warehouse_intersection(int i, int j) { return {2 * j + 1, 2 * i + 1}; }

// "warehouse-5x8" -> {5, 8}; nullopt for anything else (rows, columns in 1..100).
struct WarehouseSize {
  int rows = 5;
  int cols = 8;
};
[[nodiscard]] std::optional<WarehouseSize> parse_warehouse_name(const std::string& name);
// The size of `map` if it is exactly a warehouse_map, else nullopt.
[[nodiscard]] std::optional<WarehouseSize> warehouse_size_of(const OccupancyGrid& map);

// `robots` robots on random intersections: distinct starts, distinct goals, each start != its
// goal (the paper's choice is not stated; docs/papers.md section 3's decision). Paper rules.
// Requires robots <= rows * cols (and rows * cols >= 2).
[[nodiscard]] Instance random_warehouse_instance(int rows, int cols, int robots, std::uint64_t seed);

// `agents` agents on random Free cells of `map`: distinct starts, distinct goals, each goal
// reachable from its start and != it. Standard rules. Returns nullopt when the map has too few
// free cells.
[[nodiscard]] std::optional<Instance> random_instance(const OccupancyGrid& map, int agents, std::uint64_t seed);

}  // namespace swarm::planner::mapf
