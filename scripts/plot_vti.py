#!/usr/bin/env python3
"""A quick look at a VTK image file written by ship_lrm (`validate cylinder --vti`, the sweeps'
fields) without ParaView: the speed and the x velocity on one plane, walls greyed out.

usage: plot_vti.py FIELD.vti OUT.png [--axis z] [--index MIDDLE] [--title TEXT]

Reads the raw appended format ship_lrm writes (UInt64 block headers, little endian, point arrays
density, velocity, cell_type); any other VTK file is refused with a message.
"""
import argparse
import re
import sys

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_vti(path):
    data = open(path, "rb").read()
    start = data.find(b"<AppendedData")
    if start < 0 or b'encoding="raw"' not in data[start:start + 100] or b'header_type="UInt64"' not in data[:400]:
        sys.exit(f"plot_vti.py: {path} is not a raw-appended VTK image file as ship_lrm writes them")
    head = data[:start].decode("ascii", "replace")
    extent_m, spacing_m = re.search(r'WholeExtent="([^"]+)"', head), re.search(r'Spacing="([^"]+)"', head)
    if not extent_m or not spacing_m:
        sys.exit(f"plot_vti.py: {path} has no WholeExtent or Spacing")
    extent = [int(v) for v in extent_m.group(1).split()]
    spacing = [float(v) for v in spacing_m.group(1).split()]
    dims = [extent[1] - extent[0] + 1, extent[3] - extent[2] + 1, extent[5] - extent[4] + 1]
    base = data.index(b"_", start) + 1
    arrays = {}
    for m in re.finditer(r'<DataArray type="(\w+)" Name="(\w+)"(?: NumberOfComponents="(\d+)")? format="appended" offset="(\d+)"', head):
        kind, name, comps, offset = m.group(1), m.group(2), int(m.group(3) or 1), int(m.group(4))
        dtype = {"Float32": "<f4", "UInt8": "u1"}.get(kind)
        if dtype is None:
            continue
        n = int(np.frombuffer(data, "<u8", 1, base + offset)[0])
        a = np.frombuffer(data, dtype, n // np.dtype(dtype).itemsize, base + offset + 8)
        arrays[name] = a.reshape(dims[2], dims[1], dims[0], comps) if comps > 1 else a.reshape(dims[2], dims[1], dims[0])
    if "velocity" not in arrays:
        sys.exit(f"plot_vti.py: {path} has no velocity array")
    return arrays, spacing


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("vti")
    ap.add_argument("png")
    ap.add_argument("--axis", choices="xyz", default="z", help="normal of the plane shown")
    ap.add_argument("--index", type=int, help="the plane's index along that axis (default: the middle)")
    ap.add_argument("--title", default="")
    a = ap.parse_args()
    arrays, spacing = read_vti(a.vti)
    u = arrays["velocity"]
    ax_index = {"z": 0, "y": 1, "x": 2}[a.axis]
    n = u.shape[ax_index]
    i = n // 2 if a.index is None else a.index
    if not 0 <= i < n:
        sys.exit(f"plot_vti.py: --index {i} is outside 0 .. {n - 1}")
    plane = np.take(u, i, axis=ax_index)
    wall = np.take(arrays["cell_type"], i, axis=ax_index) != 0 if "cell_type" in arrays else None
    speed = np.linalg.norm(plane, axis=-1)
    h, v = {"z": ("x", "y"), "y": ("x", "z"), "x": ("y", "z")}[a.axis]
    sh, sv = spacing["xyz".index(h)], spacing["xyz".index(v)]
    extent = [0, plane.shape[1] * sh, 0, plane.shape[0] * sv]
    fig, axes = plt.subplots(2, 1, figsize=(11, 5.5))
    for axp, field, label, cmap in ((axes[0], speed, "|u| [lattice]", "viridis"), (axes[1], plane[..., 0], "u_x [lattice]", "RdBu_r")):
        shown = np.ma.masked_where(wall, field) if wall is not None else field
        im = axp.imshow(shown, origin="lower", extent=extent, cmap=cmap, aspect="equal")
        axp.set_facecolor("0.6")
        axp.set_xlabel(f"{h} [m]")
        axp.set_ylabel(f"{v} [m]")
        fig.colorbar(im, ax=axp, label=label, shrink=0.9)
    fig.suptitle(a.title or f"{a.vti}: plane {a.axis} = {i} of {n}")
    fig.tight_layout()
    fig.savefig(a.png, dpi=110)


if __name__ == "__main__":
    main()
