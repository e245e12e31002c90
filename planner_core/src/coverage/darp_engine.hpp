// DARP's iteration on a compact region (internal to planner_core; the public API is darp.hpp).
//
// DarpSpace is the region as DARP sees it: the cells some robot can reach, the piece (connected
// component) each belongs to, and per robot its piece and share. DarpEngine holds the evaluation
// matrices (as logarithms, see darp.hpp "Overflow") for one set of start cells and iterates.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "swarm/planner/coverage/darp.hpp"
#include "swarm/planner/coverage/region_graph.hpp"
#include "swarm/planner/grid/rng.hpp"

namespace swarm::planner::detail {

struct DarpSpace {
  RegionGraph graph;               // reachable region cells only
  std::vector<int> piece;          // per cell: its connected piece (pieces hold >= 1 robot)
  int pieces = 0;
  std::vector<int> robot_piece;    // per robot
  std::vector<double> shares;      // per robot: s_r
  std::vector<double> weights;     // per robot (all 1 for equal portions)
  int robots() const { return static_cast<int>(robot_piece.size()); }
};

// The quality of a division; lower is better: fewer split regions, then a smaller deviation.
struct DivisionScore {
  int split = 0;
  double max_deviation = 0;
  bool better_than(const DivisionScore& o) const {
    return split != o.split ? split < o.split : max_deviation < o.max_deviation;
  }
};

class DarpEngine {
 public:
  // log E. float halves the memory the two hot loops stream; update() keeps the values of every
  // cell near 0 (see there), so 24 bits of mantissa resolve the 1e-4 random factor with room.
  using Metric = float;

  // Builds the initial metrics from `starts` (compact indices, distinct) and makes the first
  // division.
  DarpEngine(const DarpSpace& space, std::vector<int> starts, const DarpConfig& config,
             std::uint64_t stream);

  const std::vector<int>& owner() const { return owner_; }
  const std::vector<int>& counts() const { return counts_; }
  const std::vector<int>& starts() const { return starts_; }
  DivisionScore score() const { return score_; }
  bool goal() const { return score_.split == 0 && score_.max_deviation <= config_.tolerance_cells; }
  int updates() const { return updates_; }

  // Iterates until the goal (Converged), `budget` updates in total (Failed) or should_stop()
  // (Stopped). `best` / `best_score` receive the best division seen (they may already hold one).
  DarpStatus run(int budget, const std::function<bool()>& should_stop, std::vector<int>& best,
                 DivisionScore& best_score);

 private:
  // A robot's distances to one of its sets of cells (the piece holding its start, or its other
  // pieces), kept from the last time the robot was split: from one iteration to the next these
  // sets are often the same or have only gained a few cells, and then the distances are reused or
  // lowered to the new cells instead of transformed again (exactly the same values either way).
  struct DistanceField {
    std::vector<std::uint8_t> source;  // per cell: in the set
    std::vector<double> distance;      // per cell: distance to the set
    double max = 0;                    // the largest distance in the robot's piece
    bool valid = false;
  };

  void assign();  // the first division (the constructor); later ones are made by update()
  // The common tail of assign() and update(): starts pinned, cells that changed hands, counts
  // (counted afresh when `first`, else corrected by the cells that changed hands).
  void finish_assignment(bool first);
  void evaluate();
  bool still_connected();
  // The metric update followed by the assignment of every cell to its cheapest robot (the two
  // are one pass over each robot's metric).
  void update();
  // The connectivity correction of split robot r (one value per cell) into `correction`.
  void connectivity_correction(int r, std::vector<Metric>& correction);
  // `field` brought up to date for `source`, its max taken over `piece` (see DistanceField).
  const DistanceField& distances_to(DistanceField& field, const std::vector<std::uint8_t>& source, int piece);
  double max_in_piece(const std::vector<double>& d, int piece) const;
  // out[i] = the smallest squared Euclidean distance from cell i to one of `cells` (exact integers).
  void squared_distances_to(const std::vector<int>& cells, std::vector<double>& out) const;
  void distances_from(const std::vector<std::uint8_t>& source, std::vector<double>& out);

  const DarpSpace& space_;
  DarpConfig config_;
  Rng rng_;
  int n_ = 0;
  int m_ = 0;
  std::vector<int> starts_;
  std::vector<Metric> log_metric_;  // n_ x m_, robot-major
  std::vector<Metric> best_value_;  // per cell: its smallest value (assign())
  std::vector<Metric> best_next_;   // scratch of update(): the next best_value_
  std::vector<std::int32_t> owner_;
  std::vector<std::int32_t> previous_owner_;  // the division evaluate() saw before this one
  std::vector<int> changed_, gained_by_;      // cells whose owner changed, and their new owners
  bool connected_before_ = false;             // every region of previous_owner_ was connected
  std::vector<int> counts_;
  std::vector<std::uint8_t> split_;  // per robot
  std::vector<std::uint16_t> noise_bits_;  // scratch of update(): one 16-bit draw per cell
  std::vector<double> log_m_;              // scratch of update(): log m_r per robot
  std::vector<Metric> correction_;
  std::vector<DistanceField> own_field_, stray_field_;  // per robot (connectivity_correction())
  // Scratch of connectivity_correction() / distances_to() / distances_from().
  std::vector<std::uint8_t> own_, stray_;
  std::vector<double> diff_, near_;
  std::vector<std::int64_t> zn_, zd_;
  std::vector<double> cell_x_, cell_y_;  // per cell: its coordinates (vectorised direct distances)
  std::vector<int> cell_column_;         // per cell: its x
  std::vector<double> root_;             // root_[k] = sqrt(k) for every squared distance in the box
  std::vector<int> added_;
  std::vector<int> row_begin_;  // per box row: its first cell (compact indices are row-major)
  std::vector<int> v_, roots_, steps_, queue_;
  std::vector<int> left_, down_;             // per cell: its -x / -y neighbour, -1 = none
  std::vector<int> parent_;                 // union-find of evaluate()
  std::vector<std::uint8_t> in_start_piece_;  // per cell: in the piece of its owner's start
  DivisionScore score_;
  int updates_ = 0;
  // Euclidean distance transforms run on the bounding box of the region.
  int box_x0_ = 0, box_y0_ = 0, box_w_ = 0, box_h_ = 0;
};

// Starts other than the robots' own cells (see DarpInit in darp.hpp). All take and return compact
// cell indices of space.graph, one per robot, distinct.
[[nodiscard]] std::vector<int> random_starts(const DarpSpace& space, const std::vector<int>& robots,
                                             DarpDistance distance, Rng& rng);
[[nodiscard]] std::vector<int> kmeans_starts(const DarpSpace& space, const std::vector<int>& robots,
                                             const DarpConfig& config);
// One K-Means iteration with a BFS assignment step (see DarpInit::BfsKMeans).
[[nodiscard]] std::vector<int> bfs_kmeans_step(const DarpSpace& space, const std::vector<int>& starts);
// bfs_kmeans_step repeated until the starts stop moving, at most lloyd_steps times.
[[nodiscard]] std::vector<int> bfs_kmeans_starts(const DarpSpace& space, const std::vector<int>& starts,
                                                 int lloyd_steps);

}  // namespace swarm::planner::detail
