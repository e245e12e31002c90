// The global map at the GCS, free of DDS (docs/papers.md section 2): every group's map changes
// fused into one grid. Every task of the mission reads it; exploration plans its rounds on it
// (tasks/explore/planning_rounds.hpp), coverage and path finding divide what it knows.
//
//   FusedMap m(w, h, res, 3);
//   m.fuse(group, changes);  // a leader's patch; a later state of a cell replaces the earlier one
//   m.grid(); m.mapped_fraction(); m.heard_from_every_group();
#pragma once

#include <cstddef>
#include <vector>

#include "swarm/planner/grid/grid.hpp"

namespace swarm::gcs {

class FusedMap {
 public:
  FusedMap(int width, int height, double resolution, int groups);

  void fuse(int group, const std::vector<planner::CellChange>& changes);

  [[nodiscard]] const planner::OccupancyGrid& grid() const { return grid_; }
  // Known cells over the map's bounding box.
  [[nodiscard]] double mapped_fraction() const;
  // Every group's first patch has come (even an empty one): the map holds each group's first scans.
  [[nodiscard]] bool heard_from_every_group() const { return heard_ == seen_group_.size(); }

 private:
  planner::OccupancyGrid grid_;
  std::size_t known_ = 0;
  std::vector<bool> seen_group_;
  std::size_t heard_ = 0;
};

}  // namespace swarm::gcs
