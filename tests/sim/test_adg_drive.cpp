// Solvers' plans driven by their action-dependency graph (planner/mapf/adg.hpp) with late, jittered
// knowledge of the others' progress, through the simulator's own move resolution (sim::resolve):
// the executed paths go through the independent MAPF validator (no vertex or swap conflict, legal
// steps), the simulator sees no conflict, and every robot arrives (no deadlock).
#include <gtest/gtest.h>

#include <deque>

#include "swarm/planner/mapf/adg.hpp"
#include "swarm/planner/mapf/solver.hpp"
#include "swarm/planner/mapf/validate.hpp"
#include "swarm/planner/mapf/warehouse.hpp"
#include "swarm/planner/grid/rng.hpp"
#include "swarm/sim/world.hpp"
#include "swarm_test/ascii_grid.hpp"

namespace {

using swarm::planner::Cell;
using namespace swarm::planner::mapf;

struct Drive {
  std::vector<Path> executed;
  std::uint64_t conflicts = 0;  // vertex + edge events the simulator saw
  std::uint64_t blocked = 0;
};

// Each tick every robot knows the others' progress `lag` ticks late (0..max_delay, drawn per robot
// and tick) and tries its next step if the graph releases it; the simulator resolves the moves.
Drive drive(const Dependencies& d, int max_delay, std::uint64_t seed) {
  const std::size_t n = d.routes.size();
  swarm::planner::Rng rng(seed);
  std::vector<std::uint32_t> progress(n, 0);
  std::deque<std::vector<std::uint32_t>> history{progress};  // history[k] = progress k ticks ago
  Drive out;
  out.executed.resize(n);
  std::vector<Cell> at(n);
  for (std::size_t r = 0; r < n; ++r) at[r] = d.routes[r][0];
  for (std::size_t r = 0; r < n; ++r) out.executed[r].push_back(at[r]);
  for (int tick = 0; tick < 5000; ++tick) {
    bool all_done = true;
    std::vector<Cell> intended = at;
    for (std::size_t r = 0; r < n; ++r) {
      if (progress[r] + 1 >= d.routes[r].size()) continue;
      all_done = false;
      const std::size_t lag = std::min<std::size_t>(history.size() - 1, rng.below(static_cast<std::uint64_t>(max_delay) + 1));
      std::vector<std::uint32_t> known = history[lag];
      known[r] = progress[r];
      if (releasable(d, static_cast<int>(r), known) > progress[r]) intended[r] = d.routes[r][progress[r] + 1];
    }
    if (all_done) break;
    const swarm::sim::Resolution res = swarm::sim::resolve(at, intended);
    out.conflicts += res.events.vertex + res.events.edge;
    for (std::size_t r = 0; r < n; ++r) {
      out.blocked += res.blocked[r];
      if (res.moved[r]) ++progress[r];
    }
    at = res.next;
    history.push_front(progress);
    if (history.size() > static_cast<std::size_t>(max_delay) + 1) history.pop_back();
    for (std::size_t r = 0; r < n; ++r) out.executed[r].push_back(at[r]);
  }
  return out;
}

TEST(AdgDrive, LateKnowledgeNeverCollidesAndEveryRobotArrives) {
  const auto map = swarm::test::grid_from({"............", "..##....#...", "......#.....", ".#......##..",
                                           "....#.......", "...#....#...", "............", "..#...#....."});
  std::size_t rotations = 0, ecbs_rotations = 0;
  for (SolverKind kind : {SolverKind::Ecbs, SolverKind::Lacam}) {
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
      const Instance in = *random_instance(map, 14, seed);
      SolverConfig c;
      c.kind = kind;
      const Result plan = solve(in, c, StopCondition::after(10));
      ASSERT_EQ(plan.status, Status::Solved);
      const Dependencies d = dependencies(plan.paths);
      if (kind == SolverKind::Ecbs) ecbs_rotations += d.rotations.size();
      for (int delay : {0, 1, 3, 6}) {
        const Drive run = drive(d, delay, seed * 10 + static_cast<std::uint64_t>(delay));
        const ValidationReport v = validate(in, run.executed);
        EXPECT_TRUE(v.ok()) << to_string(kind) << " seed " << seed << " delay " << delay << ": " << v.summary();
        // A refused try is possible only in a rotation whose robots learn of it in different ticks.
        if (delay == 0 || d.rotations.empty()) {
          EXPECT_EQ(run.conflicts, 0u) << to_string(kind) << " seed " << seed << " delay " << delay;
        }
        rotations += d.rotations.size();
      }
    }
  }
  EXPECT_EQ(ecbs_rotations, 1u);  // the case is exercised (ECBS, seed 4)
  EXPECT_GT(rotations, 0u);
}

TEST(AdgDrive, ARotationMovesTogetherOnceAllAreReleased) {
  // Four robots round the 2 x 2 square: with late knowledge some try first and are held.
  const std::vector<Path> plan{{{0, 0}, {1, 0}}, {{1, 0}, {1, 1}}, {{1, 1}, {0, 1}}, {{0, 1}, {0, 0}}};
  const Drive run = drive(dependencies(plan), 0, 1);
  EXPECT_EQ(run.conflicts, 0u);
  EXPECT_EQ(run.blocked, 0u);
  EXPECT_EQ(run.executed[0], (Path{{0, 0}, {1, 0}}));
}

}  // namespace
