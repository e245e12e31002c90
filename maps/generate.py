#!/usr/bin/env python3
"""Generates the built-in maps (ROS map_server PGM + YAML, 0.2 m per cell) from the plans below.

    python3 maps/generate.py          # rewrites maps/*.pgm and maps/*.yaml next to this script
    python3 maps/generate.py --check  # fails if the committed files differ from what it would write

Python 3 standard library only; the output is a pure function of this file (no randomness).

How a map is described
----------------------
Each map is a grid of rooms drawn as ASCII art, read like a classic maze drawing:

    +---+---+      '+'   a wall post (a junction of wall lines)
    |       |      '---' (between posts) or '|' (between rooms): a solid wall
    +...+   +      '   ' or ' ': a wall with a centred door DOOR_CELLS wide
    |   |   |      '...' or '.': no wall at all (the two rooms are one)
    +---+---+

The art's top row is the map's top (largest y). `cols` and `rows` give the cell index of every
wall line from left to right and from top to bottom (image coordinates: PGM row 0 is the top); the
first and last lines are the outer wall. Walls are one cell thick. `obstacles` adds solid
blocks, in metres of the map frame: (x0, y0, x1, y1), lower-left corner to upper-right corner.
`resolution` (metres per cell) is RESOLUTION unless a map sets its own.

A warehouse map (the MAPF paper's world, docs/papers.md section 3) is given as `warehouse=(R, C)`
instead: R x C intersections at cells (2j + 1, 2i + 1) joined by one-cell passages, with a block
of wall between every four intersections and a one-cell outer wall; (2C + 1) x (2R + 1) cells,
the same cells as the built-in `swarm mapf --map warehouse-RxC` (planner/mapf/warehouse.hpp).

A map may instead be carved out of solid wall: `areas` lists free rectangles (the same
(x0, y0, x1, y1) in metres), then `obstacles` are put back; `cells(x0, y0, x1, y1)` writes such a
rectangle from inclusive cell indices (x from the left, y from the bottom).

Every map is checked before it is written: the outer border is wall; the cell at the map centre
(width // 2, height // 2), which is where robots start by default, is free; every free cell is
reachable from it (4-connected moves, which is what 8-connected moves that never cut a corner
reach); and a 3 x 3 cell footprint (0.6 m at 0.2 m per cell, 0.3 m -- a robot vacuum -- at 0.1 m)
can pass every door and gap and reach the neighbourhood of every free cell. Warehouse maps skip the
footprint check: they are for multi-agent path finding, where a robot is one cell and the aisles
are one cell wide on purpose.
"""

import argparse
import collections
import os
import sys

RESOLUTION = 0.2  # metres per cell
DOOR_CELLS = 4  # 0.8 m doors
FREE, OCCUPIED = 254, 0  # PGM grey levels as map_saver writes them (unknown would be 205)


def cells(x0, y0, x1, y1):
    """The rectangle of cells x0..x1, y0..y1 (inclusive; y from the bottom) in metres."""
    return (x0 * RESOLUTION, y0 * RESOLUTION, (x1 + 1) * RESOLUTION, (y1 + 1) * RESOLUTION)


def even_lines(cells, rooms):
    """Wall-line cell indices splitting `cells` cells into `rooms` rooms as evenly as possible."""
    return [round(i * (cells - 1) / rooms) for i in range(rooms + 1)]


