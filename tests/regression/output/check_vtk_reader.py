#!/usr/bin/python3
"""Reads what output_vtk_fixture wrote with VTK's own readers and compares every value.

Usage: check_vtk_reader.py FIXTURE_PROGRAM OUTDIR
Runs FIXTURE_PROGRAM OUTDIR, then reads OUTDIR/results_000N.vtu with
vtkXMLUnstructuredGridReader and OUTDIR/results.pvd with ElementTree and vtkXMLDataParser
(and vtkXMLCollectionReader where the VTK build has it),
and checks coordinates, arrays, ids, cell types and connectivity bit for bit against
OUTDIR/expected.json; also that OUTDIR/summary.json is valid JSON. Exit 77 without VTK.
"""
import json
import math
import os
import struct
import subprocess
import sys
import xml.etree.ElementTree as ET

try:
    import vtk
except ImportError:
    print("python3-vtk9 is not installed for", sys.executable)
    sys.exit(77)

failures = []
checks = [0]


def check(condition, message):
    checks[0] += 1
    if not condition:
        failures.append(message)


def same(a, b):
    """Bit-for-bit equality of doubles; b None stands for NaN."""
    if b is None:
        return math.isnan(a)
    return struct.pack("<d", a) == struct.pack("<d", float(b))


class Errors:
    def __init__(self):
        self.messages = []

    def __call__(self, caller, event):
        self.messages.append(f"{event} from {caller.GetClassName()}")


