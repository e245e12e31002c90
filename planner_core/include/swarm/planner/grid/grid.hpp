// Occupancy grid: the one map type every algorithm in planner_core works on.
//
// Cells are addressed by integer (x, y) with x to the right and y up, (0, 0) being the cell whose
// lower-left corner is the map origin (ROS map_server convention: the PGM's last row is y = 0).
// Positions in metres map to cells by floor((p - origin) / resolution).
//
// Not thread-safe; copy it to share.
//
//   OccupancyGrid g(100, 100, 0.2);          // 20 m x 20 m, all Unknown
//   g.set({3, 4}, CellState::Free);
//   if (g.is_free({3, 4})) { ... }
#pragma once

#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

namespace swarm::planner {

enum class CellState : std::uint8_t { Unknown = 0, Free = 1, Occupied = 2 };

struct Cell {
  int x = 0;
  int y = 0;
  friend bool operator==(const Cell& a, const Cell& b) { return a.x == b.x && a.y == b.y; }
  friend bool operator!=(const Cell& a, const Cell& b) { return !(a == b); }
  friend bool operator<(const Cell& a, const Cell& b) { return a.y != b.y ? a.y < b.y : a.x < b.x; }
};

// One changed cell, as carried in map patches (see map_patch.hpp).
struct CellChange {
  std::int32_t index = 0;  // y * width + x
  CellState state = CellState::Unknown;
  friend bool operator==(const CellChange& a, const CellChange& b) {
    return a.index == b.index && a.state == b.state;
  }
};

class OccupancyGrid {
 public:
  OccupancyGrid() = default;
  OccupancyGrid(int width, int height, double resolution_m = 0.2, double origin_x_m = 0.0,
                double origin_y_m = 0.0, CellState fill = CellState::Unknown)
      : width_(width),
        height_(height),
        resolution_(resolution_m),
        origin_x_(origin_x_m),
        origin_y_(origin_y_m),
        cells_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), fill) {}

  int width() const { return width_; }
  int height() const { return height_; }
  double resolution() const { return resolution_; }
  double origin_x() const { return origin_x_; }
  double origin_y() const { return origin_y_; }
  std::size_t size() const { return cells_.size(); }

  bool in_bounds(Cell c) const { return c.x >= 0 && c.y >= 0 && c.x < width_ && c.y < height_; }
  int index(Cell c) const { return c.y * width_ + c.x; }
  Cell cell_of(int index) const { return {index % width_, index / width_}; }

  // Out-of-bounds reads are Occupied: the world ends in a wall for every algorithm.
  CellState at(Cell c) const { return in_bounds(c) ? cells_[index(c)] : CellState::Occupied; }
  CellState at(int index) const { return cells_[index]; }
  void set(Cell c, CellState s) { cells_[index(c)] = s; }
  void set(int index, CellState s) { cells_[index] = s; }

  bool is_free(Cell c) const { return at(c) == CellState::Free; }
  bool is_occupied(Cell c) const { return at(c) == CellState::Occupied; }
  bool is_unknown(Cell c) const { return in_bounds(c) && cells_[index(c)] == CellState::Unknown; }

  // Metres (map frame) <-> cells. The centre of cell c is returned by centre_of.
  Cell cell_at(double x_m, double y_m) const;
  void centre_of(Cell c, double& x_m, double& y_m) const;

  const std::vector<CellState>& data() const { return cells_; }
  std::vector<CellState>& data() { return cells_; }

  // Applies changes; returns how many actually changed a cell.
  int apply(const std::vector<CellChange>& changes);

  friend bool operator==(const OccupancyGrid& a, const OccupancyGrid& b) {
    return a.width_ == b.width_ && a.height_ == b.height_ && a.cells_ == b.cells_;
  }

 private:
  int width_ = 0;
  int height_ = 0;
  double resolution_ = 0.2;
  double origin_x_ = 0.0;
  double origin_y_ = 0.0;
  std::vector<CellState> cells_;
};

// 8-neighbourhood offsets, orthogonal first. Diagonal moves never cut a corner: a diagonal step is
// allowed only when both orthogonal cells it passes are passable (see astar.hpp, reachability).
inline constexpr int kNeighbourDx[8] = {1, -1, 0, 0, 1, 1, -1, -1};
inline constexpr int kNeighbourDy[8] = {0, 0, 1, -1, 1, -1, 1, -1};

// Octile distance in cells (diagonal = sqrt 2): the exact cost of an obstacle-free 8-connected path.
double octile_distance(Cell a, Cell b);
double euclidean_distance(Cell a, Cell b);

// "(x, y)", for messages.
std::string to_string(Cell c);

}  // namespace swarm::planner
