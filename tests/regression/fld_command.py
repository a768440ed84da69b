#!/usr/bin/python3
"""`plyform plot OUTDIR --fld` end to end, and its categories against their definitions.

    fld_command.py PLYFORM WORKDIR

1. The category rules and Keeler-Brazier's curve of scripts/plot_fld.py at hand-picked strain
   points (docs/outputs.md, "Formability"): FLD0 = (23.3 + 14.13 t) n / 0.21 percent, the left
   side FLD0 - minor in true strains, the right side 0.6 in engineering strains; cracks on and
   above the FLC, risk of cracks within the margin below it, then from the mid-surface: low
   strain, wrinkling tendency beyond uniaxial compression, thickening, safe.
2. A 3 x 3 patch of J2 shells pulled to ln(L / L0) = 0.3 in uniaxial tension (minor -0.15),
   judged with Keeler's curve for n = 0.21, 0.10, 0.05 (t = 1 mm): its FLC at minor -0.15 is
   0.468, 0.314, 0.235, so every shell is safe, at risk of cracks, cracked; fld.png and
   formability.png are PNGs of real figures and fld.csv's flc_distance is major - FLC; a curve
   file (a header, then minor, major) flat at 0.25 cracks them too.
3. Bad calls exit non-zero with a message naming the option or file: no curve, two curves,
   half of Keeler's, a missing or unreadable curve file, --flc without --fld, a folder without
   states, a run without shells, a state that is not there.
Exits 77 (ctest: skipped) when /usr/bin/python3 lacks matplotlib, numpy or vtk.
"""

import csv
import importlib.util
import math
import os
import shutil
import subprocess
import sys

MISSING = [m for m in ("numpy", "matplotlib", "vtkmodules")
           if importlib.util.find_spec(m) is None]
if MISSING:
    print(f"fld_command.py: skipped: {sys.executable} has no {', '.join(MISSING)}")
    sys.exit(77)
import numpy as np  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPT = os.path.join(HERE, "..", "..", "scripts", "plot_fld.py")


def check(condition, message):
    if not condition:
        print(f"fld_command.py: FAIL: {message}", file=sys.stderr)
        sys.exit(1)


