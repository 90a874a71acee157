#!/usr/bin/env python3
"""A benchmark row for the Python module's cheap call (a notebook loop, a property test):
groundtruth.run("erosion.thermal", 64x64 cone, backend="cpu", iterations=2) with quick=True
(pictures=False, descriptors=False, reps=0) beside the same call with the defaults. Prints the
median of REPS calls (default 21) after one warm-up, the size and the CPU, and their ratio.

Usage: /usr/bin/python3 scripts/bench-python-call.py [REPS]   (after scripts/setup.sh)
"""
import platform
import statistics
import sys
import time

import numpy

import groundtruth


def cone(side):
    coordinates = numpy.arange(side) + 0.5
    x, y = numpy.meshgrid(coordinates, coordinates)
    return numpy.maximum(0.0, 40.0 * (1.0 - numpy.hypot(x - side / 2, y - side / 2) / (0.4 * side)))


def median_ms(reps, **options):
    heights = cone(64)
    call = lambda: groundtruth.run("erosion.thermal", heights, backend="cpu", iterations=2, cell_size=1.0, **options)
    call()
    times = []
    for _ in range(reps):
        started = time.perf_counter()
        call()
        times.append(1000.0 * (time.perf_counter() - started))
    return statistics.median(times)


def cpu_name():
    try:
        with open("/proc/cpuinfo") as info:
            return next(line.split(":", 1)[1].strip() for line in info if line.startswith("model name"))
    except (OSError, StopIteration):
        return platform.processor() or "unknown CPU"


def main():
    reps = int(sys.argv[1]) if len(sys.argv) > 1 else 21
    quick = median_ms(reps, quick=True)
    default = median_ms(max(3, reps // 7))
    print(f"groundtruth.run erosion.thermal 64x64, 2 iterations, backend cpu, on {cpu_name()}")
    print(f"  quick=True   median {quick:8.1f} ms over {reps} calls")
    print(f"  defaults     median {default:8.1f} ms over {max(3, reps // 7)} calls")
    print(f"  ratio        {default / quick:8.1f}x")


if __name__ == "__main__":
    main()
