#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Where the world's time goes: the self time of a perf profile of satviz-sim (perf record, no call graph needed),
summed by stage of the step, by the names of the functions that run it (inlined code counts to the function it is
inlined into). Usage: world_profile.py PERF.DATA [MS_PER_STEP]; with the step's time, each stage's ms per step too.
"""
import re
import subprocess
import sys

# The first pattern that matches a function's name takes its samples.
STAGES = [
    ("speculative contacts (their manifolds)", r"Speculative"),
    ("time of impact (sweeps, hits in time order)", r"TimeOfImpact|Sweep(?!Axis)|OutrunsPair|DiscCast|Conservative|BoxGrid"),
    ("narrowphase (Collide, manifolds, warm-start matching)",
     r"Collide|RunWide|IncidentEdge|QueryFaces|CollidePair|FindContacts\(\)::\{lambda\(int, int, int\)#3|FeatureKey|"
     r"TakeContacts|LargestSeparation|RefFaceQuery|HideFaces|SecondPassSkips|CombineMaterials|WidenWithin|"
     r"ClipIncidentEdge|ScannedIncidentEdge|WithTracer"),
    ("broadphase (sort and sweep, pair sort, boxes)",
     r"FindPairs|ComputeAabb|SweepAxis|SkipPair|SkipSlowPair|sort<.*pair<int, int>|insert<.*pair<int, int>"),
    ("soft step (its sub-steps and restitution, with --soft-step)",
     r"SolveSoft|SoftRestitution|SoftBounceTargets|SolveNormalBlock|PassOverBatches|SoftPassOverBatches|"
     r"PackSoftLane|UnpackSoftLane|MakeSoftContact"),
    ("restitution", r"ApplyRestitution"),
    ("velocity passes (with preparation, warm start, order, energy limit)",
     r"SolveContactVelocity|SolveVelocities|PrepareContact|PrepareContacts|WarmStart|OrderTopDown|SortContacts|StoreImpulses|"
     r"LimitEnergyGain|RecordAfter"),
    ("position correction (passes, guards, lift off static bodies)", r"CorrectPositions|GuardAfterMove"),
    ("move (positions, sines and cosines)", r"Stepper::Move|sincos|MakeRot|TurnsBeyondContacts|__sin|__cos"),
    ("sleep and waking islands", r"Stepper::Sleep|WakeIslands"),
    ("allocation, clearing and copying memory, page faults",
     r"malloc|free|operator new|operator delete|memset|memmove|memcpy|_M_realloc|_M_default_append|_M_fill|"
     r"uninit|_int_|^\[k\]|tcache|unlink_chunk"),
    ("transforms, boxes and contact lists (rest of FindContacts)", r"Stepper::FindContacts"),
    ("hypot, sqrt", r"hypot|sqrt"),
    ("loading the scene, printing", r"nlohmann|json|Scene|Parse|strto|mpn|printf|ostream|_dl_|strlen|memcmp"),
]


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit("usage: world_profile.py PERF.DATA [MS_PER_STEP]")
    step = float(sys.argv[2]) if len(sys.argv) == 3 else None
    report = subprocess.run(["perf", "report", "-i", sys.argv[1], "--no-children", "--sort", "sym", "--stdio",
                             "-g", "none", "--percent-limit", "0"], capture_output=True, text=True, check=True).stdout
    totals = {}
    for line in report.splitlines():
        m = re.match(r"\s+([0-9.]+)%\s+\[(.)\]\s+(.*)$", line)
        if not m:
            continue
        share, symbol = float(m.group(1)), ("[k] " if m.group(2) == "k" else "") + m.group(3)
        stage = next((name for name, pattern in STAGES if re.search(pattern, symbol)), "other")
        totals[stage] = totals.get(stage, 0.0) + share
    for name in [s for s, _ in STAGES] + ["other"]:
        share = totals.get(name, 0.0)
        print("%-72s %5.1f %%" % (name, share) + ("  %7.3f ms/step" % (share * step / 100.0) if step else ""))


if __name__ == "__main__":
    main()
