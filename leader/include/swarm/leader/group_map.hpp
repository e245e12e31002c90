// What a group leader knows (paper section 3.1): the stale global map the GCS last distributed,
// and the group map = that global map + everything the group's own robots observed since. The
// group frontiers of the paper are the frontiers of the group map that are not frontiers of the
// global map (planner/explore/explore.hpp computes them from the two maps kept here).
//
// The world is static and every observation is a true ray cast, so knowledge only grows: a cell
// once known never changes, and merging is "take whichever map knows the cell". DDS-free.
#pragma once

#include <vector>

#include "swarm/planner/grid/grid.hpp"

namespace swarm::leader {

class GroupMap {
 public:
  GroupMap(int width, int height, double resolution);

  // The group's own observations; returns those new to the group map.
  std::vector<planner::CellChange> observe(const std::vector<planner::CellChange>& changes);
  // A newly distributed global map; returns the cells it adds to the group map.
  std::vector<planner::CellChange> adopt_global(const planner::OccupancyGrid& global);

  const planner::OccupancyGrid& global() const { return global_; }
  const planner::OccupancyGrid& group() const { return group_; }

 private:
  planner::OccupancyGrid global_;
  planner::OccupancyGrid group_;
};

}  // namespace swarm::leader
