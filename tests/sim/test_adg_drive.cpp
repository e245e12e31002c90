// Solvers' plans driven by their action-dependency graph (planner/mapf/adg.hpp) with late, jittered
// knowledge of the others' progress, through the simulator's own move resolution (sim::resolve):
// the executed paths go through the independent MAPF validator (no vertex or swap conflict, legal
// steps), the simulator sees no conflict, and every robot arrives (no deadlock).
#include <gtest/gtest.h>

#include <deque>
#include <string>

#include "swarm/planner/mapf/adg.hpp"
#include "swarm/planner/mapf/release_watch.hpp"
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

enum class Watches { No, Yes };

// Each tick every robot knows the others' progress `lag` ticks late (0..max_delay, drawn per robot
// and tick) and tries its next step if the graph releases it; the simulator resolves the moves.
// With watches, each robot also gets the watch made from that late knowledge
// (planner/mapf/release_watch.hpp) and follows it through the true cells of every tick since the
// knowledge was current: what a member does with the clock.
Drive drive(const Dependencies& d, int max_delay, std::uint64_t seed, Watches watches = Watches::No) {
  const std::size_t n = d.routes.size();
  swarm::planner::Rng rng(seed);
  std::vector<std::uint32_t> progress(n, 0);
  std::vector<Cell> at(n);
  for (std::size_t r = 0; r < n; ++r) at[r] = d.routes[r][0];
  // history[k]: progress and cells k ticks ago
  std::deque<std::pair<std::vector<std::uint32_t>, std::vector<Cell>>> history{{progress, at}};
  Drive out;
  out.executed.resize(n);
  for (std::size_t r = 0; r < n; ++r) out.executed[r].push_back(at[r]);
  for (int tick = 0; tick < 5000; ++tick) {
    bool all_done = true;
    std::vector<Cell> intended = at;
    for (std::size_t r = 0; r < n; ++r) {
      if (progress[r] + 1 >= d.routes[r].size()) continue;
      all_done = false;
      const std::size_t lag = std::min<std::size_t>(history.size() - 1, rng.below(static_cast<std::uint64_t>(max_delay) + 1));
      std::vector<std::uint32_t> known = history[lag].first;
      known[r] = progress[r];
      std::uint32_t may = releasable(d, static_cast<int>(r), known);
      if (watches == Watches::Yes) {
        // Made from what was known `lag` ticks ago, the robot's own progress too (as its leader
        // knows it), and followed from then on.
        const Watch w = watch_release(d, static_cast<int>(r), history[lag].first, 8);
        ReleaseWatch rw(w.routes, w.gates);
        for (std::size_t back = lag + 1; back-- > 0;) {
          std::vector<Cell> seen;
          for (int watched : w.robots) seen.push_back(history[back].second[static_cast<std::size_t>(watched)]);
          rw.see(seen);
        }
        may = std::max(may, rw.opened());
      }
      if (may > progress[r]) intended[r] = d.routes[r][progress[r] + 1];
    }
    if (all_done) break;
    const swarm::sim::Resolution res = swarm::sim::resolve(at, intended);
    out.conflicts += res.events.vertex + res.events.edge;
    for (std::size_t r = 0; r < n; ++r) {
      out.blocked += res.blocked[r];
      if (res.moved[r]) ++progress[r];
    }
    at = res.next;
    history.push_front({progress, at});
    if (history.size() > static_cast<std::size_t>(max_delay) + 1) history.pop_back();
    for (std::size_t r = 0; r < n; ++r) out.executed[r].push_back(at[r]);
  }
  return out;
}

std::size_t makespan(const Drive& run) {
  std::size_t last = 0;
  for (const Path& p : run.executed) {
    std::size_t t = p.size() - 1;
    while (t > 0 && p[t] == p[t - 1]) --t;
    last = std::max(last, t);
  }
  return last;
}

struct Solved {
  std::string name;  // solver and seed
  std::uint64_t seed;
  Instance in;
  Dependencies d;
};

// The plans both tests below drive: ECBS's and LaCAM's, seeds 1-6, 14 robots among walls.
std::vector<Solved> solved_plans() {
  const auto map = swarm::test::grid_from({"............", "..##....#...", "......#.....", ".#......##..",
                                           "....#.......", "...#....#...", "............", "..#...#....."});
  std::vector<Solved> out;
  for (SolverKind kind : {SolverKind::Ecbs, SolverKind::Lacam}) {
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
      const Instance in = *random_instance(map, 14, seed);
      SolverConfig c;
      c.kind = kind;
      const Result plan = solve(in, c, StopCondition::after(10));
      EXPECT_EQ(plan.status, Status::Solved);
      if (plan.status != Status::Solved) continue;
      out.push_back({std::string(to_string(kind)) + " seed " + std::to_string(seed), seed, in, dependencies(plan.paths)});
    }
  }
  return out;
}

TEST(AdgDrive, LateKnowledgeNeverCollidesAndEveryRobotArrives) {
  std::size_t rotations = 0, ecbs_rotations = 0;
  for (const Solved& p : solved_plans()) {
    const std::uint64_t seed = p.seed;
    if (p.name.rfind(to_string(SolverKind::Ecbs), 0) == 0) ecbs_rotations += p.d.rotations.size();
    for (int delay : {0, 1, 3, 6}) {
      const Drive run = drive(p.d, delay, seed * 10 + static_cast<std::uint64_t>(delay));
      const ValidationReport v = validate(p.in, run.executed);
      EXPECT_TRUE(v.ok()) << p.name << " delay " << delay << ": " << v.summary();
      // A refused try is possible only in a rotation whose robots learn of it in different ticks.
      if (delay == 0 || p.d.rotations.empty()) {
        EXPECT_EQ(run.conflicts, 0u) << p.name << " delay " << delay;
      }
      rotations += p.d.rotations.size();
    }
  }
  EXPECT_EQ(ecbs_rotations, 1u);  // the case is exercised (ECBS, seed 4)
  EXPECT_GT(rotations, 0u);
}

// With watches, late knowledge costs next to nothing: a robot sets off when it sees the robots it
// waits on gone, not when it learns of their progress. Still no conflict, and every robot arrives.
TEST(AdgDrive, WatchedReleasesKeepThePlanAndItsPaceUnderLateKnowledge) {
  std::size_t blind_ticks = 0, watched_ticks = 0, exact_ticks = 0;
  for (const Solved& p : solved_plans()) {
    const std::uint64_t seed = p.seed;
    exact_ticks += makespan(drive(p.d, 0, seed));
    for (int delay : {1, 3, 6}) {
      const Drive run = drive(p.d, delay, seed * 10 + static_cast<std::uint64_t>(delay), Watches::Yes);
      const ValidationReport v = validate(p.in, run.executed);
      EXPECT_TRUE(v.ok()) << p.name << " delay " << delay << ": " << v.summary();
      if (p.d.rotations.empty()) {
        EXPECT_EQ(run.conflicts, 0u) << p.name << " delay " << delay;
      }
      if (delay == 6) {
        watched_ticks += makespan(run);
        blind_ticks += makespan(drive(p.d, delay, seed * 10 + static_cast<std::uint64_t>(delay)));
      }
    }
  }
  // Measured: the 12 plans take 246 ticks in all with knowledge at once; with knowledge up to 6
  // ticks late, 533 without watches and 265 with them.
  EXPECT_LT(watched_ticks, blind_ticks);
  EXPECT_LE(watched_ticks, exact_ticks + exact_ticks / 10) << "exact " << exact_ticks << ", blind " << blind_ticks;
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