# The furniture of "clutter" (seeds/003's Fig. 9 is lost; its Fig. 10 gives 7 obstacle groups of
# complexity 0.24 to 0.74): blocks in metres (x0, y0, x1, y1), a cluster per group, clusters at least 0.8 m apart so that every obstacle's nearest neighbour is in its own.
CLUTTER = [
    # a sofa and a side table
    (0.3, 3.8, 2.3, 4.6),
    (1.1, 3.2, 1.5, 3.6),
    # three bar stools and a bin
    (3.6, 4.2, 3.9, 4.5),
    (4.0, 4.2, 4.3, 4.5),
    (4.4, 4.2, 4.7, 4.5),
    (4.9, 4.3, 5.0, 4.4),
    # two boxes and a floor lamp
    (5.0, 2.2, 5.3, 2.5),
    (5.0, 2.6, 5.3, 2.9),
    (5.1, 3.1, 5.2, 3.2),
    # a stool's four legs, 20 cm apart
    (2.8, 2.4, 2.9, 2.5),
    (3.0, 2.4, 3.1, 2.5),
    (2.8, 2.6, 2.9, 2.7),
    (3.0, 2.6, 3.1, 2.7),
    # a toy corner: two crates and toys strewn further and further away
    (0.4, 0.4, 0.6, 0.7),
    (0.7, 0.4, 0.9, 0.7),
    (1.1, 0.5, 1.2, 0.6),
    (1.5, 0.6, 1.6, 0.7),
    (2.0, 0.4, 2.1, 0.5),
    (2.6, 0.6, 2.7, 0.7),
    # a shoe rack of four pairs
    (4.0, 0.4, 4.2, 0.6),
    (4.3, 0.4, 4.5, 0.6),
    (4.6, 0.4, 4.8, 0.6),
    (4.9, 0.4, 5.1, 0.6),
    # two crates
    (4.2, 1.1, 4.4, 1.4),
    (4.5, 1.1, 4.7, 1.4),
]

# The walls of the Group-k rooms: 6 m x 5 m at 10 cm per cell. The paper's robot is one 10 cm
# cell, so gaps of one cell count as passable there (no footprint check).
ROOM = dict(
    size=(60, 50),
    resolution=0.1,
    footprint=False,
    cols=[0, 59],
    rows=[0, 49],
    art="""
+---+
|   |
+---+
""",
)

