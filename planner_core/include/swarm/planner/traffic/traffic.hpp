// The traffic layer's planner: lifelong multi-agent path finding on a grid. Robots take goals one
// after another (a coverage route's cells, a tour's stops, a waypoint, a gathering cell); the
// planner turns them into timed moves, `steps` at a time, that never put two robots on one cell
// and never swap two robots. Tasks say where each robot goes next; this decides who moves when.
//
// Algorithm: PIBT, priority inheritance with backtracking (Okumura, Machida, Défago & Tamura,
// "Priority inheritance with backtracking for iterative multi-agent path finding", AIJ 2022), in
// its lifelong form: every step each robot, in order of priority, takes the neighbouring cell (or
// its own) nearest its current goal that no robot of higher priority has taken; a robot standing
// on that cell is asked, with the asker's priority, to move out of the way first, and if it
// cannot, the asker tries its next cell. A robot's priority grows every step it is away from its
// goal and falls back when it reaches one, so a robot that has been waiting eventually goes first.
// With the swap of LaCAM* (Okumura, IJCAI 2023): two robots head-on in a corridor back up together
// to a branch and trade places there (never two bound for the same cell: the one ahead goes first).
//
// Guarantee (the PIBT paper's Theorem 2): on a graph where every two adjacent cells lie on a common
// cycle, the robot of highest priority reaches its goal, so every robot reaches each of its goals
// in finite time. Where cells hang on the map like branches of a tree (a corridor with one pocket,
// a dead end), that does not hold: robots that meet there can stand, or push each other back and
// forth, for ever. So when no robot has come nearer its goal than it ever was for
// kNoProgressSteps steps, or one has not for kStallSteps (far longer than PIBT keeps a robot
// waiting in a crowd), the planner makes a rescue: LaCAM (Okumura, AAAI 2023;
// planner/mapf/lacam.hpp), which is complete, plans the robots within kRescueRadius moves of the
// stalled ones, each to the cell of that region nearest its goal, and the other robots keep out of
// the region until the stalled ones are nearer their goals than they ever were; then PIBT goes on
// (`rescues` counts them). The planner also counts, per robot, the steps in a row in which it had
// a goal and got no closer to it (`waiting`), so that its caller sees a robot stuck.
//
// Robots that are `fixed` (stopped, or dead) never move and are obstacles to every other robot:
// distances are measured around them, and a goal that only their cells reach, or one on a wall,
// is skipped and reported (`skipped`) instead of being chased for ever. A robot without goals stays
// where it is unless a robot of higher priority needs its cell.
//
// Deterministic: the same map, agents, config and calls give the same windows. Not thread-safe
// (one planner per caller); it keeps each robot's priority and a cache of distance tables from one
// window to the next, so call it with the same robot at the same index every time.
//
//   traffic::Planner p(map, MotionModel::four(), {.seed = 7});
//   std::vector<traffic::Agent> agents = {{.at = {1, 1}, .goals = {{5, 1}, {5, 3}}}, {.at = {5, 1}}};
//   const traffic::Window w = p.plan(agents, 8);  // w.paths[a]: 9 cells from agents[a].at
//   // w.done[a] of agents[a].goals are behind it (reached, or skipped as unreachable)
#pragma once

#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "swarm/planner/grid/grid.hpp"
#include "swarm/planner/grid/motion.hpp"

namespace swarm::planner::traffic {

// A rescue's memory is capped, so that one among 1,000 robots on a large map cannot take
// gigabytes: its region stops growing once its cells times its robots reach kRescueTableEntries
// (LaCAM's distance table per robot, 4 bytes an entry: 128 MB), and LaCAM's search, which may keep
// a configuration of four numbers a robot at each of its steps, stops after rescue_polls(robots)
// polls (one per 64 steps), 512 at most: kRescueConfigEntries robots' states in all (about 16
// bytes each: 128 MB). A count, not a time, so that a run stays the same under any load.
inline constexpr std::size_t kRescueTableEntries = std::size_t{32} << 20;
inline constexpr std::size_t kRescueConfigEntries = std::size_t{8} << 20;
int rescue_polls(std::size_t robots);

struct Agent {
  Cell at;
  std::vector<Cell> goals;  // to reach in this order; empty: none
  bool fixed = false;       // stopped or dead: never moves, an obstacle to the others
};

struct Config {
  std::uint64_t seed = 0;  // tie-breaking among equally good cells, and the initial priorities
};

struct Window {
  std::vector<std::vector<Cell>> paths;  // per agent: steps + 1 cells, paths[a][0] == agents[a].at
  std::vector<int> done;                 // per agent: how many of its goals, in order, are behind it
  std::vector<std::vector<int>> skipped; // per agent: indices of the goals it could not reach
  // per agent, per goal behind it (done of them, in order): the index into its path at which it
  // stood on that goal, -1 for one skipped (a fixed agent's goals are all skipped)
  std::vector<std::vector<int>> reached_at;
  std::vector<int> waiting;              // per agent, at the window's end: steps in a row it had a
                                         // goal and got no closer to it
};

class Planner {
 public:
  Planner(OccupancyGrid map, MotionModel motion, Config config = {});

  // Plans `steps` steps from where the agents stand. Throws std::invalid_argument for agents on a
  // cell that is not free, two agents on one cell, or a changed number of agents.
  [[nodiscard]] Window plan(const std::vector<Agent>& agents, int steps);

