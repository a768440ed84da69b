#!/usr/bin/env python3
"""Whether the layers of a three-layer sheet stay in order in every state of a run: no node of
the core beyond either skin's mid-surface (a core node passed through a skin), no node of a
skin beyond the core's mid-surface (a skin node passed through the core), no node of any layer
beyond the face of a tool given with --tools (a layer that slipped out from under the others
rising through the blank holder), and the adhesion intensity beta within [0, 1]. An
independent check of the contact: it reads the states' geometry (results_*.vtu), not the
contact's own gaps.

    /usr/bin/python3 layer_order.py OUTDIR --lower P --core P --upper P --reach R [--tools P ...]

Node ids are 100000 * part + k (the examples' generators). R: how far sideways from a node of
the other layer a node is still judged against it (half an element). A tool's side is the one
the blank's nodes over its face lie on in the first state; give flat tools (the holder): on a
coarsely faceted radius the nearest node's tangent plane cuts the facets. Exit 1 when the order
breaks in any state. Needs numpy and VTK (python3-vtk9).
"""

import argparse
import glob
import os
import sys

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy


def read_state(path):
    r = vtk.vtkXMLUnstructuredGridReader()
    r.SetFileName(path)
    r.Update()
    g = r.GetOutput()
    point = {g.GetPointData().GetArrayName(k): vtk_to_numpy(g.GetPointData().GetArray(k))
             for k in range(g.GetPointData().GetNumberOfArrays())}
    cell = {g.GetCellData().GetArrayName(k): vtk_to_numpy(g.GetCellData().GetArray(k))
            for k in range(g.GetCellData().GetNumberOfArrays())}
    x = vtk_to_numpy(g.GetPoints().GetData())
    conn = vtk_to_numpy(g.GetCells().GetConnectivityArray()).reshape(-1, 4)
    return x, point, cell, conn


def part_of_node(ids):
    """Node ids are 100000 * part + k (the examples' generators)."""
    return ids // 100000


def outward(x, quads):
    """For each node of the quads on a free edge (an edge of one quad only): the unit
    direction in the layer's plane pointing out of the layer there (away from its elements'
    centroids); zero for the nodes inside."""
    edges = {}
    for q in quads:
        for k in range(4):
            e = (min(q[k], q[(k + 1) % 4]), max(q[k], q[(k + 1) % 4]))
            edges[e] = edges.get(e, 0) + 1
    on_edge = np.zeros(len(x), dtype=bool)
    for (i, j), count in edges.items():
        if count == 1:
            on_edge[i] = on_edge[j] = True
    centroid = x[quads].mean(axis=1)
    inward = np.zeros_like(x)
    for k in range(4):
        np.add.at(inward, quads[:, k], centroid - x[quads[:, k]])
    out = np.where(on_edge[:, None], -inward, 0.0)
    length = np.linalg.norm(out, axis=1)
    out[length > 0] /= length[length > 0][:, None]
    return out


def beyond(x, part, cells, cell_part, movers, layer, sign, reach):
    """Nodes of part `movers` whose position lies beyond the mid-surface of part `layer` (on
    its side `sign`: +1 above its normal, -1 below)."""
    return int(np.sum(sign * over_face(x, part, cells, cell_part, movers, layer, reach) > 0.0))


