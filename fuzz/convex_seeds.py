#!/usr/bin/env python3
"""Writes fuzz_convex's hand-made seeds into fuzz/corpus/convex/ (format: convex_fuzz.cpp).

Run from anywhere: python3 fuzz/convex_seeds.py. Each seed is on the grid: integer coordinates
g·2^e plus an offset (ox, oy)·2^f, in float and in double.
"""
import os
import struct

FLOAT, GRID, CIRCLE = 1, 2, 4


def seed(a, b=None, circle=None, e=0, f=0, ox=0, oy=0, masks=(0, 0, 0, 0)):
    """A pair as (mode without the precision bit, bytes after the mode byte)."""
    numbers = [c for v in a for c in v]
    mode = GRID
    if circle is not None:
        mode |= CIRCLE
        numbers += list(circle)
        counts = len(a)
    else:
        numbers += [c for v in b for c in v]
        counts = len(a) | len(b) << 4
    body = bytes([counts]) + struct.pack("<%dh" % len(numbers), *numbers)
    body += struct.pack("<4b", e, f, ox, oy) + bytes(masks)
    return mode, body


def box(x0, y0, x1, y1):
    return [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]


OCTAGON = [(1, 0), (2, 0), (3, 1), (3, 2), (2, 3), (1, 3), (0, 2), (0, 1)]
HEXAGON = [(2, 0), (4, 0), (5, 2), (4, 4), (2, 4), (1, 2)]

SEEDS = {
    "box_on_box": seed(box(0, 0, 4, 4), box(3, 1, 6, 3)),
    "boxes_touching": seed(box(0, 0, 4, 4), box(4, 1, 6, 3)),
    "boxes_apart": seed(box(0, 0, 4, 4), box(6, 5, 9, 7)),
    "octagons": seed([(x * 4, y * 4) for x, y in OCTAGON], [(x * 4 + 10, y * 4 + 3) for x, y in OCTAGON], e=-2),
    "nested": seed([(x * 8, y * 8) for x, y in OCTAGON], box(8, 8, 12, 12), e=-3),
    "triangles": seed([(0, 0), (8, 0), (0, 8)], [(2, 2), (9, 3), (3, 9)]),
    "far": seed(box(0, 0, 4, 4), HEXAGON, e=-2, f=16, ox=100, oy=-50),
    "tiny": seed(box(0, 0, 4, 4), box(3, 1, 6, 3), e=-60),
    "masked_ground": seed(box(0, 0, 8, 2), box(2, 1, 4, 3), masks=(0b1011, 0, 0, 0)),
    "hexagon_circle": seed(HEXAGON, circle=(5, 5, 2)),
    "circle_inside": seed(HEXAGON, circle=(3, 2, 1)),
    "circle_on_vertex": seed(box(0, 0, 4, 4), circle=(4, 4, 1)),
    "circle_touching_face": seed(box(0, 0, 4, 4), circle=(2, 6, 2)),
    "circle_tangent_at_corner": seed(box(0, 0, 4, 4), circle=(7, 8, 5)),
    "too_few_vertices": seed([(0, 0)], box(0, 0, 1, 1)),
    "segment_under_box": seed([(8, 0), (0, 0)], box(2, -1, 4, 3)),
    "segment_end_at_box": seed([(0, 0), (4, 0)], box(4, -2, 6, 2)),
    "one_sided_segment": seed([(8, 0), (0, 0)], box(2, -3, 4, 1), masks=(0b10, 0b11, 0, 0)),
    "segment_circle": seed([(0, 0), (8, 0)], circle=(4, 1, 2)),
    "circle_past_segment_end": seed([(0, 0), (8, 0)], circle=(9, 1, 2), masks=(0b10, 0b10, 0, 0)),
    "collinear": seed([(0, 0), (2, 0), (4, 0), (4, 4)], box(0, 0, 1, 1)),
    "reflex": seed([(0, 0), (4, 0), (2, 1), (4, 4), (0, 4)], box(0, 0, 1, 1)),
}


def main():
    out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus", "convex")
    os.makedirs(out, exist_ok=True)
    for name, (mode, body) in SEEDS.items():
        for precision, bit in (("double", 0), ("float", FLOAT)):
            with open(os.path.join(out, "%s_%s" % (name, precision)), "wb") as f:
                f.write(bytes([mode | bit]) + body)


if __name__ == "__main__":
    main()
