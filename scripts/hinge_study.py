#!/usr/bin/env python3
"""Air bending of a plastic strip by a rigid punch of radius R, for the hinge-resolution study
of docs/shells.md: writes one deck per element size.

    hinge_study.py OUTDIR --radius 5 --sizes 10 5 2.5 1.25 [--elform 2|16]

A strip 100 x 10 x 1 mm (*MAT_024: sigma_y 200 MPa, E_tan 1 GPa; mm, tonne, s) on rollers at
x = 0 and 100 (pinned at x = 0), a rigid half cylinder of radius R (48 facets over 180
degrees) over its middle pushed down 20 mm in 20 ms; --ihq gives the strip a *HOURGLASS. Run each deck with
`plyform run DECK -o OUT --threads 1` and compare external work and internal energy at the end
(OUT/glstat.csv).
"""
import argparse
import math
import os


def deck(radius, h, elform, ihq):
    nx = round(100 / h)
    ny = max(1, round(10 / h))
    lines = ["*KEYWORD", "*TITLE", f"air bend R {radius} h {h} ELFORM {elform}",
             "*CONTROL_TERMINATION", "0.02", "*DATABASE_GLSTAT", "2.0e-4", "*NODE"]
    nid = 1
    for j in range(ny + 1):
        for i in range(nx + 1):
            lines.append(f"{nid},{100.0 * i / nx},{10.0 * j / ny},0.0")
            nid += 1
    tool0 = nid
    facets = 48
    for j in range(2):
        for k in range(facets + 1):
            a = math.pi * k / facets
            lines.append(f"{nid},{50.0 - radius * math.cos(a)},{-2.0 + 14.0 * j},"
                         f"{1.05 + radius * (1.0 - math.sin(a))}")
            nid += 1
    lines.append("*ELEMENT_SHELL")
    eid = 1
    for j in range(ny):
        for i in range(nx):
            a = 1 + j * (nx + 1) + i
            lines.append(f"{eid},1,{a},{a + 1},{a + nx + 2},{a + nx + 1}")
            eid += 1
    for k in range(facets):
        a = tool0 + k
        lines.append(f"{eid},2,{a},{a + facets + 1},{a + facets + 2},{a + 1}")
        eid += 1
    lines += ["*PART", "strip", f"1,1,1,0,{1 if ihq else 0}", "*PART", "punch", "2,2,2",
              "*SECTION_SHELL", f"1,{elform},1.0,5", "1.0,1.0,1.0,1.0",
              "*SECTION_SHELL", "2,2,1.0,3", "1.0,1.0,1.0,1.0",
              "*MAT_PIECEWISE_LINEAR_PLASTICITY", "1,7.85e-9,210000.0,0.3,200.0,1000.0", "", "", "",
              "*MAT_RIGID", "2,7.85e-9,210000.0,0.3", "1.0,4,7",
              *(["*HOURGLASS", f"1,{ihq},0.1"] if ihq else []),
              "*CONTACT_AUTOMATIC_SINGLE_SURFACE", "0,0,0,0", "0.0,0.0", "",
              "*DEFINE_CURVE", "1", "0.0,0.0", "0.02,-20.0", "1.0,-20.0",
              "*BOUNDARY_PRESCRIBED_MOTION_RIGID", "2,3,2,1,1.0",
              "*BOUNDARY_SPC_NODE"]
    for j in range(ny + 1):
        left = 1 + j * (nx + 1)
        lines.append(f"{left},0,1,{1 if j == 0 else 0},1,0,0,0")
        lines.append(f"{left + nx},0,0,0,1,0,0,0")
    lines.append("*END")
    return "\n".join(lines) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("outdir")
    ap.add_argument("--radius", type=float, default=5.0)
    ap.add_argument("--sizes", type=float, nargs="+", default=[10.0, 5.0, 2.5, 1.25])
    ap.add_argument("--elform", type=int, default=2)
    ap.add_argument("--ihq", type=int, default=0, help="*HOURGLASS IHQ of the strip (0: default)")
    a = ap.parse_args()
    os.makedirs(a.outdir, exist_ok=True)
    for h in a.sizes:
        tag = f"_ihq{a.ihq}" if a.ihq else ""
        path = os.path.join(a.outdir, f"airbend_R{a.radius:g}_h{h:g}_e{a.elform}{tag}.k")
        with open(path, "w") as f:
            f.write(deck(a.radius, h, a.elform, a.ihq))
        print(path)


if __name__ == "__main__":
    main()