MAPS = {
    # An open hall: outer wall and scattered pillars, boxes and short wall pieces.
    "open": dict(
        size=(100, 100),
        cols=[0, 99],
        rows=[0, 99],
        art="""
+---+
|   |
+---+
""",
        obstacles=[
            (3.0, 3.0, 3.6, 3.6),  # pillars
            (3.0, 16.4, 3.6, 17.0),
            (16.4, 3.0, 17.0, 3.6),
            (16.4, 16.4, 17.0, 17.0),
            (7.0, 13.0, 7.6, 13.6),
            (13.0, 7.0, 13.6, 7.6),
            (6.0, 6.0, 8.0, 7.0),  # boxes
            (12.4, 12.6, 14.0, 14.2),
            (2.0, 9.0, 4.0, 9.4),  # short wall pieces
            (9.6, 16.0, 10.0, 18.4),
            (15.0, 9.4, 18.0, 9.8),
            (8.0, 2.0, 11.0, 2.4),
        ],
    ),
    # 5 x 5 rooms of about 3.7 m, joined by doors like a maze with a few loops.
    "maze1": dict(
        size=(100, 100),
        cols=even_lines(100, 5),
        rows=even_lines(100, 5),
        art="""
+---+---+---+---+---+
|       |           |
+   +   +   +---+   +
|   |       |       |
+   +---+   +   +---+
|       |       |   |
+---+   +   +---+   +
|   |           |   |
+   +---+   +   +   +
|           |       |
+---+---+---+---+---+
""",
        obstacles=[],
    ),
    # 7 x 7 rooms of about 2.6 m joined as a maze with few loops and many dead ends; two pairs of
    # rooms are merged ('.') into short corridors.
    "maze2": dict(
        size=(100, 100),
        cols=even_lines(100, 7),
        rows=even_lines(100, 7),
        art="""
+---+---+---+---+---+---+---+
|       |                   |
+---+   +   +---+   +---+---+
|   .           |       |   |
+---+---+---+   +---+---+   +
|               |   |   |   |
+   +   +---+   +   +   +   +
|       |           .       |
+---+   +   +---+   +---+   +
|               |       |   |
+---+   +---+   +   +   +   +
|           |   |   |   |   |
+   +---+   +   +   +---+   +
|   |           |       |   |
+---+---+---+---+---+---+---+
""",
        obstacles=[],
    ),
    # 8 m x 8 m, three rooms in a chain: a tall left room holding the centre, and two on the right.
    "small": dict(
        size=(40, 40),
        cols=[0, 22, 39],
        rows=[0, 18, 39],
        art="""
+---+---+
|       |
+...+   +
|   |   |
+---+---+
""",
        obstacles=[],
    ),
    # Group-k's test room (seeds/003, Fig. 9, whose layout is lost): 6 m x 5 m at the paper's 10 cm
    # per cell, furnished with 7 clusters of obstacles.
    "clutter": dict(ROOM, obstacles=CLUTTER),
    # The same room with nothing in it.
    "empty": dict(ROOM, obstacles=[]),
    # The MAPF paper's test world: 5 x 8 intersections, 17 x 11 cells (planner/mapf/warehouse.hpp).
    "warehouse-5x8": dict(warehouse=(5, 8)),
    # An airport passenger terminal in miniature (the DARP paper's complex map: corridors,
    # intersections, bottlenecks): a check-in hall with counter islands along the bottom, two
    # 0.8 m security passages up to the airside concourse, three piers with a gate lounge on each
    # side (0.8 m doors), and a satellite on the middle pier, also reached from the left pier by a
    # 0.6 m service corridor (one loop). Entrance: the middle of the hall's bottom wall.
    "terminal": dict(
        size=(140, 100),
        areas=[
            cells(8, 4, 131, 14),  # check-in hall
            cells(38, 15, 41, 23), cells(98, 15, 101, 23),  # security passages
            cells(8, 24, 131, 31),  # airside concourse
            cells(22, 32, 27, 83), cells(67, 32, 72, 85), cells(112, 32, 117, 83),  # piers
            cells(9, 44, 20, 55), cells(21, 48, 21, 51),  # pier 1: left lounge and its door
            cells(29, 62, 40, 73), cells(28, 66, 28, 69),  # pier 1: right lounge
            cells(54, 44, 65, 55), cells(66, 48, 66, 51),  # pier 2
            cells(74, 62, 85, 73), cells(73, 66, 73, 69),
            cells(99, 44, 110, 55), cells(111, 48, 111, 51),  # pier 3
            cells(119, 62, 130, 73), cells(118, 66, 118, 69),
            cells(52, 86, 87, 94),  # satellite
            cells(22, 84, 51, 86),  # service corridor from pier 1 to the satellite
        ],
        obstacles=[cells(x, 8, x + 3, 11) for x in (18, 36, 54, 82, 100, 118)],  # counters
    ),
    # A near-empty rectangle (the paper's "normal" map): four small pillars, two of them 0.8 m
    # apart near the centre (the one narrow gap).
    "rectangle": dict(
        size=(80, 60),
        cols=[0, 79],
        rows=[0, 59],
        art="""
+---+
|   |
+---+
""",
        obstacles=[cells(36, 28, 37, 29), cells(42, 28, 43, 29), cells(16, 14, 17, 15),
                   cells(62, 44, 63, 45)],
    ),
}


