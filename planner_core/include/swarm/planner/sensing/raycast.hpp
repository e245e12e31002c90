// 2-D LiDAR on an occupancy grid: the simulator's range sensor (cast_ray, scan on the ground
// truth) and the agents' map update (integrate_scan on their own map).
//
// Exact grid traversal after Amanatides & Woo, "A Fast Voxel Traversal Algorithm for Ray
// Tracing", Eurographics 1987: the ray visits every cell whose interior it crosses, in order.
// Units are cells: a robot in cell c sits at (c.x + 0.5, c.y + 0.5); angles are radians,
// counter-clockwise from +x; ranges are cell lengths (multiply by the resolution for metres).
//
// Conventions (chosen so that integrate_scan can recover exactly what scan saw):
//  * A range is the distance at which the ray enters the first Occupied cell; out-of-bounds cells
//    count as Occupied; max_range_cells means nothing was hit within range.
//  * A ray passing exactly through a cell corner does not slip between two cells touching only at
//    that corner: it is stopped there if either of them is Occupied (as robots may not cut
//    corners, see grid.hpp). It enters only the diagonal cell. Such an end is ambiguous (which of
//    the three cells was hit?), so integrate_scan marks no cell Occupied for it.
//  * All arithmetic is float and identical in scan and integrate_scan, so a range from scan names
//    its hit cell exactly. Noisy ranges are fine too: the cell containing the end point is the hit.
//
//   std::vector<float> ranges(360);
//   scan(truth, robot, 360, 15.0f, ranges.data());                     // simulator
//   std::vector<CellChange> changes;
//   integrate_scan(map, robot, ranges.data(), 360, 15.0f, &changes);   // agent
//
// Thread-safety: the functions are safe to call concurrently (per-thread direction tables).
#pragma once

#include <vector>

#include "swarm/planner/grid/grid.hpp"

namespace swarm::planner {

// The angle of beam i of a `beams`-beam scan: 2*pi*i/beams. scan(...)[i] equals
// cast_ray(truth, c.x + 0.5, c.y + 0.5, beam_angle(i, beams), max) bit for bit.
[[nodiscard]] double beam_angle(int i, int beams);

// Distance from (x, y) (cell units) along angle_rad to where the ray enters the first Occupied
// cell, or max_range_cells if there is none within range. 0 if (x, y) itself is Occupied or out
// of bounds.
[[nodiscard]] float cast_ray(const OccupancyGrid& truth, double x, double y, double angle_rad,
                             float max_range_cells);

// `beams` rays from the centre of `origin`, beam i at beam_angle(i, beams), written to
// ranges_out[0 .. beams).
void scan(const OccupancyGrid& truth, Cell origin, int beams, float max_range_cells,
          float* ranges_out);

// Updates `map` with one scan taken from the centre of `origin` (in bounds). The origin cell and
// every cell a beam crosses before its range become Free; the cell a beam ends in becomes Occupied
// when its range is < max_range_cells. Within one scan Occupied wins: a cell one beam ends in is
// not freed by another. Each cell that actually changed is appended once to `changes` (if not
// null) with its new state; returns how many changed. Negative or NaN ranges are skipped;
// ranges above max_range_cells count as max_range_cells.
int integrate_scan(OccupancyGrid& map, Cell origin, const float* ranges, int beams,
                   float max_range_cells, std::vector<CellChange>* changes);

}  // namespace swarm::planner
