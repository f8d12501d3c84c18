#!/usr/bin/env python3
"""Compares the COLOR_0 of two bakes of the same asset (.glb written by `vlit bake`).

Usage: bench/compare_baked_colors.py A.glb B.glb

Prints the number of vertices, how many differ, the largest difference (in the stored colour's
units, 1 = white) and how many differ by more than 1e-3. Both files must hold the same primitives
in the same order (two bakes of one input). Python's standard library only.
"""
import json
import struct
import sys

COMPONENT = {5126: ("f", 1.0), 5123: ("H", 65535.0), 5121: ("B", 255.0)}  # struct format, full scale
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
            kind, scale = COMPONENT[accessor["componentType"]]
            width = WIDTH[accessor["type"]]
            item = struct.calcsize(kind)
            stride = view.get("byteStride", item * width)
            start = view.get("byteOffset", 0) + accessor.get("byteOffset", 0)
            rgb = struct.Struct("<3" + kind)
            for k in range(accessor["count"]):
                colors.append(tuple(c / scale for c in rgb.unpack_from(binary, start + k * stride)))
    return colors


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    a, b = vertex_colors(sys.argv[1]), vertex_colors(sys.argv[2])
    if len(a) != len(b):
        sys.exit(f"different vertex counts: {len(a)} and {len(b)}")
    diff = [max(abs(x - y) for x, y in zip(ca, cb)) for ca, cb in zip(a, b)]
    print(f"vertices {len(a)}, differing {sum(d > 0 for d in diff)}, largest difference "
          f"{max(diff, default=0):.3g}, differing by more than 1e-3 {sum(d > 1e-3 for d in diff)}")


if __name__ == "__main__":
    main()