class Plan:
    """The parsed art: which wall segments are walls, doors or open."""

    def __init__(self, art, n_cols, n_rows):
        lines = [l.rstrip() for l in art.strip("\n").split("\n")]
        if len(lines) != 2 * n_rows + 1:
            raise ValueError(f"art has {len(lines)} lines, expected {2 * n_rows + 1}")
        width = 4 * n_cols + 1
        for i, l in enumerate(lines):
            if len(l) != width:
                raise ValueError(f"art line {i + 1} has {len(l)} characters, expected {width}")
        self.lines = lines
        self.n_cols, self.n_rows = n_cols, n_rows

    @staticmethod
    def _kind(text):
        if set(text) == {"-"} or text == "|":
            return "wall"
        if set(text) == {" "}:
            return "door"
        if set(text) == {"."}:
            return "open"
        raise ValueError(f"unknown wall segment {text!r}")

    def horizontal(self, line_row, col):
        """The segment on horizontal wall line `line_row` above room column `col`."""
        return self._kind(self.lines[2 * line_row][4 * col + 1:4 * col + 4])

    def vertical(self, line_col, row):
        """The segment on vertical wall line `line_col` beside room row `row`."""
        return self._kind(self.lines[2 * row + 1][4 * line_col])


def build_warehouse(rows, cols):
    """Intersections at odd (x, y), passages between them, blocks at even (x, y), walled."""
    width, height = 2 * cols + 1, 2 * rows + 1
    img = [[OCCUPIED] * width for _ in range(height)]  # img[row][col], row 0 = top
    for y in range(1, height - 1):
        for x in range(1, width - 1):
            if x % 2 == 1 or y % 2 == 1:
                img[height - 1 - y][x] = FREE
    return img


def build(spec):
    if "warehouse" in spec:
        return build_warehouse(*spec["warehouse"])
    width, height = spec["size"]
    if "areas" in spec:
        img = [[OCCUPIED] * width for _ in range(height)]
        fill(img, spec["areas"], FREE)
        fill(img, spec["obstacles"], OCCUPIED)
        return img
    cols, rows = spec["cols"], spec["rows"]
    plan = Plan(spec["art"], len(cols) - 1, len(rows) - 1)
    img = [[FREE] * width for _ in range(height)]  # img[row][col], row 0 = top

    def wall_span(kind, lo, hi, put):
        """Fills cells lo..hi (inclusive, the segment between two posts) per the segment kind."""
        if kind == "open":
            return
        n = hi - lo + 1
        door = set()
        if kind == "door":
            if n < DOOR_CELLS:
                raise ValueError(f"segment of {n} cells is too short for a door")
            first = lo + (n - DOOR_CELLS) // 2
            door = set(range(first, first + DOOR_CELLS))
        for i in range(lo, hi + 1):
            if i not in door:
                put(i)

    for j, r in enumerate(rows):  # horizontal wall lines
        for i in range(len(cols) - 1):
            kind = plan.horizontal(j, i)
            wall_span(kind, cols[i] + 1, cols[i + 1] - 1,
                      lambda x, r=r: img[r].__setitem__(x, OCCUPIED))
    for i, c in enumerate(cols):  # vertical wall lines
        for j in range(len(rows) - 1):
            kind = plan.vertical(i, j)
            wall_span(kind, rows[j] + 1, rows[j + 1] - 1,
                      lambda y, c=c: img[y].__setitem__(c, OCCUPIED))
    for j, r in enumerate(rows):  # posts: kept unless every segment meeting there is open
        for i, c in enumerate(cols):
            kinds = []
            if i > 0:
                kinds.append(plan.horizontal(j, i - 1))
            if i < len(cols) - 1:
                kinds.append(plan.horizontal(j, i))
            if j > 0:
                kinds.append(plan.vertical(i, j - 1))
            if j < len(rows) - 1:
                kinds.append(plan.vertical(i, j))
            if any(k != "open" for k in kinds):
                img[r][c] = OCCUPIED
    fill(img, spec["obstacles"], OCCUPIED, spec.get("resolution", RESOLUTION))
    return img


def fill(img, rects, value, res=RESOLUTION):
    """Sets every cell that the metre rectangles (x0, y0, x1, y1) (map frame, y up) overlap."""
    height = len(img)
    for x0, y0, x1, y1 in rects:
        cx0, cx1 = int(round(x0 / res)), int(round(x1 / res))
        cy0, cy1 = int(round(y0 / res)), int(round(y1 / res))
        for y in range(cy0, cy1):
            for x in range(cx0, cx1):
                img[height - 1 - y][x] = value


