"""erosion.thermal in numpy, as a user would write it to have groundtruth grade it from Python:

    import groundtruth
    from thermal_numpy import thermal_step
    result = groundtruth.check(thermal_step, "erosion.thermal", heights, cell_size=10, iterations=40)
    result.status    # pass

Hydra's two-pass thermal erosion (seed 000 §4.4.3, Algorithms 9-11), written from the digest: per
cell and pipe (4 neighbours, cardinal on even iterations and diagonal on odd ones for the
alternating neighbourhood), the excess over the talus limit T·l (T = tan α, l the pipe's length),
a request per pipe scaled by f_s = strength/2, then the smaller of two opposite requests moves
along each pipe. Heights in metres (float64 here), NaN cells no-data; physical heights only.

`thermal_step_leaky` is the same with one subtle bug: pipes across the grid's border are open to
a neighbour at height 0, so material leaves the grid (mass.relative_drift.external catches it).
"""

import math

import numpy

CARDINAL = ((-1, 0), (0, 1), (1, 0), (0, -1))  # (dx, dy); pipe k and k + 2 point opposite ways
DIAGONAL = ((-1, -1), (-1, 1), (1, 1), (1, -1))


def _neighbour(values, dx, dy, outside):
    """values at (x + dx, y + dy), `outside` beyond the grid."""
    rows, columns = values.shape
    out = numpy.full_like(values, outside)
    out[max(0, -dy):rows - max(0, dy), max(0, -dx):columns - max(0, dx)] = \
        values[max(0, dy):rows - max(0, -dy), max(0, dx):columns - max(0, -dx)]
    return out


def _share(factor, largest, total, has):
    """clamp(f·largest/total, 0, 1) where `has`, else 0 (no division where total is 0)."""
    ratio = numpy.divide(factor * largest, total, out=numpy.zeros_like(total), where=has)
    return numpy.where(has, numpy.clip(ratio, 0.0, 1.0), 0.0)


def _step(state, params, border_height):
    heights = state["terrain"]
    dy, dx = params["spacing"]
    if params["normalised"]:
        raise ValueError("this example erodes physical heights only (normalised = false)")
    neighbourhood = params["neighbourhood"]
    cardinal = neighbourhood == "cardinal" or (neighbourhood == "alternating" and params["iteration"] % 2 == 0)
    pipes = CARDINAL if cardinal else DIAGONAL
    slope = math.tan(math.radians(params["talus_angle"]))
    lengths = (dx, dy, dx, dy) if cardinal else (math.hypot(dx, dy),) * 4
    factor = params["strength"] * 0.5
    demand, supply = [], []
    for (px, py), length in zip(pipes, lengths):
        limit = slope * length
        difference = _neighbour(heights, px, py, border_height) - heights  # NaN: no pipe
        demand.append(numpy.where(difference > limit, difference - limit, 0.0))
        supply.append(numpy.where(difference < -limit, difference + limit, 0.0))
    demand_total = ((demand[0] + demand[1]) + demand[2]) + demand[3]
    supply_total = ((supply[0] + supply[1]) + supply[2]) + supply[3]
    demand_share = _share(factor, numpy.maximum.reduce(demand), demand_total, demand_total > 0.0)
    supply_share = _share(factor, numpy.minimum.reduce(supply), supply_total, supply_total < 0.0)
    requests = [s * supply_share + d * demand_share for s, d in zip(supply, demand)]
    after = heights.copy()
    for k, (px, py) in enumerate(pipes):
        mine = requests[k]
        theirs = _neighbour(requests[(k + 2) % 4], px, py, numpy.nan)
        open_pipe = ~numpy.isnan(_neighbour(heights, px, py, border_height))
        gain = numpy.where(open_pipe & (theirs < 0.0) & (mine > 0.0), numpy.minimum(-theirs, mine), 0.0)
        loss = numpy.where(open_pipe & (theirs > 0.0) & (mine < 0.0), numpy.minimum(theirs, -mine), 0.0)
        if not numpy.isnan(border_height):  # the bug: what a cell offers across the border leaves
            loss = numpy.where(numpy.isnan(theirs) & (mine < 0.0), -mine, loss)
        after = numpy.where(gain > 0.0, after + gain, numpy.where(loss > 0.0, after - loss, after))
    return {"terrain": after}


def thermal_step(state, params):
    """One iteration of erosion.thermal: the state {"terrain": heights} after it."""
    return _step(state, params, border_height=numpy.nan)


def thermal_step_leaky(state, params):
    """The same, with the border open to a neighbour at height 0 (material lost there)."""
    return _step(state, params, border_height=0.0)
