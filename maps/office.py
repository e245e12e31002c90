#!/usr/bin/env python3
"""Draws a random office floor plan: a map no task was tuned on, to judge a change on.

    python3 maps/office.py --seed 3 --out /tmp/office    # writes office-s3.pgm and office-s3.yaml

A corridor of 2-3 cells runs across the middle (it holds the centre cell, where robots start);
rooms of 8-16 cells wide line both sides of it, each with a door of 1-3 cells to the corridor at a
random place, some with a second door to the next room, some with a desk or two standing in them.
Doors down to one cell are on purpose: robots of one cell must pass each other through them.
Same seed, same plan (Python's own random.Random); the standard library only. Every free cell is
checked to be reachable from the centre before anything is written.
"""

import argparse
import os
import random
import sys

FREE, WALL = 254, 0
RESOLUTION = 0.2


def draw(seed, width, height):
    rng = random.Random(seed)
    img = [[WALL] * width for _ in range(height)]

    def carve(x0, y0, x1, y1, value=FREE):  # inclusive cell rectangle, row 0 at the top
        for y in range(max(y0, 1), min(y1, height - 2) + 1):
            for x in range(max(x0, 1), min(x1, width - 2) + 1):
                img[y][x] = value

    corridor = rng.randint(2, 3)
    c0 = height // 2 - corridor // 2
    c1 = c0 + corridor - 1
    carve(1, c0, width - 2, c1)
    for top in (True, False):
        y0, y1 = (1, c0 - 2) if top else (c1 + 2, height - 2)
        x = 1
        previous = None
        while x < width - 2:
            w = min(rng.randint(8, 16), width - 2 - x)
            if w < 4:  # too thin for a room: the last room takes it
                if previous:
                    carve(previous[0], y0, width - 2, y1)
                break
            carve(x, y0, x + w - 1, y1)
            door = rng.randint(1, 3)
            at = rng.randint(x, x + w - door)
            carve(at, c0 - 1 if top else c1 + 1, at + door - 1, c0 - 1 if top else c1 + 1)
            if previous and rng.random() < 0.4:  # a door through the wall to the previous room
                door = rng.randint(1, 2)
                at = rng.randint(y0, y1 - door + 1)
                carve(x - 1, at, x - 1, at + door - 1)
            for _ in range(rng.randint(0, 2)):  # desks, a cell clear of every wall
                dw, dh = rng.randint(2, 4), rng.randint(1, 2)
                if w - dw < 4 or (y1 - y0 + 1) - dh < 6:
                    continue
                dx = rng.randint(x + 2, x + w - dw - 2)
                dy = rng.randint(y0 + 2, y1 - dh - 2)
                carve(dx, dy, dx + dw - 1, dy + dh - 1, WALL)
            previous = (x, w)
            x += w + 1
    return img


def check(img):
    height, width = len(img), len(img[0])
    cx, cy = width // 2, height // 2
    if img[cy][cx] != FREE:
        raise SystemExit(f"office.py: the centre cell ({cx}, {cy}) is a wall")
    seen = {(cx, cy)}
    todo = [(cx, cy)]
    while todo:
        x, y = todo.pop()
        for nx, ny in ((x + 1, y), (x - 1, y), (x, y + 1), (x, y - 1)):
            if img[ny][nx] == FREE and (nx, ny) not in seen:
                seen.add((nx, ny))
                todo.append((nx, ny))
    free = sum(row.count(FREE) for row in img)
    if free != len(seen):
        raise SystemExit(f"office.py: {free - len(seen)} free cells cannot be reached from the centre")
    return free


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--seed", type=int, required=True)
    p.add_argument("--width", type=int, default=72)
    p.add_argument("--height", type=int, default=44)
    p.add_argument("--out", required=True, help="directory for office-sSEED.pgm and .yaml")
    a = p.parse_args()
    if a.width < 20 or a.height < 20:
        raise SystemExit("office.py: --width and --height must be at least 20 cells")
    img = draw(a.seed, a.width, a.height)
    free = check(img)
    os.makedirs(a.out, exist_ok=True)
    name = f"office-s{a.seed}"
    with open(os.path.join(a.out, name + ".pgm"), "wb") as f:
        f.write(f"P5\n# CREATOR: maps/office.py --seed {a.seed}\n{a.width} {a.height}\n255\n".encode())
        f.write(bytes(v for row in img for v in row))
    with open(os.path.join(a.out, name + ".yaml"), "w") as f:
        f.write(f"image: {name}.pgm\nmode: trinary\nresolution: {RESOLUTION:.6f}\n"
                "origin: [0.000000, 0.000000, 0.000000]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n")
    print(f"office.py: {a.out}/{name}.yaml: {a.width} x {a.height} cells, {free} free", file=sys.stderr)


if __name__ == "__main__":
    main()