def load_script():
    spec = importlib.util.spec_from_file_location("plot_fld", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def keeler_closed_form(n, t, minor):
    fld0 = (23.3 + 14.13 * t) * n / 0.21 / 100.0
    if minor <= 0.0:
        return math.log1p(fld0) - minor
    return math.log1p(fld0 + 0.6 * math.expm1(minor))


def check_rules(fld):
    flc = fld.keeler_flc(0.2, 1.2)
    for minor in (-0.3, -0.1, 0.0, 0.05, 0.2, 0.4):
        got, want = float(flc(minor)), keeler_closed_form(0.2, 1.2, minor)
        check(abs(got - want) < 1e-14, f"Keeler FLC at minor {minor}: {got} != {want}")
    fld0 = keeler_closed_form(0.2, 1.2, 0.0)
    # (label, top (minor, major), bottom (minor, major), middle (minor, major), category)
    cases = [
        ("above the FLC on the bottom only", (-0.1, 0.2), (-0.1, fld0 + 0.11), (-0.1, 0.2),
         "cracks"),
        ("on the FLC", (0.0, float(flc(0.0))), (0.0, fld0 - 0.3), (0.0, 0.2), "cracks"),
        ("within the margin", (-0.2, fld0 + 0.2 - 0.05), (-0.2, 0.1), (-0.2, 0.2),
         "risk of cracks"),
        ("just past the margin", (0.0, fld0 - 0.1001), (0.0, 0.0), (0.0, 0.1), "safe"),
        ("stretched a little", (0.005, 0.01), (0.005, 0.01), (0.005, 0.01), "low strain"),
        ("compressed a little", (-0.015, 0.005), (-0.015, 0.005), (-0.015, 0.005), "low strain"),
        ("drawn: thicker, beyond pure shear", (-0.2, 0.15), (-0.2, 0.15), (-0.2, 0.15),
         "thickening"),
        ("beyond uniaxial compression", (-0.2, 0.05), (-0.2, 0.05), (-0.2, 0.05),
         "wrinkling tendency"),
        ("bent: the inside compressed, the middle stretched", (-0.3, 0.0), (0.0, 0.2),
         (0.0, 0.1), "safe"),
        ("uniaxial tension", (-0.1, 0.2), (-0.1, 0.2), (-0.1, 0.2), "safe"),
    ]
    s = {f: np.array([]) for f in fld.FIELDS}
    for surface, k in (("top", 1), ("bottom", 2), ("middle", 3)):
        s[f"minor_strain_{surface}"] = np.array([c[k][0] for c in cases])
        s[f"major_strain_{surface}"] = np.array([c[k][1] for c in cases])
    names, distance = fld.classify(s, flc, 0.1, 0.02)
    for c, name in zip(cases, names):
        check(name == c[4], f"{c[0]}: {name}, expected {c[4]}")
    check(abs(distance[1]) < 1e-15, f"the FLC distance on the curve is {distance[1]}")
    print(f"fld_command.py: {len(cases)} category cases and the Keeler curve ok")


def patch_deck(path, solid=False):
    """A 3 x 3 patch of 10 mm J2 shells pulled along x to ln(L / L0) = 0.3 (free sides), or one
    elastic hexahedron (no shells)."""
    end = 5.0e-3
    lines = ["*KEYWORD", "*CONTROL_TERMINATION", f"{end},", "*DATABASE_BINARY_D3PLOT",
             f"{end / 2},", "*DEFINE_CURVE", "1,"]
    for k in range(21):
        s = k / 20.0
        lines.append(f"{0.9 * end * s!r},{s * s * (3.0 - 2.0 * s)!r}")
    lines.append(f"{end},1.0")
    if solid:
        lines += ["*PART", "cube", "1,1,1", "*SECTION_SOLID", "1,1", "*MAT_ELASTIC",
                  "1,7.85e-9,210000.0,0.3", "*NODE"]
        for k in range(8):
            lines.append(f"{k + 1},{k % 2},{(k // 2) % 2},{k // 4}")
        lines += ["*ELEMENT_SOLID", "1,1,1,2,4,3,5,6,8,7", "*END"]
    else:
        lines += ["*PART", "sheet", "1,1,1", "*SECTION_SHELL", "1,2,0.8333,3", "1.0,1.0,1.0,1.0",
                  "*MAT_PLASTIC_KINEMATIC", "1,7.85e-9,210000.0,0.3,100.0,600.0,1.0", "*NODE"]
        nid = lambda i, j: 1 + i + 4 * j  # noqa: E731
        for j in range(4):
            for i in range(4):
                lines.append(f"{nid(i, j)},{10.0 * i},{10.0 * j},0.0")
        lines.append("*ELEMENT_SHELL")
        for j in range(3):
            for i in range(3):
                lines.append(f"{1 + i + 3 * j},1,{nid(i, j)},{nid(i + 1, j)},{nid(i + 1, j + 1)},"
                             f"{nid(i, j + 1)}")
        lines.append("*BOUNDARY_SPC_NODE")
        for j in range(4):
            for i in range(4):
                lines.append(f"{nid(i, j)},0,{int(i == 0)},{int(i == 0 and j == 0)},1,1,1,1")
        lines.append("*BOUNDARY_PRESCRIBED_MOTION_NODE")
        for j in range(4):
            lines.append(f"{nid(3, j)},1,2,1,{30.0 * (math.exp(0.3) - 1.0)!r}")
        lines.append("*END")
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")


def run(args, expect_ok=True, message=None):
    p = subprocess.run(args, capture_output=True, text=True, timeout=120)
    if expect_ok:
        check(p.returncode == 0, f"{' '.join(args)} exited {p.returncode}: {p.stderr}")
    else:
        check(p.returncode != 0, f"{' '.join(args)} succeeded; expected an error")
        check(message in p.stderr,
              f"{' '.join(args)}: the message does not say '{message}':\n{p.stderr}")
    return p


def is_png(path, least=20000):
    with open(path, "rb") as f:
        head = f.read(8)
    return head == b"\x89PNG\r\n\x1a\n" and os.path.getsize(path) >= least


def read_fld_csv(path):
    with open(path, newline="", encoding="utf-8") as f:
        return list(csv.DictReader(f))


def main(argv):
    if len(argv) != 2:
        sys.exit(__doc__)
    plyform, work = argv
    check_rules(load_script())
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    deck = os.path.join(work, "patch.k")
    patch_deck(deck)
    out = os.path.join(work, "patch_out")
    run([plyform, "run", deck, "-o", out])
    for n, want in ((0.21, "safe"), (0.10, "risk of cracks"), (0.05, "cracks")):
        for f in ("fld.png", "formability.png", "fld.csv"):
            if os.path.exists(os.path.join(out, f)):
                os.remove(os.path.join(out, f))
        run([plyform, "plot", out, "--fld", "--keeler-n", str(n), "--keeler-t", "1"])
        for png in ("fld.png", "formability.png"):
            check(is_png(os.path.join(out, png)), f"n = {n}: {png} is not a PNG of a figure")
        rows = read_fld_csv(os.path.join(out, "fld.csv"))
        check(len(rows) == 9, f"n = {n}: fld.csv has {len(rows)} shells, expected 9")
        for r in rows:
            check(r["category"] == want, f"n = {n}: element {r['element']} is {r['category']}, "
                                         f"expected {want}")
            worst = max(float(r[f"major_strain_{s}"]) -
                        keeler_closed_form(n, 1.0, float(r[f"minor_strain_{s}"]))
                        for s in ("top", "bottom"))
            check(abs(float(r["flc_distance"]) - worst) < 1e-9,
                  f"n = {n}: flc_distance {r['flc_distance']} != {worst}")
        r = rows[4]
        print(f"fld_command.py: n = {n}: {want}; element 5 minor {float(r['minor_strain_top']):.4f}"
              f" major {float(r['major_strain_top']):.4f}, FLC distance "
              f"{float(r['flc_distance']):.4f}")
    curve = os.path.join(work, "flat.csv")
    with open(curve, "w", encoding="utf-8") as f:
        f.write("minor,major\n-0.4,0.25\n0.0,0.25\n0.4,0.25\n")
    run([plyform, "plot", out, "--fld", "--flc", curve, "--state", "2"])
    rows = read_fld_csv(os.path.join(out, "fld.csv"))
    check(all(r["category"] == "cracks" for r in rows),
          "a flat FLC at 0.25 leaves shells uncracked")

    # Bad calls.
    bad = os.path.join(work, "bad.csv")
    with open(bad, "w", encoding="utf-8") as f:
        f.write("0.0,0.3\n0.1 zero\n")
    empty = os.path.join(work, "empty")
    os.makedirs(empty)
    solid_deck = os.path.join(work, "cube.k")
    patch_deck(solid_deck, solid=True)
    cube = os.path.join(work, "cube_out")
    run([plyform, "run", solid_deck, "-o", cube])
    cases = [
        ([out, "--fld"], "needs a forming-limit curve"),
        ([out, "--fld", "--flc", curve, "--keeler-n", "0.2", "--keeler-t", "1"], "not both"),
        ([out, "--fld", "--keeler-n", "0.2"], "--keeler-t is missing"),
        ([out, "--fld", "--flc", os.path.join(work, "none.csv")], "none.csv' does not exist"),
        ([out, "--fld", "--flc", bad], "bad.csv:2: '0.1 zero' is not two numbers"),
        ([out, "--flc", curve], "--flc requires --fld"),
        ([empty, "--fld", "--flc", curve], "no state in"),
        ([cube, "--fld", "--flc", curve], "no deformable shell"),
        ([out, "--fld", "--flc", curve, "--state", "7"], "--state 7: no results_0007.vtu"),
    ]
    for args, message in cases:
        run([plyform, "plot"] + args, expect_ok=False, message=message)
    print(f"fld_command.py: {len(cases)} bad calls refused by name; ok")


if __name__ == "__main__":
    main(sys.argv[1:])
