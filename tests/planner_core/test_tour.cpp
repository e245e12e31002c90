#include "swarm/planner/tours/tour.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "swarm_test/ascii_grid.hpp"

namespace swarm::planner {
namespace {

using swarm::test::ascii_map;

// Like the paper's scenario 1: a 12 x 12 room, `per_type` objects of each of `types` types scattered
// by seed, destinations in the top right corner, start near the bottom middle.
TourProblem scattered(const OccupancyGrid& map, int types, int per_type, std::uint64_t seed) {
  TourProblem p;
  p.start = {6, 1};
  for (int t = 0; t < types; ++t) p.destinations.push_back({map.width() - 1 - t, map.height() - 1});
  Rng rng(seed);
  while (static_cast<int>(p.objects.size()) < types * per_type) {
    const Cell c{rng.uniform_int(0, map.width() - 1), rng.uniform_int(0, map.height() - 3)};
    const bool taken = c == p.start || std::any_of(p.objects.begin(), p.objects.end(),
                                                    [&](const TourObject& o) { return o.cell == c; });
    if (map.is_free(c) && !taken) p.objects.push_back({c, static_cast<int>(p.objects.size()) % types});
  }
  return p;
}

TourOptions options(TourVariant variant, std::uint64_t seed = 1, bool reference = false) {
  TourOptions o;
  o.variant = variant;
  o.seed = seed;
  o.compute_reference = reference;
  return o;
}

const OccupancyGrid kRoom(12, 12, 0.1, 0, 0, CellState::Free);

const OccupancyGrid& cluttered_room() {
  static const OccupancyGrid g = swarm::test::grid_from({
      "............",
      "............",
      "..###.......",
      "..###...##..",
      "........##..",
      "............",
      ".....####...",
      "............",
      ".##.........",
      ".##.....#...",
      "........#...",
      "............",
  });
  return g;
}

TEST(TourProblem, NamesEveryFault) {
  const auto art = ascii_map({
      "S....#.",
      "....#..",
      "###.#.U",  // U: enclosed, unreachable
      "...B#..",
  });
  TourProblem p;
  p.start = art.at.at('S');
  p.destinations = {{0, 0}, {4, 0}, {9, 9}};  // free, wall, outside
  p.objects = {{{1, 3}, 0}, {{20, 1}, 0}, {{0, 1}, 1}, {art.at.at('U'), 0}, {{2, 3}, 3}, {art.at.at('B'), 0}};
  const std::vector<TourIssue> issues = check_tour_problem(art.grid, p);
  std::vector<std::string> text;
  for (const TourIssue& i : issues) text.push_back(describe(i));
  EXPECT_EQ(text, (std::vector<std::string>{
                      "destination 1 is on a blocked cell",
                      "destination 2 is outside the map",
                      "object 1 is outside the map",
                      "object 2 is on a blocked cell",
                      "object 3 cannot be reached from the start",
                      "object 4's type has no destination",
                  }));
  const TourPlan plan = plan_tour(art.grid, p);
  EXPECT_EQ(plan.status, TourStatus::kPartial);
  EXPECT_EQ(plan.skipped, (std::vector<int>{1, 2, 3, 4}));
  EXPECT_EQ(check_tour(art.grid, p, plan), "");
  ASSERT_EQ(plan.runs.size(), 1u);
  EXPECT_EQ(plan.runs[0].order, (std::vector<int>{0, 5}));
}

TEST(Tour, TheNearestObjectFixesTheTypeAndEveryLegIsLegal) {
  TourProblem p = scattered(cluttered_room(), 3, 6, 11);
  for (TourVariant v : {TourVariant::kNna, TourVariant::kDistance, TourVariant::kDistanceAngle}) {
    const TourPlan plan = plan_tour(cluttered_room(), p, options(v, 3));
    EXPECT_EQ(plan.status, TourStatus::kComplete);
    EXPECT_EQ(check_tour(cluttered_room(), p, plan), "") << variant_name(v);
    ASSERT_EQ(plan.runs.size(), 3u);
    EXPECT_EQ(plan.legs.size(), 18u + 3u);
    // Every A* leg keeps off the obstacles (the validator checks every move; this says it again).
    for (const TourLeg& leg : plan.legs) {
      for (const Cell c : leg.cells) EXPECT_TRUE(cluttered_room().is_free(c));
    }
  }
}

// The start (S) is nearest a type-1 object; the type-0 objects are farther.
TEST(Tour, TypesGoInNearestObjectOrderAndNnaFixesTheFirstWaypoint) {
  const OccupancyGrid open(10, 5, 0.1, 0, 0, CellState::Free);
  TourProblem p;
  p.start = {3, 0};
  p.destinations = {{9, 4}, {9, 0}};
  p.objects = {{{0, 4}, 0}, {{4, 2}, 1}, {{6, 1}, 0}, {{5, 0}, 1}};
  const TourPlan plan = plan_tour(open, p, options(TourVariant::kNna));
  ASSERT_EQ(plan.runs.size(), 2u);
  EXPECT_EQ(plan.runs[0].type, 1);
  EXPECT_EQ(plan.runs[0].order.front(), 3);  // (5, 0), two cells from S; (4, 2) is sqrt 5 away
  EXPECT_EQ(plan.runs[1].type, 0);
  EXPECT_EQ(check_tour(open, p, plan), "");
  // The robot starts facing up and, after the drop at (9, 0), faces left.
  EXPECT_EQ(plan.legs.front().rotation, rotation_eighths(plan.legs.front().cells, kHeadingUp));
  const TourLeg& after_drop = plan.legs[3];
  EXPECT_EQ(after_drop.rotation, rotation_eighths(after_drop.cells, kHeadingLeft));
}

// While type 0 is collected the type-1 object X blocks the direct way; where it is the only way,
// the leg goes through it and says so.
TEST(Tour, OtherTypesAreObstaclesUntilThereIsNoOtherWay) {
  const auto around = ascii_map({
      "..#..",
      "S.X.a",
      "..#..",
  });
  TourProblem p;
  p.start = around.at.at('S');
  p.destinations = {{4, 0}, {0, 0}};
  p.objects = {{around.at.at('a'), 0}, {around.at.at('X'), 1}, {{1, 0}, 1}};
  TourPlan plan = plan_tour(around.grid, p);
  EXPECT_EQ(check_tour(around.grid, p, plan), "");
  // Type 1 at (1, 0) is nearest: collected first, X too; then type 0 can go straight.
  EXPECT_EQ(plan.runs[0].type, 1);

  p.objects = {{around.at.at('a'), 0}, {around.at.at('X'), 1}};
  p.start = {1, 1};
  p.destinations = {{4, 1}, {0, 0}};
  plan = plan_tour(around.grid, p);
  ASSERT_EQ(plan.runs.size(), 2u);
  EXPECT_EQ(plan.runs[0].type, 1);  // X is one cell away
  EXPECT_FALSE(plan.legs[0].through_objects);
  EXPECT_EQ(check_tour(around.grid, p, plan), "");

  // Now the type-0 object is nearer: X sits in the only gap, so the leg must cross it.
  p.objects = {{{3, 1}, 0}, {around.at.at('X'), 1}};
  p.start = {0, 1};
  p.destinations = {{4, 1}, {0, 0}};
  plan = plan_tour(around.grid, p);
  EXPECT_EQ(plan.runs[0].type, 1);  // X at distance 2, the other at 3
  p.objects = {{{3, 1}, 0}, {around.at.at('X'), 1}, {{0, 2}, 0}};
  plan = plan_tour(around.grid, p);
  ASSERT_EQ(plan.runs[0].type, 0);  // (0, 2) is one cell away
  EXPECT_TRUE(std::any_of(plan.legs.begin(), plan.legs.end(),
                          [](const TourLeg& l) { return l.through_objects; }));
  EXPECT_EQ(check_tour(around.grid, p, plan), "");
}

// With the best order per type (Search::kExact) the distance variants are never longer than the
// NNA method: every run starts from the same cell with the same heading whatever the variant, and
// the NNA order is one they could choose; among equal lengths the angle variant turns least.
TEST(Tour, TheDistanceVariantsAreNeverLongerThanTheNnaMethodOnSeededInstances) {
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    const TourProblem p = scattered(cluttered_room(), 3, 6, 100 + seed);
    TourOptions o = options(TourVariant::kNna, seed);
    o.search = TourOptions::Search::kExact;
    const TourPlan nna = plan_tour(cluttered_room(), p, o);
    o.variant = TourVariant::kDistance;
    const TourPlan dist = plan_tour(cluttered_room(), p, o);
    o.variant = TourVariant::kDistanceAngle;
    const TourPlan angle = plan_tour(cluttered_room(), p, o);
    EXPECT_LE(dist.length, nna.length) << "seed " << seed;
    EXPECT_EQ(angle.length, dist.length) << "seed " << seed;
    EXPECT_LE(angle.rotation, dist.rotation) << "seed " << seed;
    for (const TourPlan* plan : {&nna, &dist, &angle}) EXPECT_EQ(check_tour(cluttered_room(), p, *plan), "");
  }
}

// The paper's GA is never better than the best order, and on seeded instance 102 (below) it is
// what the experiment finds one time in four: the distance variant comes out LONGER than the NNA
// method, because the GA settled on a worse order of one type (its gap to the best order is
// known from compute_reference). Polishing the GA's orders closes the gap here.
TEST(Tour, ThePapersGaCanBeLongerThanTheNnaMethodAndItsGapIsKnown) {
  const TourProblem p = scattered(cluttered_room(), 3, 6, 102);
  const TourPlan nna = plan_tour(cluttered_room(), p, options(TourVariant::kNna, 2, true));
  const TourPlan dist = plan_tour(cluttered_room(), p, options(TourVariant::kDistance, 2, true));
  EXPECT_GT(dist.length, nna.length);
  bool gap = false;
  for (const TourPlan* plan : {&nna, &dist}) {
    for (const TourRun& run : plan->runs) {
      ASSERT_TRUE(run.reference);
      EXPECT_LE(run.reference->cost.length, run.length);
      gap |= run.reference->cost.length < run.length;
    }
  }
  EXPECT_TRUE(gap);
  TourOptions polished = options(TourVariant::kDistance, 2);
  polished.search = TourOptions::Search::kGaPolished;
  EXPECT_LE(plan_tour(cluttered_room(), p, polished).length, nna.length);
}

TEST(Tour, ReferenceIsNoWorseThanTheGa) {
  const TourProblem p = scattered(kRoom, 3, 8, 7);
  const TourPlan plan = plan_tour(kRoom, p, options(TourVariant::kNna, 1, true));
  for (const TourRun& run : plan.runs) {
    ASSERT_TRUE(run.reference);
    EXPECT_TRUE(run.reference->exact);
    EXPECT_LE(run.reference->cost.length, run.length);
    EXPECT_EQ(run.reference->order.front(), run.order.front());  // NNA: the same first waypoint
  }
}

// A robot whose map calls its own cell blocked still gets a whole tour (it can leave the cell).
TEST(Tour, AStartOnABlockedCellIsPlannedFromAnyway) {
  OccupancyGrid map = cluttered_room();
  TourProblem p = scattered(map, 2, 3, 8);
  map.set(p.start, CellState::Occupied);
  ASSERT_EQ(check_tour_problem(map, p).front().kind, TourIssue::kStartBlocked);
  const TourPlan plan = plan_tour(map, p);
  EXPECT_EQ(plan.status, TourStatus::kComplete);
  EXPECT_EQ(plan.runs.size(), 2u);
  EXPECT_EQ(check_tour(map, p, plan), "");
}

TEST(Tour, SameSeedSamePlan) {
  const TourProblem p = scattered(cluttered_room(), 3, 6, 5);
  const TourPlan a = plan_tour(cluttered_room(), p, options(TourVariant::kDistanceAngle, 9));
  const TourPlan b = plan_tour(cluttered_room(), p, options(TourVariant::kDistanceAngle, 9));
  EXPECT_EQ(a.cells(), b.cells());
  EXPECT_EQ(a.length, b.length);
  EXPECT_EQ(a.rotation, b.rotation);
}

TEST(Tour, StoppedEarlyStillGivesAWholeValidTour) {
  const TourProblem p = scattered(kRoom, 3, 8, 2);
  const TourPlan plan = plan_tour(kRoom, p, {}, [] { return true; });
  EXPECT_EQ(plan.status, TourStatus::kStopped);
  EXPECT_EQ(plan.runs.size(), 3u);
  EXPECT_EQ(plan.runs[0].generations, 1);
  EXPECT_EQ(plan.runs[1].generations, 0);  // greedy order
  EXPECT_EQ(check_tour(kRoom, p, plan), "");
}

TEST(Tour, TheValidatorCatchesABrokenPlan) {
  const TourProblem p = scattered(kRoom, 2, 3, 4);
  const TourPlan good = plan_tour(kRoom, p);
  ASSERT_EQ(check_tour(kRoom, p, good), "");
  TourPlan jump = good;
  jump.legs[1].cells.insert(jump.legs[1].cells.begin() + 1, Cell{0, 11});
  EXPECT_NE(check_tour(kRoom, p, jump), "");
  TourPlan missing = good;
  missing.legs.erase(missing.legs.begin());
  EXPECT_NE(check_tour(kRoom, p, missing), "");
  TourPlan wrong_total = good;
  wrong_total.rotation += 1;
  EXPECT_NE(check_tour(kRoom, p, wrong_total), "");
}

}  // namespace
}  // namespace swarm::planner
