#include "swarm/planner/grid/grid.hpp"

#include <cmath>

namespace swarm::planner {

Cell OccupancyGrid::cell_at(double x_m, double y_m) const {
  return {static_cast<int>(std::floor((x_m - origin_x_) / resolution_)),
          static_cast<int>(std::floor((y_m - origin_y_) / resolution_))};
}

void OccupancyGrid::centre_of(Cell c, double& x_m, double& y_m) const {
  x_m = origin_x_ + (c.x + 0.5) * resolution_;
  y_m = origin_y_ + (c.y + 0.5) * resolution_;
}

int OccupancyGrid::apply(const std::vector<CellChange>& changes) {
  int changed = 0;
  for (const CellChange& ch : changes) {
    if (cells_[ch.index] != ch.state) {
      cells_[ch.index] = ch.state;
      ++changed;
    }
  }
  return changed;
}

double octile_distance(Cell a, Cell b) {
  const int dx = std::abs(a.x - b.x);
  const int dy = std::abs(a.y - b.y);
  return (dx > dy ? dx - dy : dy - dx) + std::sqrt(2.0) * (dx < dy ? dx : dy);
}

double euclidean_distance(Cell a, Cell b) { return std::hypot(a.x - b.x, a.y - b.y); }

std::string to_string(Cell c) {
  std::string s = "(";  // appended piecewise: GCC 12 warns (-Wrestrict) on "(" + std::to_string(..)
  s += std::to_string(c.x);
  s += ", ";
  s += std::to_string(c.y);
  s += ")";
  return s;
}

}  // namespace swarm::planner