  // The map grew or changed (an explored map): the next window plans on `map`, of the same size.
  // The robots keep their priorities. Throws std::invalid_argument for another size.
  void set_map(const OccupancyGrid& map);

  // Steps planned so far; the most steps in a row any robot had a goal and got no closer to it.
  [[nodiscard]] std::uint64_t steps_planned() const { return steps_planned_; }
  [[nodiscard]] int longest_wait() const { return longest_wait_; }
  // Rescues driven because PIBT stalled (see above), and the rescues tried that failed: LaCAM found
  // no plan within its budget, or none that brings a stalled robot nearer its goal (the robots then
  // go on with PIBT, and a rescue in a region twice as wide is tried after twice as long).
  [[nodiscard]] std::uint64_t rescues() const { return rescues_; }
  [[nodiscard]] std::uint64_t rescues_failed() const { return rescues_failed_; }

  // Steps in which no robot, or one robot, came nearer its goal than it ever was, after which the
  // planner makes a complete plan.
  static constexpr int kNoProgressSteps = 16;
  static constexpr int kStallSteps = 128;
  // A rescue's region: the cells within this many moves of a stalled robot, twice as many after
  // each rescue in a row that failed (up to 2^12 times, or the memory cap above).
  static constexpr int kRescueRadius = 8;

  static constexpr int kUnreachable = 1 << 29;

 private:
  // Steps from `cell` to `goal` around walls and fixed robots (kUnreachable where there is no
  // way). A breadth-first search from the goal, run only as far as the cells asked for so far
  // and resumed when a farther one is asked for: a robot on its way asks for cells ever nearer.
  int steps_to(int goal, int cell);
  struct Table {
    std::vector<int> dist;   // per cell; -1: not reached yet
    std::vector<int> queue;  // the search's cells in order of distance
    std::size_t head = 0;    // the next one to expand
  };
  // Drops the tables of goals no robot is heading for, once they hold more than a cap of cells.
  void trim_tables(const std::vector<Agent>& agents);
  bool push(int a, int parent);  // PIBT for agent a, asked by `parent` (-1: nobody)
  // PIBT's swap (planner/mapf/pibt_swap.hpp): the robot that must trade places with `a`, which
  // wants `best`, in a corridor too narrow to pass (-1: none); a robot without a goal never does.
  int swap_partner(int a, int best);
  bool swap_required(int pusher, int puller, int at_pusher, int at_puller);
  bool swap_possible(int at_pusher, int at_puller) const;
  // The passable neighbours of `cell` but `excluded`, not counting a dead end a robot without a goal
  // rests in; `other`: the last of them.
  int side_ways(int cell, int excluded, int& other) const;
  bool dead_end(int cell) const;  // exactly one passable neighbour
  int distance(int a, int cell);
  bool passable(int cell) const { return free_[static_cast<std::size_t>(cell)] && !blocked_[static_cast<std::size_t>(cell)]; }
  // After a step: counts each robot's steps without coming nearer its goal, and makes a rescue
  // plan (rescue_) once one has stalled for kStallSteps.
  void watch_for_stalls(const std::vector<Agent>& agents);
  // LaCAM from the current configuration (now_) within a region round the `stalled` robots, driven
  // until they are nearer their goals than they ever were; false if it found no plan.
  bool plan_rescue(const std::vector<Agent>& agents, const std::vector<int>& stalled);
  void end_rescue();
  void forget_distances();  // after the map or the fixed robots changed

  OccupancyGrid map_;
  MotionModel motion_;
  Config config_;
  std::vector<bool> free_;     // per cell: the map's free cells
  std::vector<bool> blocked_;  // per cell: a fixed robot stands there
  std::unordered_map<int, Table> tables_;  // goal cell -> its search
  std::size_t table_cells_ = 0;
  std::vector<double> priority_;  // per agent, kept across windows
  std::vector<double> base_;      // per agent: its priority when it has nothing to wait for
  // One step's state: each agent's cell, goal cell (-1: none), next cell (-1: undecided), and who
  // stands on / has taken each cell.
  std::vector<int> now_, goal_, next_;
  std::vector<int> on_now_, on_next_;
  std::uint64_t tie_ = 0;  // the tie-breaking stream's state
  std::vector<int> waiting_;  // per agent, kept across windows
  std::uint64_t steps_planned_ = 0;
  int longest_wait_ = 0;
  // Stalls: per agent the goal cell it is measured against, the nearest it has come to it, and the
  // steps since it last came nearer; and a rescue plan being driven (per agent its cells, empty:
  // none) with the step of it the agents stand at.
  std::vector<int> stall_goal_, nearest_, stalled_;
  int no_progress_ = 0;  // steps in a row in which no robot came nearer its goal than it ever was
  std::vector<std::vector<int>> rescue_;  // per agent: its cells in the rescue (empty: not in it)
  std::vector<bool> region_;              // per cell: the rescue's region, which only its robots enter
  std::size_t rescue_step_ = 0;
  std::size_t rescue_until_ = 0;  // the step at which the rescue hands back to PIBT
  int failed_in_a_row_ = 0;       // rescues that found no plan since the last that did
  std::uint64_t rescues_ = 0;
  std::uint64_t rescues_failed_ = 0;
};

}  // namespace swarm::planner::traffic
