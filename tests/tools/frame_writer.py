"""Frames and a .pvd series in partimix's layout, for the tests of the tools that read them."""

import os

import numpy as np


def write_frame(path, points, kind, body):
    """A frame in partimix's layout: VTK PolyData, raw appended data, UInt64 size headers."""
    arrays = [("kind", "Int32", np.asarray(kind, np.int32)),
              ("body", "Int32", np.asarray(body, np.int32)),
              ("Points", "Float64", np.asarray(points, np.float64))]
    headers, blobs, offset = [], [], 0
    for name, kind_name, values in arrays:
        components = 1 if values.ndim == 1 else values.shape[1]
        headers.append(f'<DataArray type="{kind_name}" Name="{name}" '
                       f'NumberOfComponents="{components}" format="appended" offset="{offset}"/>')
        blob = np.uint64(values.nbytes).tobytes() + values.tobytes()
        blobs.append(blob)
        offset += len(blob)
    count = len(points)
    text = ('<?xml version="1.0"?>\n<VTKFile type="PolyData" version="1.0" '
            'byte_order="LittleEndian" header_type="UInt64">\n<PolyData>\n'
            f'<Piece NumberOfPoints="{count}">\n<PointData>\n{headers[0]}\n{headers[1]}\n'
            f'</PointData>\n<Points>\n{headers[2]}\n</Points>\n</Piece>\n</PolyData>\n'
            '<AppendedData encoding="raw">\n_')
    with open(path, "wb") as out:
        out.write(text.encode() + b"".join(blobs) + b"\n</AppendedData>\n</VTKFile>\n")


def write_series(folder, frames):
    """sph.pvd and frames/sph_NNNNNN.vtp in `folder` from (time, points, kind, body) tuples."""
    os.makedirs(os.path.join(folder, "frames"), exist_ok=True)
    entries = []
    for k, (time, points, kind, body) in enumerate(frames):
        name = f"frames/sph_{k:06d}.vtp"
        write_frame(os.path.join(folder, name), points, kind, body)
        entries.append(f'<DataSet timestep="{time!r}" group="" part="0" file="{name}"/>')
    with open(os.path.join(folder, "sph.pvd"), "w", encoding="utf-8") as pvd:
        pvd.write('<?xml version="1.0"?>\n<VTKFile type="Collection" version="1.0">\n'
                  '<Collection>\n' + "\n".join(entries) + '\n</Collection>\n</VTKFile>\n')
