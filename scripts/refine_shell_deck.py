#!/usr/bin/env python3
"""Split the shells of chosen parts of an LS-DYNA deck n x n, for mesh studies.

    refine_shell_deck.py DECK OUT --parts 1 --split 2 [--elform 16] [--nip 5]

Each quadrilateral of the parts becomes n x n quadrilaterals by its bilinear map (exact for a
flat element); nodes on shared edges are made once. A node set (*SET_NODE_LIST) gains the new
nodes that lie on an edge whose two ends are both in the set, so a clamped line stays a
clamped line. *DATABASE_HISTORY_SHELL (element ids that no longer exist) is dropped.
--elform / --nip rewrite the first card of every *SECTION_SHELL that a refined part uses.

The deck must be a single file in fixed format (*NODE 8+16+16+16, *ELEMENT_SHELL 8 x 6), as
LS-PrePost writes it; it is the mesh study's tool (docs/shells.md), not a general mesher.
"""

import argparse
import sys


def cards(lines, start):
    """Indices of the data lines of the keyword block starting at `start` (comments skipped)."""
    out = []
    i = start + 1
    while i < len(lines) and not lines[i].startswith("*"):
        if not lines[i].startswith("$") and lines[i].strip():
            out.append(i)
        i += 1
    return out, i


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("deck")
    ap.add_argument("out")
    ap.add_argument("--parts", type=int, nargs="+", required=True)
    ap.add_argument("--split", type=int, required=True)
    ap.add_argument("--elform", type=int)
    ap.add_argument("--nip", type=int)
    a = ap.parse_args()
    n = a.split
    lines = open(a.deck, encoding="latin-1").read().splitlines()
    keys = [(i, l.split()[0].upper()) for i, l in enumerate(lines) if l.startswith("*")]

    nodes = {}
    shells = []  # (eid, pid, [n1..n4])
    node_block = shell_block = None
    sections = {}
    part_section = {}
    for i, k in keys:
        if k == "*NODE":
            idx, end = cards(lines, i)
            node_block = (i, end)
            for j in idx:
                s = lines[j]
                nodes[int(s[0:8])] = (float(s[8:24]), float(s[24:40]), float(s[40:56]))
        elif k == "*ELEMENT_SHELL":
            idx, end = cards(lines, i)
            shell_block = (i, end)
            for j in idx:
                s = lines[j]
                f = [int(s[8 * c:8 * c + 8]) for c in range(6)]
                shells.append((f[0], f[1], f[2:6]))
        elif k.startswith("*SECTION_SHELL"):
            idx, _ = cards(lines, i)
            idx = idx[1:] if k.endswith("_TITLE") else idx
            sections[int(lines[idx[0]][0:10])] = idx[0]
        elif k == "*PART":
            idx, _ = cards(lines, i)
            for t in range(0, len(idx) - 1, 2):  # title, then the card
                s = lines[idx[t + 1]]
                part_section[int(s[0:10])] = int(s[10:20])
    if node_block is None or shell_block is None:
        sys.exit("the deck has no *NODE or no *ELEMENT_SHELL block")

    next_node = max(nodes) + 1
    next_elem = max(e for e, _, _ in shells) + 1
    by_position = {}
    edge_nodes = {}  # (a, b) sorted corner ids -> the new nodes on that edge

    def node_at(x, y, z, edge):
        nonlocal next_node
        key = (round(x, 9), round(y, 9), round(z, 9))
        if key in by_position:
            nid = by_position[key]
        else:
            nid = next_node
            next_node += 1
            nodes[nid] = (x, y, z)
            by_position[key] = nid
        if edge is not None:
            edge_nodes.setdefault(edge, set()).add(nid)
        return nid

    for nid, p in nodes.items():
        by_position[(round(p[0], 9), round(p[1], 9), round(p[2], 9))] = nid
    new_shells = []
    for eid, pid, c in shells:
        if pid not in a.parts:
            new_shells.append((eid, pid, c))
            continue
        if c[2] == c[3]:
            sys.exit(f"element {eid}: triangles are not split by this script")
        p = [nodes[k] for k in c]
        grid = {}
        for j in range(n + 1):
            for i in range(n + 1):
                if (i in (0, n)) and (j in (0, n)):
                    grid[i, j] = c[{(0, 0): 0, (n, 0): 1, (n, n): 2, (0, n): 3}[i, j]]
                    continue
                u, v = i / n, j / n
                w = ((1 - u) * (1 - v), u * (1 - v), u * v, (1 - u) * v)
                x = [sum(w[k] * p[k][d] for k in range(4)) for d in range(3)]
                edge = None
                if j == 0:
                    edge = tuple(sorted((c[0], c[1])))
                elif i == n:
                    edge = tuple(sorted((c[1], c[2])))
                elif j == n:
                    edge = tuple(sorted((c[2], c[3])))
                elif i == 0:
                    edge = tuple(sorted((c[3], c[0])))
                grid[i, j] = node_at(*x, edge)
        first = True
        for j in range(n):
            for i in range(n):
                quad = [grid[i, j], grid[i + 1, j], grid[i + 1, j + 1], grid[i, j + 1]]
                new_shells.append((eid if first else next_elem, pid, quad))
                if not first:
                    next_elem += 1
                first = False

    refined_sections = {part_section[p] for p in a.parts if p in part_section}
    for sid in refined_sections:
        j = sections[sid]
        row = lines[j]
        fields = [row[10 * c:10 * c + 10] for c in range(8)]
        if a.elform is not None:
            fields[1] = f"{a.elform:10d}"
        if a.nip is not None:
            fields[3] = f"{a.nip:10d}"
        new_row = "".join(fields)
        lines[j] = new_row
    out = []
    skip_to = -1
    for i, line in enumerate(lines):
        if i < skip_to:
            continue
        key = line.split()[0].upper() if line.startswith("*") else None
        if key == "*DATABASE_HISTORY_SHELL":
            _, skip_to = cards(lines, i)
            continue
        if i == shell_block[0]:
            out.append(line)
            out.extend(f"{e:8d}{p:8d}" + "".join(f"{k:8d}" for k in q) for e, p, q in new_shells)
            skip_to = shell_block[1]
            continue
        if i == node_block[0]:
            out.append(line)
            for nid in sorted(nodes):
                x, y, z = nodes[nid]
                out.append(f"{nid:8d}{x:16.9g}{y:16.9g}{z:16.9g}")
            skip_to = node_block[1]
            continue
        if key is not None and key.startswith("*SET_NODE_LIST"):
            idx, end = cards(lines, i)
            idx = idx[1:] if key.endswith("_TITLE") else idx
            members = set()
            for j in idx[1:]:
                s = lines[j]
                members.update(int(s[10 * c:10 * c + 10]) for c in range(8) if s[10 * c:10 * c + 10].strip())
            members.discard(0)
            added = set()
            for (ea, eb), mids in edge_nodes.items():
                if ea in members and eb in members:
                    added |= mids
            ids = sorted(members | added)
            out.extend(lines[i:idx[1]])
            for t in range(0, len(ids), 8):
                out.append("".join(f"{k:10d}" for k in ids[t:t + 8]))
            skip_to = end
            continue
        out.append(line)

    open(a.out, "w").write("\n".join(out) + "\n")
    print(f"{a.out}: {len(new_shells)} shells, {len(nodes)} nodes")


if __name__ == "__main__":
    main()
