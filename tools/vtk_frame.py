"""Reads the frames partimix writes: VTK PolyData with raw appended data and UInt64 headers."""

import re

import numpy as np

TYPES = {"Float64": np.float64, "Int32": np.int32, "Int64": np.int64}


def read_frame(path):
    """The point arrays of a frame by name (Points included), as numpy arrays of rows."""
    with open(path, "rb") as frame:
        data = frame.read()
    start = data.find(b"<AppendedData")
    if start < 0 or b'header_type="UInt64"' not in data[:start]:
        raise ValueError(f"{path}: not a frame with raw appended data and UInt64 headers")
    raw = data.index(b"_", start) + 1
    arrays = {}
    pattern = rb'<DataArray type="(\w+)" Name="(\w+)" NumberOfComponents="(\d+)" ' \
              rb'format="appended" offset="(\d+)"'
    for kind, name, components, offset in re.findall(pattern, data[:start]):
        at = raw + int(offset)
        size = int(np.frombuffer(data, np.uint64, 1, at)[0])
        values = np.frombuffer(data, TYPES[kind.decode()], offset=at + 8,
                               count=size // np.dtype(TYPES[kind.decode()]).itemsize)
        arrays[name.decode()] = values.reshape(-1, int(components))
    return arrays
