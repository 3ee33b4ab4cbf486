#!/usr/bin/env python3
"""Hides most of chosen scans of a CARMEN log behind people round the robot.

    crowd_scans.py IN OUT FIRST:LAST [FIRST:LAST...] [--seed N]

Each FLASER scan numbered FIRST to LAST (from 0) gets five people at random
bearings across its 180 degrees, 0.5-1.2 m away, each a body 0.5 m wide: the
readings behind a body become its distance. Prints on stderr how many of the
crowded scans' readings were hidden."""
import math
import random
import sys

args = sys.argv[1:]
seed = 1
if "--seed" in args:
    at = args.index("--seed")
    seed = int(args[at + 1])
    del args[at:at + 2]
source, target, spans = args[0], args[1], [tuple(map(int, s.split(":"))) for s in args[2:]]
rng = random.Random(seed)
hidden = total = 0
scan = -1
with open(source) as log, open(target, "w") as out:
    for line in log:
        fields = line.split()
        if fields and fields[0] == "FLASER":
            scan += 1
            if any(first <= scan <= last for first, last in spans):
                count = int(fields[1])
                ranges = [float(v) for v in fields[2:2 + count]]
                for _ in range(5):
                    bearing = rng.uniform(0.0, math.pi)
                    distance = rng.uniform(0.5, 1.2)
                    half_width = math.asin(0.25 / distance)
                    for i in range(count):
                        if abs(math.pi * i / (count - 1) - bearing) < half_width and distance < ranges[i]:
                            ranges[i] = distance
                hidden += sum(1 for new, old in zip(ranges, fields[2:2 + count]) if new != float(old))
                total += count
                fields[2:2 + count] = ["%.3f" % r for r in ranges]
                line = " ".join(fields) + "\n"
        out.write(line)
print("hid %d of %d readings" % (hidden, total), file=sys.stderr)
