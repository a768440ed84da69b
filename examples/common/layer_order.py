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
    `layer`, from its mid-surface, along its normal (which points from the lower layer to the
    upper), told two ways that must agree: from the tangent plane at the layer's nearest node
    (its nodal normal, the mean of its elements' normals), within `reach` sideways of that
    node; and from the nearest of the layer's elements, each quadrilateral as two triangles
    (the sign of the side of the nearest triangle's plane). Where the two disagree the node is
    counted as on neither side (0): each alone misjudged nodes at a coarse mesh's bends, the
    tangent plane a core node 0.33 mm inside the upper skin's elements (3.75 mm elements at
    the punch's corner: read 0.05 mm beyond), the nearest element a lower skin node beside a
    core element bent by 40 degrees over the die's corner. A node beyond the layer's free edge,
    or within a tenth of `reach` of it, is not over the layer's face and is not judged: a skin
    that reaches past the core's edge bends round the core's edge face, which the mid-surface
    does not describe (the plain draw at 1.5 mm: two upper skin nodes at the core's edge,
    0.32 mm below its mid-surface and 0.08 mm inside its edge)."""
    quads = cells[cell_part == layer]
    n_quad = np.cross(x[quads[:, 2]] - x[quads[:, 0]], x[quads[:, 3]] - x[quads[:, 1]])
    normal = np.zeros_like(x)
    for k in range(4):
        np.add.at(normal, quads[:, k], n_quad)
    tri = np.concatenate([quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]])
    n_tri = np.cross(x[tri[:, 1]] - x[tri[:, 0]], x[tri[:, 2]] - x[tri[:, 0]])
    n_tri *= np.sign(np.einsum("ij,ij->i", n_tri, np.concatenate([n_quad, n_quad])))[:, None]
    n_tri /= np.linalg.norm(n_tri, axis=1)[:, None]
    centre = x[tri].mean(axis=1)
    out = outward(x, quads)
    nodes = np.where(part == layer)[0]
    nn = normal[nodes] / np.linalg.norm(normal[nodes], axis=1)[:, None]
    movers = np.where(np.isin(part, movers))[0]
    nearest_k = min(8, len(tri))
    judged = []
    for chunk in np.array_split(movers, max(1, len(movers) // 256)):
        p = x[chunk]
        rows = np.arange(len(chunk))
        # The tangent plane at the nearest node.
        dn = x[chunk][:, None, :] - x[nodes][None, :, :]
        nearest = np.argmin(np.einsum("ijk,ijk->ij", dn, dn), axis=1)
        rel = p - x[nodes][nearest]
        along = np.einsum("ij,ij->i", rel, nn[nearest])
        side = np.linalg.norm(rel - along[:, None] * nn[nearest], axis=1)
        # Only a layer's edge nodes have an outward direction (zero inside).
        o = out[nodes][nearest]
        past_edge = (np.einsum("ij,ij->i", o, o) > 0.0) & (
            np.einsum("ij,ij->i", rel, o) > -0.1 * reach)
        # The nearest triangle (of the eight with the nearest centroids): the distance to its
        # plane where the foot lies on it, else to its nearest edge point.
        d2 = np.einsum("ijk,ijk->ij", p[:, None, :] - centre[None], p[:, None, :] - centre[None])
        near = np.argpartition(d2, nearest_k - 1, axis=1)[:, :nearest_k]
        a, b, c = x[tri[near, 0]], x[tri[near, 1]], x[tri[near, 2]]
        n = n_tri[near]
        height = np.einsum("ijk,ijk->ij", p[:, None, :] - a, n)
        foot = p[:, None, :] - height[..., None] * n
        v0, v1, v2 = b - a, c - a, foot - a
        d00, d01, d11 = (np.einsum("ijk,ijk->ij", u, w) for u, w in ((v0, v0), (v0, v1), (v1, v1)))
        d20, d21 = np.einsum("ijk,ijk->ij", v2, v0), np.einsum("ijk,ijk->ij", v2, v1)
        den = d00 * d11 - d01 * d01
        v = (d11 * d20 - d01 * d21) / den
        w = (d00 * d21 - d01 * d20) / den
        inside = np.minimum(np.minimum(v, w), 1.0 - v - w) >= 0.0
        edge = np.full(height.shape, np.inf)
        for e0, e1 in ((a, b), (b, c), (c, a)):
            t = np.clip(np.einsum("ijk,ijk->ij", p[:, None, :] - e0, e1 - e0) /
                        np.einsum("ijk,ijk->ij", e1 - e0, e1 - e0), 0.0, 1.0)
            q = e0 + t[..., None] * (e1 - e0) - p[:, None, :]
            edge = np.minimum(edge, np.einsum("ijk,ijk->ij", q, q))
        best = np.argmin(np.where(inside, height * height, edge), axis=1)
        facet = height[rows, best]
        agreed = np.where(along * facet > 0.0, along, 0.0)
        judged.append(agreed[(side < reach) & ~past_edge])
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


def tool_crossings(x, ids, cells, cell_part, blank, tool, side=None):
    """Nodes of the parts `blank` beyond the face of the flat tool part `tool`, and the side
    (+1 or -1 along the tool's nodal normals) the blank lies on: `side`, or where none is
    given yet the side most of the blank's nodes over the tool's face lie on now (None while
    none is over it). A tool's mesh is coarser than the layers': a node is judged within half
    the tool's largest element diagonal of the nearest tool node."""
    q = cells[cell_part == tool]
    reach = 0.5 * max(np.linalg.norm(x[q[:, 2]] - x[q[:, 0]], axis=1).max(),
                      np.linalg.norm(x[q[:, 3]] - x[q[:, 1]], axis=1).max())
    along = over_face(x, part_of_node(ids), cells, cell_part, blank, tool, reach)
    if side is None and len(along):
        side = 1.0 if np.median(along) > 0.0 else -1.0
    return (int(np.sum(-side * along > 0.0)) if side is not None else 0), side


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
            bad, tool_side[tool] = tool_crossings(x, ids, conn, cell_part, blank, tool,
                                                  tool_side.get(tool))
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
