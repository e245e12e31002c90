#!/usr/bin/env python3
"""Writes the two scenarios of Kim & Lee 2025 (seeds/001, Figs. 2 and 4) as tour files.

    python3 scenarios/tour/generate.py          # rewrites scenario1.tour and scenario2.tour here
    python3 scenarios/tour/generate.py --check  # fails if the files differ from what it would write

The paper's figures are lost; its text keeps the room sizes, the start, the number of objects of
each type, that the destinations are in the top right corner, the type order, and a few object
positions. Everything else is drawn here: objects uniformly on the free cells (random.Random with
a fixed seed, so the files are a pure function of this script), drawing again until the layout
agrees with every fact the paper states (the type order the nearest-object rule gives, and that
the NNA method's first waypoint is not the point the paper says the GA moved it to). Nothing is
chosen by how the planners do on it.
"""

import argparse
import os
import random
import sys

SCENARIOS = {
    "scenario1": dict(
        title="Scenario 1 (Fig. 2): 12 x 12 room, 8 each of paper, can, PET, no obstacles",
        size=(12, 12), origin=(-6, -6), start=(0, -5),
        types=["paper", "can", "pet"],
        destinations={"paper": (5, 5), "can": (4, 5), "pet": (5, 4)},
        per_type=8,
        obstacles=[],
        fixed=[("paper", (4, -4))],
        type_order=["paper", "pet", "can"],
        # The GA (distance efficient) moved paper's first waypoint to (4, -4): NNA's is another.
        not_first={"paper": (4, -4)},
    ),
    "scenario2": dict(
        title="Scenario 2 (Fig. 4): 20 x 20 room, 10 each of 5 types, rectangular obstacles",
        size=(20, 20), origin=(-10, -10), start=(0, -9),
        types=["paper", "can", "pet", "glass", "metal"],
        destinations={"paper": (9, 9), "can": (8, 9), "pet": (9, 8), "glass": (7, 9), "metal": (9, 7)},
        per_type=10,
        obstacles=[(-7, -3, -5, 2), (2, -6, 5, -5), (-3, 3, 0, 4), (5, 0, 6, 4), (-8, 5, -6, 6)],
        fixed=[("paper", (-3, -7)), ("can", (2, 8))],
        type_order=["paper", "pet", "metal", "glass", "can"],
        not_first={"paper": (-3, -7), "can": (2, 8)},
    ),
}


def blocked(spec, c):
    return any(x0 <= c[0] <= x1 and y0 <= c[1] <= y1 for x0, y0, x1, y1 in spec["obstacles"])


def d2(a, b):
    return (a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2


def agrees(spec, objects):
    """The type order of the nearest-object rule, and NNA's first waypoint of each type."""
    left = list(objects)
    at = spec["start"]
    for t in spec["type_order"]:
        first = min(left, key=lambda o: d2(at, o[1]))  # ties: the first in file order, as the planner
        if first[0] != t or spec["not_first"].get(t) == first[1]:
            return False
        left = [o for o in left if o[0] != t]
        at = spec["destinations"][t]
    return True


def layout(spec):
    w, h = spec["size"]
    ox, oy = spec["origin"]
    taken = {spec["start"], *spec["destinations"].values(), *(c for _, c in spec["fixed"])}
    free = [(x, y) for y in range(oy, oy + h) for x in range(ox, ox + w)
            if (x, y) not in taken and not blocked(spec, (x, y))]
    rng = random.Random(2025)
    for _ in range(100000):
        cells = rng.sample(free, spec["per_type"] * len(spec["types"]) - len(spec["fixed"]))
        objects = list(spec["fixed"])
        counts = {t: sum(1 for f, _ in spec["fixed"] if f == t) for t in spec["types"]}
        for t in spec["types"]:
            while counts[t] < spec["per_type"]:
                objects.append((t, cells.pop()))
                counts[t] += 1
        objects.sort(key=lambda o: (spec["types"].index(o[0]), o[1][1], o[1][0]))  # file order
        if agrees(spec, objects):
            return objects
    raise RuntimeError("no layout agrees with the paper")


def text(name, spec):
    w, h = spec["size"]
    lines = [f"# {spec['title']}.",
             "# Kim & Lee 2025 (seeds/001). Written by scenarios/tour/generate.py: the paper's facts",
             "# (sizes, start, counts, type order, the points marked fixed), the rest drawn at random.",
             f"size {w} {h}",
             f"origin {spec['origin'][0]} {spec['origin'][1]}",
             f"start {spec['start'][0]} {spec['start'][1]} up",
             "after-drop left"]
    for t in spec["types"]:
        x, y = spec["destinations"][t]
        lines.append(f"destination {t} {x} {y}")
    for x0, y0, x1, y1 in spec["obstacles"]:
        lines.append(f"obstacle {x0} {y0} {x1} {y1}")
    fixed = set(spec["fixed"])
    for t, (x, y) in layout(spec):
        lines.append(f"object {t} {x} {y}" + (" fixed" if (t, (x, y)) in fixed else ""))
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--check", action="store_true")
    args = parser.parse_args()
    here = os.path.dirname(os.path.abspath(__file__))
    stale = []
    for name, spec in SCENARIOS.items():
        path = os.path.join(here, name + ".tour")
        data = text(name, spec)
        if args.check:
            try:
                with open(path) as f:
                    if f.read() != data:
                        stale.append(path)
            except FileNotFoundError:
                stale.append(path)
        else:
            with open(path, "w") as f:
                f.write(data)
            print(path)
    if stale:
        print("out of date (run scenarios/tour/generate.py):", *stale, sep="\n  ", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