def check(name, img, footprint=True):
    """Asserts the properties promised in the module docstring (the footprint one only if asked);
    returns the free-cell count."""
    height, width = len(img), len(img[0])
    for x in range(width):
        assert img[0][x] == OCCUPIED and img[height - 1][x] == OCCUPIED, f"{name}: open top/bottom"
    for y in range(height):
        assert img[y][0] == OCCUPIED and img[y][width - 1] == OCCUPIED, f"{name}: open left/right"
    free = {(x, y) for y in range(height) for x in range(width) if img[height - 1 - y][x] == FREE}
    start = (width // 2, height // 2)
    assert start in free, f"{name}: the centre cell {start} is not free"

    def flood(cells, seed):
        seen, todo = {seed}, collections.deque([seed])
        while todo:
            x, y = todo.popleft()
            for n in ((x + 1, y), (x - 1, y), (x, y + 1), (x, y - 1)):
                if n in cells and n not in seen:
                    seen.add(n)
                    todo.append(n)
        return seen

    reached = flood(free, start)
    assert reached == free, f"{name}: {len(free - reached)} free cells unreachable from {start}"
    if not footprint:
        return len(free)
    # Cells where a 3 x 3 footprint fits; they must be one connected area that touches (within
    # one cell) every free cell, so no door or gap is narrower than 0.6 m and no nook is a trap.
    wide = {(x, y) for (x, y) in free
            if all((x + dx, y + dy) in free for dx in (-1, 0, 1) for dy in (-1, 0, 1))}
    assert start in wide, f"{name}: no 3 x 3 footprint fits at the centre"
    wide_reached = flood(wide, start)
    assert wide_reached == wide, f"{name}: {len(wide - wide_reached)} footprint cells cut off"
    covered = {(x + dx, y + dy) for (x, y) in wide for dx in (-1, 0, 1) for dy in (-1, 0, 1)}
    assert free <= covered, f"{name}: {len(free - covered)} free cells a 0.6 m robot cannot reach"
    return len(free)


def pgm_bytes(img, res):
    height, width = len(img), len(img[0])
    header = f"P5\n# CREATOR: maps/generate.py {res:.3f} m/pix\n{width} {height}\n255\n"
    return header.encode("ascii") + bytes(v for row in img for v in row)


def yaml_bytes(name, res):
    # The keys and number formats map_server's map_saver writes.
    return (f"image: {name}.pgm\n"
            f"mode: trinary\n"
            f"resolution: {res:.6f}\n"
            f"origin: [0.000000, 0.000000, 0.000000]\n"
            f"negate: 0\n"
            f"occupied_thresh: 0.65\n"
            f"free_thresh: 0.196\n").encode("ascii")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--check", action="store_true",
                        help="fail if the files on disk differ instead of writing them")
    parser.add_argument("--out", default=os.path.dirname(os.path.abspath(__file__)))
    args = parser.parse_args()
    stale = []
    for name, spec in MAPS.items():
        img = build(spec)
        free = check(name, img, spec.get("footprint", "warehouse" not in spec))
        res = spec.get("resolution", RESOLUTION)
        files = {f"{name}.pgm": pgm_bytes(img, res), f"{name}.yaml": yaml_bytes(name, res)}
        for fname, data in files.items():
            path = os.path.join(args.out, fname)
            if args.check:
                try:
                    with open(path, "rb") as f:
                        if f.read() != data:
                            stale.append(path)
                except FileNotFoundError:
                    stale.append(path)
            else:
                with open(path, "wb") as f:
                    f.write(data)
        h, w = len(img), len(img[0])
        print(f"{name}: {w} x {h} cells ({w * res:g} x {h * res:g} m), "
              f"{free} free cells")
    if stale:
        print("out of date (run maps/generate.py):", *stale, sep="\n  ", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
