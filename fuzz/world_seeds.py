#!/usr/bin/env python3
"""Writes fuzz_world's hand-made seeds into fuzz/corpus/world/ (format: world_ops.hpp).

Run from anywhere: python3 fuzz/world_seeds.py. Inputs the fuzzer found (regress_*) are kept as
they were found, not made here.
"""
import os

KINDS = ["NewWorld", "EndWorld", "CreateBody", "DestroyBody", "AddTriangle", "AddMesh",
         "AddPolygon", "AddCircle", "DestroyFixture", "Teleport", "SetType", "SetEnabled",
         "SetVelocity", "ApplyImpulse", "Install", "Uninstall", "FixEdges", "RefreshEdges",
         "ForgetEdges", "Step", "WorldFlags", "AddEdge", "AddChain"]
STATIC, KINEMATIC, DYNAMIC, BULLET = range(4)
DYOP, DYOP_FAST, LIN_CANNY, SAT, EPA, BOX2D = range(6)


def op(kind, *args):
    args = [a & 0xFF for a in args] + [0] * (7 - len(args))
    return bytes([KINDS.index(kind)] + args)


def at(world, body):  # a body operation's target byte
    return world + 3 * body


def xy(x, y):  # two grid nibbles
    return ((y + 8) << 4) | (x + 8)


def step(world=3, dt=0, iterations=(8, 3), repeats=1):
    return op("Step", world, dt, iterations[0], iterations[1], repeats - 1)


def pile():
    s = op("Install", DYOP, 0, 0)  # world 0 exists from the start
    s += op("CreateBody", 0, STATIC, 0, -8, 0, 0)
    s += op("AddMesh", at(0, 0), 3, 0x13, xy(-2, 0), 1, 0)  # 4 x 2 cells of 1 m, sloped top
    for k in range(4):
        s += op("CreateBody", 0, DYNAMIC, 4 * k - 6, 2 + 3 * k, 0, 8 * k)  # just above
        s += op("AddTriangle", at(0, k + 1), 2 | (k << 5), xy(0, 0), xy(2, 0), xy(1, 2), xy(0, 0))
        s += op("AddTriangle", at(0, k + 1), 2, xy(0, 0), xy(1, 2), xy(-1, 2), xy(0, 0))
    return s + step(repeats=4) * 10


def t_junction_slide():
    s = op("Install", SAT, 0, 1)
    s += op("CreateBody", 0, STATIC, 0, 0, 0, 0)
    s += op("AddMesh", at(0, 0), 3 | 8, 0x03, xy(-2, -1), 0, 4)  # 4 cells, T-junction
    s += op("CreateBody", 0, DYNAMIC, -6, 1, 0, 0)  # resting on the mesh
    s += op("AddTriangle", at(0, 1), 1, xy(-4, -4), xy(4, -4), xy(4, 4), xy(0, 0))  # a 0.4 m box
    s += op("AddTriangle", at(0, 1), 1, xy(-4, -4), xy(4, 4), xy(-4, 4), xy(0, 0))
    s += op("SetVelocity", at(0, 1), 1, 48, -4, 0)
    s += op("FixEdges", 0, 1) + step(repeats=4) * 3
    s += op("Install", DYOP, 8, 0) + step(repeats=4) * 3  # internal edges off
    return s


def switch_backends():
    s = op("NewWorld", 1, 0)
    s += op("CreateBody", 1, STATIC, 0, 0, 0, 0)
    s += op("AddTriangle", at(1, 0), 3, xy(-4, -1), xy(4, -1), xy(4, 0), xy(0, 0))  # a slope
    s += op("CreateBody", 1, DYNAMIC, 0, -1, 0, 3)  # just above the slope
    s += op("AddTriangle", at(1, 1), 2, xy(-1, 0), xy(1, 0), xy(0, 1), xy(0, 0))
    s += op("AddCircle", at(1, 1), 1, xy(0, 2), 0)
    for backend in range(6):
        s += op("Install", backend, backend, backend) + step(1, repeats=2)
    s += op("Uninstall") + step(1, repeats=2) + op("Install", LIN_CANNY, 4, 1) + step(1)
    return s


def three_worlds():
    s = b""
    for w in range(3):
        s += op("NewWorld", w, w) if w else b""
        s += op("CreateBody", w, STATIC, 0, 0, 0, 0)
        s += op("AddMesh", at(w, 0), 2, 0x11, xy(0, 0), w, 0)
        s += op("CreateBody", w, DYNAMIC, 1, 3, 0, 0)
        s += op("AddTriangle", at(w, 1), 2, xy(0, 0), xy(1, 0), xy(0, 1), xy(0, 0))
    s += op("Install", EPA, 0, 0) + step(3, repeats=4) * 2
    s += op("EndWorld", 1, 1)  # delete without destroying bodies
    s += op("NewWorld", 1, 0) + op("CreateBody", 1, DYNAMIC, 0, 0, 0, 0)
    s += op("AddTriangle", at(1, 0), 3, xy(0, 0), xy(1, 0), xy(0, 1), xy(0, 0))
    s += op("EndWorld", 0, 0) + step(3, repeats=4) * 2
    return s


