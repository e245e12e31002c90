// How collect shares objects out, at every level (the GCS among the groups or among all robots,
// a leader among its members): each object, in order, to the nearest holder (straight-line
// distance between cells; the first in order on a tie) that holds fewer than `room`, where room
// is an even share of everything to be held: ⌈(objects + already held) / holders⌉.
#pragma once

#include <cstddef>
#include <vector>

#include "swarm/planner/grid/grid.hpp"

namespace swarm::collect {

// The holder index each of `objects` goes to (-1: none had room, only when there are no holders).
// `held[h]`: what holder h holds already, counted into the room and grown by what it is given.
[[nodiscard]] std::vector<int> nearest_with_room(const std::vector<planner::Cell>& objects,
                                                 const std::vector<planner::Cell>& holders,
                                                 std::vector<std::size_t>& held);

}  // namespace swarm::collect
