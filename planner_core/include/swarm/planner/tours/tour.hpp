// Collection tours: pick up objects of several types and carry each type to its own destination.
//
// Kim & Lee, "A New Heuristic Approach for Generating Efficient Paths for Cleaning and Recycling
// Tasks", 2025 (seeds/001_645b6156304cdc3a.txt; digest docs/papers.md section 4).
//
// The type-by-type method: from where the robot is, the nearest remaining object (Euclidean,
// ties: the lower object number) fixes the type; the robot collects every object of that type,
// in an order from the GA (tour_order.hpp), then carries them to the type's destination; from
// there the next type is chosen the same way. While a type is collected, the remaining objects of
// the other types are obstacles (collected ones are gone; a cell that also holds an object of the
// current type, the robot or the destination stays open). Every leg is an A* path, 8-connected,
// never cutting a corner (astar.hpp, motion.hpp); if a leg has no path with those obstacles it is
// planned through them and marked `through_objects` (it never fails for an object reachable on
// the map itself).
//
// Variants (the paper's three columns):
//   kNna            the baseline: each type's first waypoint is the nearest object (the one that
//                   fixed the type); the GA orders the rest on distance only.
//   kDistance       the GA orders all of a type's objects on distance only.
//   kDistanceAngle  the GA orders them on distance, then rotation (lexicographic, exact ties).
// Length is in cells (1 per straight step, sqrt 2 per diagonal); rotation R = sum |delta theta|
// over the cell path, in eighths of a turn (turns.hpp) and radians. The robot starts facing
// `start_heading` (the paper: up) and faces `heading_after_drop` (the paper: left) after each
// destination; that turn to face left is not counted (the paper resets the heading there).
// The type order does not depend on the variant: after each type the robot stands on the same
// destination whatever the order inside the type was.
//
//   TourProblem p;
//   p.start = {6, 1};
//   p.destinations = {{11, 11}, {10, 11}};              // type 0, type 1
//   p.objects = {{{10, 2}, 0}, {{3, 7}, 1}, {{5, 5}, 0}};
//   TourOptions options;                                 // the paper's GA, distance + angle
//   options.seed = 7;
//   TourPlan plan = plan_tour(map, p, options);
//   for (const TourLeg& leg : plan.legs) drive(leg.cells);   // then pick up / drop at leg.stop
//
// Legs use Free cells only (pass a map whose Unknown cells are set Free to plan optimistically). A
// start on a blocked cell is planned from as if it were free: the robot stands there
// (check_tour_problem still reports it).
// Deterministic per seed (each type's GA draws from Rng(mix_seed(seed, run index))).
// Interruptible: `stop` is polled once per GA generation; once it is true the current type keeps
// its best order so far and the later types take the greedy nearest-neighbour order, so the plan
// is still a whole tour (status kStopped). Thread-safe (no shared state).
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "swarm/planner/grid/grid.hpp"
#include "swarm/planner/tours/tour_order.hpp"
#include "swarm/planner/tours/turns.hpp"