def over_face(x, part, cells, cell_part, movers, layer, reach):
    """The signed distances of the nodes of part(s) `movers` that lie over the face of part
    `layer`: for each, the nearest node of the layer within `reach` sideways and the distance
    along the layer's nodal normal there (the mean of its elements' normals, which point from
    the lower layer to the upper). A mover beyond the layer's free edge, or within a tenth of
    `reach` of it, is not over the layer's face and is not judged: a skin that reaches past the
    core's edge bends round the core's edge face, which the mid-surface does not describe (the
    plain draw at 1.5 mm: two upper skin nodes at the core's edge, 0.32 mm below its
    mid-surface and 0.08 mm inside its edge)."""
    quads = cells[cell_part == layer]
    a, b = x[quads[:, 2]] - x[quads[:, 0]], x[quads[:, 3]] - x[quads[:, 1]]
    n_cell = np.cross(a, b)
    normal = np.zeros_like(x)
    for k in range(4):
        np.add.at(normal, quads[:, k], n_cell)
    out = outward(x, quads)
    nodes = np.where(part == layer)[0]
    nn = normal[nodes] / np.linalg.norm(normal[nodes], axis=1)[:, None]
    movers = np.where(np.isin(part, movers))[0]
    judged = []
    for chunk in np.array_split(movers, max(1, len(movers) // 256)):
        d = x[chunk][:, None, :] - x[nodes][None, :, :]
        nearest = np.argmin(np.einsum("ijk,ijk->ij", d, d), axis=1)
        rel = x[chunk] - x[nodes][nearest]
        along = np.einsum("ij,ij->i", rel, nn[nearest])
        side = np.linalg.norm(rel - along[:, None] * nn[nearest], axis=1)
        # Only a layer's edge nodes have an outward direction (zero inside).
        o = out[nodes][nearest]
        past_edge = (np.einsum("ij,ij->i", o, o) > 0.0) & (
            np.einsum("ij,ij->i", rel, o) > -0.1 * reach)
        judged.append(along[(side < reach) & ~past_edge])
    return np.concatenate(judged) if judged else np.zeros(0)


def crossings(x, ids, cells, cell_part, lower, core, upper, reach):
    """Nodes on the wrong side of a neighbouring layer's mid-surface, all four ways: the core's
    nodes above the upper skin or below the lower skin, the upper skin's below the core, the
    lower skin's above the core."""
    part = part_of_node(ids)
    return (beyond(x, part, cells, cell_part, core, upper, 1.0, reach) +
            beyond(x, part, cells, cell_part, core, lower, -1.0, reach) +
            beyond(x, part, cells, cell_part, upper, core, -1.0, reach) +
            beyond(x, part, cells, cell_part, lower, core, 1.0, reach))


def check(outdir, lower, core, upper, reach, report, tools=()):
    """Reports 'layers in order', 'layers under the tools' (with `tools`) and 'beta range' over
    every state of the run in OUTDIR."""
    paths = sorted(glob.glob(os.path.join(outdir, "results_*.vtu")))
    worst, when, bad_beta = 0, 0, 0
    tool_worst, tool_when, tool_side = 0, 0, {}
    blank = (lower, core, upper)
    for k, path in enumerate(paths):
        x, pd, cd, conn = read_state(path)
        ids, cell_part = pd["node_id"].astype(np.int64), cd["part"].astype(np.int64)
        c = crossings(x, ids, conn, cell_part, lower, core, upper, reach)
        if c > worst:
            worst, when = c, k
        for tool in tools:
            # A tool's mesh is coarser than the layers': a node is judged within half the
            # tool's largest element diagonal of the nearest tool node.
            q = conn[cell_part == tool]
            tool_reach = 0.5 * max(np.linalg.norm(x[q[:, 2]] - x[q[:, 0]], axis=1).max(),
                                   np.linalg.norm(x[q[:, 3]] - x[q[:, 1]], axis=1).max())
            along = over_face(x, part_of_node(ids), conn, cell_part, blank, tool, tool_reach)
            if tool not in tool_side and len(along):
                tool_side[tool] = 1.0 if np.median(along) > 0.0 else -1.0
            bad = int(np.sum(-tool_side.get(tool, 0.0) * along > 0.0))
            if bad > tool_worst:
                tool_worst, tool_when = bad, k
        if "beta" in pd:
            b = pd["beta"][np.isfinite(pd["beta"])]
            bad_beta += int(np.sum((b < 0.0) | (b > 1.0)))
    report("layers in order", worst == 0,
           f"at most {worst} nodes beyond a neighbouring layer's mid-surface (state {when}) over "
           f"{len(paths)} states")
    if tools:
        report("layers under the tools", tool_worst == 0,
               f"at most {tool_worst} nodes of the blank beyond the face of part(s) "
               f"{', '.join(map(str, tools))} (state {tool_when}) over {len(paths)} states")
    report("beta range", bad_beta == 0, f"{bad_beta} values outside [0, 1] in {len(paths)} states")


def main(argv):
    a = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    a.add_argument("outdir")
    a.add_argument("--lower", type=int, required=True)
    a.add_argument("--core", type=int, required=True)
    a.add_argument("--upper", type=int, required=True)
    a.add_argument("--reach", type=float, required=True)
    a.add_argument("--tools", type=int, nargs="*", default=[],
                   help="flat tools (parts) no layer may pass, the blank holder")
    args = a.parse_args(argv)
    failures = []

    def report(name, ok, text):
        print(f"{'ok  ' if ok else 'FAIL'} {name}: {text}")
        if not ok:
            failures.append(name)

    check(args.outdir, args.lower, args.core, args.upper, args.reach, report, args.tools)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
