// PIBT's swap (Okumura, "Improving LaCAM for Scalable Eventually Optimal Multi-Agent Pathfinding",
// IJCAI 2023): two agents head-on in a corridor too narrow to pass. PIBT alone has the one with
// priority push the other back for ever; with the swap the pusher backs away instead, pulling the
// other along into its cell, until they reach a branch where they can trade places. These are the
// two walks along the corridor that decide it; LaCAM*'s PIBT (lacam.cpp) and the traffic layer's
// (traffic/traffic.cpp) run them over their own graphs.
//
//   side_ways(cell, excluded, other) -> int: how many ways lead on from `cell` but to `excluded`
//     (a dead end an agent rests in does not count); `other` is set to one of them.
//   dist(agent, cell) -> int: the agent's distance from `cell` to its goal.
//
// Header-only and pure: deterministic, thread-safe as the callbacks are.
#pragma once

namespace swarm::planner::mapf {

// Must `pusher` (at at_pusher, heading for at_puller) and `puller` (at at_puller) trade places?
// Along the corridor in the pusher's direction, as long as that brings it nearer its goal, a
// branch leaves room to step aside; where none does, they must if the puller wants to be where the
// pusher is and the pusher where the puller is (or it is home already).
template <class SideWays, class Dist>
[[nodiscard]] bool swap_required(int pusher, int puller, int at_pusher, int at_puller, const SideWays& side_ways,
                                 const Dist& dist) {
  while (dist(pusher, at_puller) < dist(pusher, at_pusher)) {
    int other = -1;
    const int ways = side_ways(at_puller, at_pusher, other);
    if (ways >= 2) return false;
    if (ways == 0) break;
    at_pusher = at_puller;
    at_puller = other;
  }
  const int dq_p = dist(puller, at_pusher), dq_q = dist(puller, at_puller);
  const int dp_p = dist(pusher, at_pusher), dp_q = dist(pusher, at_puller);
  return dq_p < dq_q && (dp_p == 0 || dp_q < dp_p);
}

// Is there a branch off the corridor behind the puller (at at_puller, the pusher at at_pusher)
// where the two can trade places?
template <class SideWays>
[[nodiscard]] bool swap_possible(int at_pusher, int at_puller, const SideWays& side_ways) {
  const int start = at_pusher;
  while (at_puller != start) {
    int other = -1;
    const int ways = side_ways(at_puller, at_pusher, other);
    if (ways >= 2) return true;
    if (ways == 0) return false;
    at_pusher = at_puller;
    at_puller = other;
  }
  return false;
}

}  // namespace swarm::planner::mapf
