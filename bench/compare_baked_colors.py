#!/usr/bin/env python3
"""Compares the COLOR_0 of two bakes of the same asset (.glb written by `vlit bake`).

Usage: bench/compare_baked_colors.py A.glb B.glb

Prints the number of vertices, how many differ, the largest difference (in the stored colour's
units, 1 = white) and how many differ by more than 1e-3. Both files must hold the same primitives
in the same order (two bakes of one input). Needs python3-numpy.
"""
import json
import struct
import sys

import numpy as np

COMPONENT = {5126: ("<f4", 1.0), 5123: ("<u2", 65535.0), 5121: ("u1", 255.0)}
WIDTH = {"VEC3": 3, "VEC4": 4}


def vertex_colors(path):
    data = open(path, "rb").read()
    if data[:4] != b"glTF":
        sys.exit(f"{path}: not a .glb")
    json_length = struct.unpack("<I", data[12:16])[0]
    gltf = json.loads(data[20:20 + json_length])
    offset = 20 + json_length
    bin_length = struct.unpack("<I", data[offset:offset + 4])[0]
    binary = data[offset + 8:offset + 8 + bin_length]
    colors = []
    for mesh in gltf["meshes"]:
        for primitive in mesh["primitives"]:
            index = primitive["attributes"].get("COLOR_0")
            if index is None:
                continue
            accessor = gltf["accessors"][index]
            view = gltf["bufferViews"][accessor["bufferView"]]
            dtype, scale = COMPONENT[accessor["componentType"]]
            width = WIDTH[accessor["type"]]
            item = np.dtype(dtype).itemsize
            stride = view.get("byteStride", item * width)
            start = view.get("byteOffset", 0) + accessor.get("byteOffset", 0)
            count = accessor["count"]
            raw = np.frombuffer(binary[start:start + stride * count], dtype=dtype).reshape(count, stride // item)
            colors.append(raw[:, :3].astype(float) / scale)
    return np.concatenate(colors) if colors else np.zeros((0, 3))


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    a, b = vertex_colors(sys.argv[1]), vertex_colors(sys.argv[2])
    if a.shape != b.shape:
        sys.exit(f"different vertex counts: {len(a)} and {len(b)}")
    diff = np.abs(a - b).max(axis=1) if len(a) else np.zeros(0)
    print(f"vertices {len(a)}, differing {int((diff > 0).sum())}, largest difference "
          f"{diff.max() if len(diff) else 0:.3g}, differing by more than 1e-3 {int((diff > 1e-3).sum())}")


if __name__ == "__main__":
    main()