namespace swarm::planner {

struct TourObject {
  Cell cell;
  int type = 0;  // index into TourProblem::destinations
};

struct TourProblem {
  Cell start;
  int start_heading = kHeadingUp;
  int heading_after_drop = kHeadingLeft;
  std::vector<TourObject> objects;
  std::vector<Cell> destinations;  // destinations[t] = where type t is dropped
};

enum class TourVariant { kNna, kDistance, kDistanceAngle };

// "nna" | "distance" | "distance-angle".
[[nodiscard]] const char* variant_name(TourVariant v);
[[nodiscard]] std::optional<TourVariant> parse_variant(const std::string& name);

struct TourOptions {
  TourVariant variant = TourVariant::kDistanceAngle;
  OrderGaConfig ga;
  std::uint64_t seed = 1;
  bool other_types_block = true;   // the paper's rule; false = objects never block
  // How each type's order is searched. kGa is the paper. The paper's GA converges early (its
  // top-10 parents fill with copies of one order and it becomes a hill-climber), so alone it
  // misses the best order of 8 objects about 1 time in 6, and then a distance variant can come
  // out longer than the NNA method. The other two are not in the paper:
  //   kGaPolished  the GA's order improved by 2-opt + Or-opt local search (polish_order)
  //   kExact       the best order (reference_order under the variant's objective): exact up to
  //                kExactMaxFreeObjects objects of a type, beyond that a local search
  // With kExact the distance variants are never longer than the NNA method (each run starts
  // from the same place facing the same way, and the NNA order is one they could choose).
  enum class Search { kGa, kGaPolished, kExact };
  Search search = Search::kGa;
  bool compute_reference = false;  // also find each run's best order (tour_order.hpp reference)
};

// "ga" | "ga-polished" | "exact".
[[nodiscard]] const char* search_name(TourOptions::Search s);
[[nodiscard]] std::optional<TourOptions::Search> parse_search(const std::string& name);

// What is wrong with a problem, one entry per fault. Objects and destinations are numbered from 0
// in the order given.
struct TourIssue {
  enum Kind {
    kStartOutside,
    kStartBlocked,            // the start cell is not Free
    kObjectOutside,
    kObjectBlocked,
    kObjectNoDestination,     // its type has no destination
    kObjectUnreachable,       // no 8-connected path from the start on the map
    kDestinationOutside,
    kDestinationBlocked,
    kDestinationUnreachable,
  };
  Kind kind;
  int index = -1;  // the object or destination; -1 for the start
};

// Every fault of `problem` on `map` (empty: the plan will hold every object).
[[nodiscard]] std::vector<TourIssue> check_tour_problem(const OccupancyGrid& map,
                                                        const TourProblem& problem);
[[nodiscard]] std::string describe(const TourIssue& issue);

// Where a leg ends and what happens there.
struct TourStop {
  enum Kind { kPickUp, kDrop };
  Kind kind = kPickUp;
  int object = -1;  // kPickUp: the object picked up
  int type = 0;     // the type being collected (kDrop: the type dropped)
  Cell cell;
};

struct TourLeg {
  std::vector<Cell> cells;  // 8-connected; front = the previous stop's cell (or the start)
  TourStop stop;
  GridLength length;
  int rotation = 0;              // eighths, the turn onto its first step included
  bool through_objects = false;  // it crosses other types' objects (no path around them)
};

// One type's run: from the start or the previous destination to this type's destination.
struct TourRun {
  int type = 0;
  std::vector<int> order;  // objects in pick-up order
  GridLength length;
  int rotation = 0;  // eighths, from the run's initial heading
  int generations = 0;
  std::optional<OrderSearch> reference;  // with compute_reference: the best order found for the
                                         // same constraint (kNna: same first waypoint), its
                                         // order in object numbers like `order`
};

enum class TourStatus {
  kComplete,  // every object of the problem is in the tour
  kStopped,   // the stop predicate cut a GA short; the tour is whole but maybe not as good
  kPartial,   // some objects could not be collected (see skipped; check_tour_problem says why)
};

struct TourPlan {
  TourStatus status = TourStatus::kComplete;
  std::vector<TourLeg> legs;
  std::vector<TourRun> runs;
  std::vector<int> skipped;  // objects left out, ascending
  GridLength length;
  int rotation = 0;  // eighths

  [[nodiscard]] double length_cells() const { return length.cells(); }
  [[nodiscard]] double rotation_rad() const { return eighths_to_rad(rotation); }
  // The whole path: the legs' cells, each junction once.
  [[nodiscard]] std::vector<Cell> cells() const;
};

// Where a robot that stops for good (lost) leaves what it carries: the nearest free cell beside it
// (breadth first over 8-neighbours, in a fixed order) that no robot stands on, so that another
// robot can stand there to pick it up; `at` itself when there is none. The simulator and the
// leader both use it, so they agree.
[[nodiscard]] Cell put_down_cell(const OccupancyGrid& map, Cell at, const std::vector<Cell>& robots);

[[nodiscard]] TourPlan plan_tour(const OccupancyGrid& map, const TourProblem& problem,
                                 const TourOptions& options = {},
                                 const std::function<bool()>& stop = {});

// An independent check of a plan (for tests and the live task): legs join up from the start,
// every step is a legal 8-connected move on `map` (motion.hpp; the start cell counts as free), a leg not marked through_objects
// never enters a cell of another type's object still waiting, types are collected one at a time
// in the nearest-object order and dropped at their own destination, every object not skipped is
// picked up exactly once, and the lengths and rotations add up. Returns "" when all holds, else
// the first fault found.
[[nodiscard]] std::string check_tour(const OccupancyGrid& map, const TourProblem& problem,
                                     const TourPlan& plan);

}  // namespace swarm::planner
