// DARP division and STC coverage paths on the instances of data/darp, side by side with the
// reference Python implementation's figures on exactly those instances and starts (data/README.md:
// github.com/alice-st/DARP, one thread, 2-core 2.3 GHz Xeon).
// Run: swarm bench darp [--benchmark_filter=terminal]   (data: $SWARM_BENCHMARKS_DIR/darp)
//
// Counters per benchmark:
//   iterations, converged      ours (deterministic per seed, the same every repetition)
//   ref_iterations, ref_s      the reference's (0 = it did not converge; its s is the failed search)
//   cpu_s                      our thread CPU seconds per run
//   x_faster                   ref_s / cpu_s: the goal is >= 20 on the same starts (Division/euclidean/given
//                              is the reference's own method; the other variants are ours)
//   Paths: cells, moves, turns, repeats of our STC on the map's cells; turns_2x: the same regions
//   covered on the reference's 2 x 2 sub-cell grid (each cell a whole block, as the reference
//   plans), against ref_turns (its best mode, on its own division).
#include <benchmark/benchmark.h>

#include <time.h>

#include <fstream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "swarm/planner/coverage/coverage_plan.hpp"
#include "swarm/planner/coverage/darp.hpp"
#include "swarm/planner/grid/map_io.hpp"
#include "swarm/planner/coverage/stc.hpp"
#include "swarm_test/data.hpp"