def read_vtu(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    errors = Errors()
    reader.AddObserver("ErrorEvent", errors)
    reader.AddObserver("WarningEvent", errors)
    reader.SetFileName(path)
    reader.Update()
    check(not errors.messages, f"{path}: reader reported {errors.messages}")
    return reader.GetOutput()


def check_float_array(where, array, components, values):
    check(array is not None, f"{where}: array missing")
    if array is None:
        return
    check(array.GetDataType() == vtk.VTK_DOUBLE, f"{where}: not Float64 ({array.GetDataTypeAsString()})")
    check(array.GetNumberOfComponents() == components,
          f"{where}: {array.GetNumberOfComponents()} components, expected {components}")
    check(array.GetNumberOfTuples() * components == len(values),
          f"{where}: {array.GetNumberOfTuples()} tuples, expected {len(values) // components}")
    for i, expected in enumerate(values):
        got = array.GetComponent(i // components, i % components)
        check(same(got, expected), f"{where}[{i}]: {got!r} != {expected!r}")


def check_id_array(where, array, values):
    check(array is not None, f"{where}: array missing")
    if array is None:
        return
    check(array.GetDataTypeSize() == 8 and array.GetDataType() in (vtk.VTK_LONG_LONG, vtk.VTK_LONG,
                                                                      vtk.VTK_ID_TYPE),
          f"{where}: not Int64 ({array.GetDataTypeAsString()})")
    check(array.GetNumberOfTuples() == len(values) and array.GetNumberOfComponents() == 1,
          f"{where}: shape {array.GetNumberOfTuples()} x {array.GetNumberOfComponents()}")
    for i, expected in enumerate(values):
        got = array.GetValue(i)
        check(got == expected, f"{where}[{i}]: {got} != {expected}")


def check_grid(where, grid, state):
    n = len(state["x"])
    types = state["types"]
    check(grid.GetNumberOfPoints() == n, f"{where}: {grid.GetNumberOfPoints()} points, expected {n}")
    check(grid.GetNumberOfCells() == len(types),
          f"{where}: {grid.GetNumberOfCells()} cells, expected {len(types)}")
    check(grid.GetPoints().GetDataType() == vtk.VTK_DOUBLE, f"{where}: points not Float64")
    for p in range(min(n, grid.GetNumberOfPoints())):
        got = grid.GetPoint(p)
        for c, axis in enumerate("xyz"):
            check(same(got[c], state[axis][p]), f"{where}: point {p} {axis} {got[c]!r} != {state[axis][p]!r}")
    ids = vtk.vtkIdList()
    start = 0
    for c in range(min(len(types), grid.GetNumberOfCells())):
        check(grid.GetCellType(c) == types[c], f"{where}: cell {c} type {grid.GetCellType(c)} != {types[c]}")
        grid.GetCellPoints(c, ids)
        got = [ids.GetId(k) for k in range(ids.GetNumberOfIds())]
        expected = state["connectivity"][start:state["offsets"][c]]
        check(got == expected, f"{where}: cell {c} points {got} != {expected}")
        start = state["offsets"][c]
    pd, cd = grid.GetPointData(), grid.GetCellData()
    for name, (components, values) in state["point_data"].items():
        check_float_array(f"{where}: point array {name}", pd.GetArray(name), components, values)
    for name, (components, values) in state["cell_data"].items():
        check_float_array(f"{where}: cell array {name}", cd.GetArray(name), components, values)
    for name, values in state["point_ids"].items():
        check_id_array(f"{where}: point ids {name}", pd.GetArray(name), values)
    for name, values in state["cell_ids"].items():
        check_id_array(f"{where}: cell ids {name}", cd.GetArray(name), values)
    check(pd.GetNumberOfArrays() == len(state["point_data"]) + len(state["point_ids"]),
          f"{where}: {pd.GetNumberOfArrays()} point arrays")
    check(cd.GetNumberOfArrays() == len(state["cell_data"]) + len(state["cell_ids"]),
          f"{where}: {cd.GetNumberOfArrays()} cell arrays")
    time_value = grid.GetFieldData().GetArray("TimeValue")
    check(time_value is not None and same(time_value.GetValue(0), state["time"]),
          f"{where}: TimeValue field data")


def main():
    program, outdir = sys.argv[1], sys.argv[2]
    subprocess.run([program, outdir], check=True)
    with open(os.path.join(outdir, "expected.json")) as f:
        states = json.load(f)["states"]

    # The .vtu files, one by one.
    for state in states:
        path = os.path.join(outdir, state["file"])
        check_grid(state["file"], read_vtu(path), state)

    # The .pvd as XML: every state in order, nothing else, no temporary files left.
    pvd = os.path.join(outdir, "results.pvd")
    root = ET.parse(pvd).getroot()
    check(root.tag == "VTKFile" and root.get("type") == "Collection", "pvd: not a VTK collection")
    datasets = root.findall("./Collection/DataSet")
    check([d.get("file") for d in datasets] == [s["file"] for s in states], "pvd: file list")
    check(all(same(float(d.get("timestep")), s["time"]) for d, s in zip(datasets, states)),
          "pvd: timesteps")
    leftovers = [f for f in os.listdir(outdir) if f.endswith(".tmp")]
    check(not leftovers, f"temporary files left: {leftovers}")

    # The .pvd through VTK's own XML parser (ParaView reads it with vtkPVDReader), and through
    # vtkXMLCollectionReader where this VTK build wraps it (Debian's python3-vtk9 does not).
    parser = vtk.vtkXMLDataParser()
    parser.SetFileName(pvd)
    check(parser.Parse() == 1, "pvd: vtkXMLDataParser cannot parse it")
    top = parser.GetRootElement()
    collection = top.FindNestedElementWithName("Collection") if top else None
    check(collection is not None, "pvd: no Collection element")
    if collection is not None:
        found = [(collection.GetNestedElement(i).GetAttribute("timestep"),
                  collection.GetNestedElement(i).GetAttribute("file"))
                 for i in range(collection.GetNumberOfNestedElements())]
        check(len(found) == len(states) and
              all(same(float(t), s["time"]) and f == s["file"] for (t, f), s in zip(found, states)),
              f"pvd via vtkXMLDataParser: {found}")
    if hasattr(vtk, "vtkXMLCollectionReader"):
        reader = vtk.vtkXMLCollectionReader()
        errors = Errors()
        reader.AddObserver("ErrorEvent", errors)
        reader.AddObserver("WarningEvent", errors)
        reader.SetFileName(pvd)
        reader.UpdateInformation()
        info = reader.GetOutputInformation(0)
        key = vtk.vtkStreamingDemandDrivenPipeline.TIME_STEPS()
        steps = list(info.Get(key)) if info.Has(key) else []
        check(len(steps) == len(states) and all(same(a, s["time"]) for a, s in zip(steps, states)),
              f"pvd via vtkXMLCollectionReader: time steps {steps}")
        for state in states:
            reader.UpdateTimeStep(state["time"])
            output = reader.GetOutputDataObject(0)
            if output is not None and output.IsA("vtkMultiBlockDataSet"):
                output = output.GetBlock(0)
            check(output is not None and output.IsA("vtkUnstructuredGrid"),
                  f"pvd at t={state['time']}: no unstructured grid")
            if output is not None and output.IsA("vtkUnstructuredGrid"):
                check_grid(f"pvd at t={state['time']}", output, state)
        check(not errors.messages, f"pvd: reader reported {errors.messages}")

    # summary.json: valid JSON, escapes decoded back to the text written.
    with open(os.path.join(outdir, "summary.json"), encoding="utf-8") as f:
        summary = json.load(f)
    check(summary["warnings"] == ["quote \" backslash \\ newline \n tab \t",
                                  "\u00b0C and a bad byte \ufffd"],
          f"summary.json warnings: {summary['warnings']!r}")
    check(summary["cycles"] == 3 and summary["status"] == "normal termination", "summary.json fields")

    if failures:
        for message in failures[:50]:
            print("FAIL:", message)
        print(f"{len(failures)} failures")
        return 1
    print(f"VTK {vtk.vtkVersion.GetVTKVersion()}: {len(states)} states read back exactly "
          f"({checks[0]} checks)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