def fast_and_far():
    s = op("NewWorld", 2, 0) + op("Install", DYOP, 0, 2) + op("WorldFlags", 2, 8)
    s += op("CreateBody", 2, STATIC, 0, 0, 0o44, 0)  # 1e3 m from the origin
    s += op("AddMesh", at(2, 0), 5, 0x03, xy(-2, -1), 0, 0)  # 4 cells of 4 m
    s += op("AddTriangle", at(2, 0), 7, xy(-1, -2), xy(1, -2), xy(0, -1), xy(0, 0))  # huge
    s += op("CreateBody", 2, BULLET, 0, 20, 0o44, 0)
    s += op("AddTriangle", at(2, 1), 3 | (2 << 3), xy(-1, 0), xy(1, 0), 0, xy(0, 0), 1)  # sliver
    s += op("AddTriangle", at(2, 1), 3 | (3 << 3), xy(-1, 1), xy(0, 1), 0, xy(0, 0), 1)  # needle
    s += op("SetVelocity", at(2, 1), 3, 0, -100, 20)
    s += op("CreateBody", 2, DYNAMIC, 8, 20, 0o44, 0)
    s += op("AddTriangle", at(2, 2), 0, xy(0, 0), xy(1, 0), xy(0, 1), xy(0, 0))  # tiny
    s += op("AddPolygon", at(2, 2), 0 | (4 << 3), 0, 3, xy(2, 2), 0)
    s += op("ApplyImpulse", at(2, 2), 2, 0, -100, xy(1, 0), 10)
    for dt in (0, 1, 5, 2, 7):
        s += step(2, dt, (10, 4), 2)
    return s


def move_and_change():
    s = op("Install", DYOP, 0, 0)
    s += op("CreateBody", 0, STATIC, 0, 0, 0, 0)
    s += op("AddMesh", at(0, 0), 3, 0x02, xy(-1, 0), 0, 0)
    s += op("CreateBody", 0, STATIC, 12, 0, 0, 0)  # a second ground sharing an edge
    s += op("AddMesh", at(0, 1), 3, 0x00, xy(-1, 0), 0, 0)
    s += op("CreateBody", 0, DYNAMIC, 0, 8, 0, 0)
    s += op("AddTriangle", at(0, 2), 3, xy(-1, -1), xy(1, -1), xy(1, 0), xy(0, 0))
    s += op("AddPolygon", at(0, 2), 2, 0, 4, xy(0, 2), 0)
    s += op("FixEdges", 0, 1) + step(repeats=3)
    s += op("Teleport", at(0, 1), 14, 0, 0, 0) + op("RefreshEdges", 0, 12, 0, 0, 3)
    s += step(repeats=2) + op("ForgetEdges", 0)
    s += op("SetType", at(0, 1), KINEMATIC) + op("SetVelocity", at(0, 1), 1, -8, 0, 4)
    s += step(repeats=2) + op("SetEnabled", at(0, 0), 1) + step(repeats=2)
    s += op("SetEnabled", at(0, 0), 0) + op("SetType", at(0, 1), STATIC)
    s += op("DestroyFixture", at(0, 0), 3) + op("FixEdges", at(0, 0), 0) + step(repeats=2)
    s += op("DestroyBody", at(0, 1)) + op("Uninstall") + step(repeats=2)
    return s


def chains_and_edges():
    s = op("Install", DYOP, 0, 0)
    s += op("CreateBody", 0, STATIC, 0, 0, 0, 0)
    # An open chain of 5 vertices 2 m apart, the front up (right to left), then a loop of 4.
    s += op("AddChain", at(0, 0), 4 | (3 << 4), xy(-2, 0), xy(-2, 0), xy(-2, 1), xy(-2, 0), 0)
    s += op("AddChain", at(0, 0), 3 | 8 | (1 << 4), xy(3, 0), xy(0, 3), xy(-3, 0), 0, 0)
    s += op("CreateBody", 0, STATIC, 8, 0, 0, 0)  # two-sided edges end to end on another body
    for k in range(3):
        s += op("AddEdge", at(0, 1), 3, xy(k, 0), xy(k + 1, 0), 0)
    s += op("AddEdge", at(0, 1), 3 | 8 | (1 << 4), xy(3, 0), xy(4, 1), 0)  # one-sided, a ghost up
    s += op("CreateBody", 0, DYNAMIC, -2, 2, 0, 0)
    s += op("AddTriangle", at(0, 2), 2, xy(-1, 0), xy(1, 0), xy(1, 1), xy(0, 0))
    s += op("AddTriangle", at(0, 2), 2, xy(-1, 0), xy(1, 1), xy(-1, 1), xy(0, 0))
    s += op("CreateBody", 0, DYNAMIC, 6, 2, 0, 0)
    s += op("AddPolygon", at(0, 3), 2, 0, 0, xy(0, 1), 4)  # frictionless
    s += op("AddCircle", at(0, 3), 2, xy(2, 1), 4)
    s += op("SetVelocity", at(0, 3), 1, 32, 0, 0)
    s += op("FixEdges", 0, 1) + step(repeats=4) * 2
    s += op("Install", DYOP, 16, 0) + step(repeats=2)  # edges and chains left to Box2D
    s += op("Install", SAT, 0, 1) + step(repeats=2)
    s += op("CreateBody", 0, DYNAMIC, -4, -3, 0, 0)  # behind the chain, thrown up through it
    s += op("AddCircle", at(0, 4), 1, xy(0, 0), 0)
    s += op("SetVelocity", at(0, 4), 1, 0, 64, 0)
    return s + step(repeats=4) * 3


SEEDS = [pile, t_junction_slide, switch_backends, three_worlds, fast_and_far, move_and_change,
         chains_and_edges]

if __name__ == "__main__":
    folder = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus", "world")
    os.makedirs(folder, exist_ok=True)
    for seed in SEEDS:
        with open(os.path.join(folder, seed.__name__), "wb") as f:
            f.write(seed())
