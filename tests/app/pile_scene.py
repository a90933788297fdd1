#!/usr/bin/env python3
"""Writes a scene of N dynamic bodies (boxes, balls and pentagons in rows) falling into a static bin, with gravity
and dt 1/60 s, for measuring the app's frame rate while it simulates: pile_scene.py N > pile.json, then
satviz pile.json --play --measure-fps 300 under Xvfb. The first two bodies are the bin's floor and the first body
above it, the pair the figure tests."""
import json
import sys

n = int(sys.argv[1])
columns = 25 if n <= 500 else 50
width = columns * 0.5
bodies = [
    {"name": "floor", "box": [width + 1.0, 0.5], "position": [0.0, -0.25], "static": True},
]
for i in range(n):
    row, column = divmod(i, columns)
    x = -width / 2 + 0.25 + column * 0.5 + (0.1 if row % 2 else 0.0)
    y = 0.3 + row * 0.5
    body = {"name": f"body{i + 1}", "position": [round(x, 3), round(y, 3)]}
    kind = i % 3
    if kind == 0:
        body["box"] = [0.4, 0.3]
    elif kind == 1:
        body["circle"] = {"radius": 0.2}
    else:
        body["regular"] = {"sides": 5, "radius": 0.22}
    bodies.append(body)
height = (n // columns + 2) * 0.5 + 1.0
bodies.append({"name": "left wall", "box": [0.5, height], "position": [-width / 2 - 0.25, height / 2], "static": True})
bodies.append({"name": "right wall", "box": [0.5, height], "position": [width / 2 + 0.25, height / 2], "static": True})
scene = {
    "description": f"{n} bodies falling into a bin, for measuring the frame rate while the app simulates them.",
    "bodies": bodies,
    "world": {"gravity": [0.0, -9.81], "dt": 1.0 / 60.0},
}
json.dump(scene, sys.stdout, indent=1)