namespace {

using namespace swarm::planner;

struct Reference {
  bool converged;
  int iterations;  // the failed searches: all stages
  double division_s;
  double paths_s;  // 0 = not run
  int turns;       // sum over robots, best mode; 0 = not run
};

// data/README.md, "darp/".
const std::map<std::string, Reference> kReference = {
    {"empty-50-4", {true, 51, 0.073, 0.82, 108 + 100 + 110 + 106}},
    {"empty-100-4", {true, 84, 0.21, 3.9, 214 + 200 + 226 + 212}},
    {"empty-100-8", {true, 225, 0.82, 4.7, 114 + 136 + 188 + 140 + 112 + 136 + 148 + 136}},
    {"empty-200-8", {true, 507, 4.5, 22.0, 232 + 294 + 402 + 284 + 220 + 268 + 296 + 276}},
    {"rooms-64-8", {true, 341, 0.62, 1.6, 160 + 160 + 194 + 184 + 166 + 192 + 152 + 162}},
    {"bunched-100-8", {false, 140003, 505, 0, 0}},
    {"terminal-6", {false, 120002, 452, 0, 0}},
    {"terminal-8", {false, 120002, 486, 0, 0}},
};

struct Instance {
  OccupancyGrid map;
  std::vector<Cell> robots;
};

Instance load(const std::string& name) {
  const std::string dir = swarm::test::benchmarks_dir() + "/darp/";
  Instance in;
  in.map = load_movingai_map(dir + name + ".map");
  std::ifstream robots(dir + name + ".robots");
  int x = 0, y = 0;
  while (robots >> x >> y) in.robots.push_back(from_movingai_xy(in.map, x, y));
  if (in.robots.empty()) throw std::runtime_error("no robots in " + dir + name + ".robots");
  return in;
}

double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

void set_reference(benchmark::State& state, double ref_s, double cpu_s) {
  state.counters["cpu_s"] = cpu_s;
  state.counters["ref_s"] = ref_s;
  state.counters["x_faster"] = ref_s > 0 && cpu_s > 0 ? ref_s / cpu_s : 0;
}

// The instance, or nullopt after telling Google Benchmark why it is skipped.
std::optional<Instance> load_or_skip(benchmark::State& state, const std::string& name) {
  try {
    return load(name);
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return std::nullopt;
  }
}

void BM_Division(benchmark::State& state, const std::string& name, DivisionMethod method, DarpDistance distance,
                 DarpInit init) {
  const std::optional<Instance> loaded = load_or_skip(state, name);
  if (!loaded) return;
  const Instance& in = *loaded;
  DarpRequest req;
  req.robots = in.robots;
  DarpConfig cfg;
  cfg.method = method;
  cfg.distance = distance;
  cfg.init = init;
  DarpResult r;
  double cpu = 0;
  for (auto _ : state) {
    const double t0 = thread_seconds();
    r = divide_areas(in.map, req, cfg);
    cpu += thread_seconds() - t0;
    benchmark::DoNotOptimize(r.assignment.data());
  }
  const Reference& ref = kReference.at(name);
  state.counters["iterations"] = r.iterations;
  state.counters["converged"] = r.status == DarpStatus::Converged;
  state.counters["repaired_cells"] = r.repair_moves;
  state.counters["ref_iterations"] = ref.iterations;
  state.counters["ref_converged"] = ref.converged;
  set_reference(state, ref.division_s, cpu / static_cast<double>(state.iterations()));
}

// Every cell of `map` as a whole 2 x 2 block of sub-cells (the reference's path geometry).
OccupancyGrid doubled(const OccupancyGrid& region) {
  OccupancyGrid out(region.width() * 2, region.height() * 2, region.resolution() / 2, region.origin_x(),
                    region.origin_y(), CellState::Occupied);
  for (int y = 0; y < out.height(); ++y) {
    for (int x = 0; x < out.width(); ++x) out.set({x, y}, region.at(Cell{x / 2, y / 2}));
  }
  return out;
}

void BM_Paths(benchmark::State& state, const std::string& name) {
  const std::optional<Instance> loaded = load_or_skip(state, name);
  if (!loaded) return;
  const Instance& in = *loaded;
  DarpRequest req;
  req.robots = in.robots;
  DarpConfig darp_alone;
  darp_alone.method = DivisionMethod::Darp;
  const DarpResult division = divide_areas(in.map, req, darp_alone);  // the Division/darp/euclidean/given result
  std::vector<CoveragePlan> plans;
  double cpu = 0;
  for (auto _ : state) {
    const double t0 = thread_seconds();
    plans = plan_coverage(in.map, division, in.robots);
    cpu += thread_seconds() - t0;
    benchmark::DoNotOptimize(plans.data());
  }
  double moves = 0, turns = 0, repeats = 0, turns_2x = 0;
  for (std::size_t r = 0; r < plans.size(); ++r) {
    moves += plans[r].coverage.length;
    turns += plans[r].coverage.turns;
    repeats += plans[r].coverage.revisits;
    const OccupancyGrid fine = doubled(region_of(in.map, division.assignment, static_cast<int>(r)));
    const Cell s = in.robots[r];
    turns_2x += spanning_tree_coverage(fine, {2 * s.x, 2 * s.y}).turns;
  }
  const Reference& ref = kReference.at(name);
  state.counters["converged"] = division.status == DarpStatus::Converged;
  state.counters["moves"] = moves;
  state.counters["turns"] = turns;
  state.counters["repeats"] = repeats;
  state.counters["turns_2x"] = turns_2x;
  state.counters["ref_turns"] = ref.turns;
  set_reference(state, ref.paths_s, cpu / static_cast<double>(state.iterations()));
}

void register_all() {
  for (const auto& [name, ref] : kReference) {
    // The failed searches run up to 10,000 iterations: once is enough.
    const int runs = ref.converged ? 0 : 1;
    auto division = [&](DivisionMethod m, DarpDistance d, DarpInit i) {
      const std::string label = std::string(to_string(m)) + "/" + to_string(d) + "/" + to_string(i);
      auto* b = benchmark::RegisterBenchmark(("Division/" + name + "/" + label).c_str(), BM_Division, name, m, d, i)
                    ->Unit(benchmark::kMillisecond);
      if (runs > 0 && m == DivisionMethod::Darp) b->Iterations(runs);
    };
    // DARP alone, as the reference (and the paper's BFS + K-Means); then the default, auto.
    division(DivisionMethod::Darp, DarpDistance::Euclidean, DarpInit::Given);
    division(DivisionMethod::Darp, DarpDistance::Geodesic, DarpInit::Given);
    division(DivisionMethod::Darp, DarpDistance::Geodesic, DarpInit::BfsKMeans);
    division(DivisionMethod::Auto, DarpDistance::Euclidean, DarpInit::Given);
    division(DivisionMethod::Auto, DarpDistance::Geodesic, DarpInit::Given);
    auto* p = benchmark::RegisterBenchmark(("Paths/" + name).c_str(), BM_Paths, name)->Unit(benchmark::kMillisecond);
    if (runs > 0) p->Iterations(1);
  }
}

}  // namespace

int main(int argc, char** argv) {
  register_all();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
