// The paper's genetic algorithm with the direction-ordering chromosome — its options.
//
// Park & Hwang, "Multi-robot Path Planning Based on Two-stage Genetic Algorithm Using Direction
// Ordering Chromosome", 2025 (docs/papers.md section 3; seeds/002_3978f293b65c7987.txt). On the
// warehouse world only (warehouse.hpp: intersections joined by 2-step passages, the paper's rules;
// anything else, a graph instance included, is Status::Unsupported).
//   - Chromosome, per robot: a DIRECTION part, a permutation of the moves of a shortest path
//     between its start and goal intersections (a columns and b rows apart: a + b genes, 1 up,
//     2 down, 3 right, 4 left; every order is a shortest path, so no detours), and an IDLE part of
//     a + b + 1 genes: gene 1 = stops before departure, gene i >= 2 = stops in the middle of move
//     i - 1; one stop = 2 time steps.
//   - Crossover: per robot, a random choice of the parent that gives its direction part and
//     (independently) the one that gives its idle part; the second child takes the other choices.
//   - Mutation (a chromosome chosen with the mutation probability): for every robot, two random
//     genes of its direction part swap, and one random idle gene gains or loses 1 (never below 0).
//   - Roulette-wheel selection on weights 1 / (1 + F).
//   - Fitness F: collisions (equation 4) in stage 1, α·collisions + β·idle time steps (equation
//     3) in stage 2. Collisions: one per pair of robots on one place (intersection or passage
//     middle) at one time step, or swapping places within a step; a robot leaves the check on
//     arrival. The two-stage GA runs stage 1 for `stage1_generations` from a random population,
//     then stage 2 for `stage2_generations` from stage 1's population; the single-stage GA runs
//     the stage-2 fitness for both counts together.
// What the paper does not give (our choices, all fields below): population size, crossover and
// mutation probabilities, elitism, the weights of the roulette, the range of the initial idle
// genes. The result is the best chromosome of the last generation by the final fitness; it may
// keep collisions (Status::Failed, conflicts > 0): the paper's GA does not guarantee none.
//
// Run it through solve() (solver.hpp) on a warehouse instance:
//   SolverConfig c;  c.kind = SolverKind::Ga;  c.ga.population = 200;  c.ga.seed = 7;
//   const Result r = solve(random_warehouse_instance(5, 8, 20, 1), c, StopCondition::after(60.0));
#pragma once

#include <cstdint>

namespace swarm::planner::mapf {

struct GaConfig {
  int population = 100;            // chromosomes per generation (paper: not given)
  int stage1_generations = 500;    // paper: 500
  int stage2_generations = 500;    // paper: 500
  double alpha = 1.0;              // weight of collisions in stage 2 (paper: 1)
  double beta = 0.02;              // weight of idle time steps in stage 2 (paper: 0.02)
  double crossover_rate = 0.9;     // probability that a selected pair is crossed (else copied)
  double mutation_rate = 0.2;      // probability that a child is mutated
  int elite = 1;                   // best chromosomes copied unchanged into the next generation
  int max_initial_idle = 1;        // initial idle genes are uniform in [0, max_initial_idle]
  bool stop_when_perfect = false;  // end early once a plan has 0 collisions and 0 stops
  std::uint64_t seed = 0;
};

}  // namespace swarm::planner::mapf
