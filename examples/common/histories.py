"""Reading a run's outputs back in the examples' checks and plots: the CSV histories
(docs/outputs.md) as rows, and the list of VTU states. Standard library only.
"""

import csv
import os
import xml.etree.ElementTree as ET


def _value(text):
    try:
        return float(text)
    except ValueError:
        return text  # a text column (a contact state, a load type)


def rows(path):
    """The rows of a CSV history (glstat.csv, rcforc.csv, ...) as dicts by column: numbers as
    floats, text columns as they are written."""
    with open(path) as f:
        return [{k: _value(v) for k, v in r.items()} for r in csv.DictReader(f)]


def states(outdir):
    """(time, path) of every VTU state a run wrote, in the order of results.pvd."""
    root = ET.parse(os.path.join(outdir, "results.pvd")).getroot()
    return [(float(d.get("timestep")), os.path.join(outdir, d.get("file")))
            for d in root.iter("DataSet")]
