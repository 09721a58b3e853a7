#!/usr/bin/python3
"""Generate the meshes shipped in Data/: files as a scientist's tools write them, with
texture coordinates and no tangents, for the tangent-free relief mapper's tests.

    /usr/bin/python3 Data/make_meshes.py

Plain Python, no dependencies; the output is fully determined by the code below.

* ``torus.obj``: a torus around the z axis (ring radius 0.35, tube radius 0.15),
  32 x 16 quads, positions, texture coordinates (6 x 2 tiles, seams duplicated) and
  unit normals: what Blender or MeshLab export.
* ``icosahedron.ply``: a regular icosahedron of circumradius 0.5, a separate corner
  per face, texture coordinates from a spherical projection (4 x 2 tiles, each face
  kept on one side of the seam) and no normals: Tichenor's (2012) "faceted crystal".
"""

import math
import os

OUT_DIR = os.path.dirname(os.path.abspath(__file__))


def torus_obj(path, ring=32, tube=16, major=0.35, minor=0.15, tiles=(6, 2)):
    lines = ["# vtkRelief Data/make_meshes.py: torus, texture coordinates and normals, no tangents"]
    vertices, tcoords, normals = [], [], []
    for i in range(ring + 1):
        theta = 2.0 * math.pi * i / ring
        for j in range(tube + 1):
            phi = 2.0 * math.pi * j / tube
            normal = (math.cos(phi) * math.cos(theta), math.cos(phi) * math.sin(theta),
                      math.sin(phi))
            centre = (major * math.cos(theta), major * math.sin(theta), 0.0)
            vertices.append(tuple(c + minor * n for c, n in zip(centre, normal)))
            normals.append(normal)
            tcoords.append((tiles[0] * i / ring, tiles[1] * j / tube))
    lines += ["v %.6f %.6f %.6f" % v for v in vertices]
    lines += ["vt %.6f %.6f" % t for t in tcoords]
    lines += ["vn %.6f %.6f %.6f" % n for n in normals]
    for i in range(ring):
        for j in range(tube):
            a = i * (tube + 1) + j + 1  # OBJ counts from 1
            b = a + tube + 1
            quad = (a, b, b + 1, a + 1)
            lines.append("f " + " ".join("%d/%d/%d" % (k, k, k) for k in quad))
    with open(path, "w") as out:
        out.write("\n".join(lines) + "\n")


def icosahedron_ply(path, radius=0.5, tiles=(4, 2)):
    golden = (1.0 + math.sqrt(5.0)) / 2.0
    corners = [(-1, golden, 0), (1, golden, 0), (-1, -golden, 0), (1, -golden, 0),
               (0, -1, golden), (0, 1, golden), (0, -1, -golden), (0, 1, -golden),
               (golden, 0, -1), (golden, 0, 1), (-golden, 0, -1), (-golden, 0, 1)]
    scale = radius / math.sqrt(1.0 + golden * golden)
    corners = [tuple(scale * c for c in corner) for corner in corners]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
             (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
             (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]

    def spherical(point):
        x, y, z = point
        u = (math.atan2(y, x) / (2.0 * math.pi)) % 1.0
        v = math.acos(max(-1.0, min(1.0, z / radius))) / math.pi
        return u, 1.0 - v

    vertices, tcoords = [], []
    for face in faces:
        uvs = [spherical(corners[k]) for k in face]
        # one side of the seam for the whole face
        if max(u for u, _ in uvs) - min(u for u, _ in uvs) > 0.5:
            uvs = [(u + 1.0 if u < 0.5 else u, v) for u, v in uvs]
        for k, (u, v) in zip(face, uvs):
            vertices.append(corners[k])
            tcoords.append((tiles[0] * u, tiles[1] * v))
    lines = ["ply", "format ascii 1.0",
             "comment vtkRelief Data/make_meshes.py: icosahedron, texture coordinates, no normals",
             "element vertex %d" % len(vertices), "property float x", "property float y",
             "property float z", "property float u", "property float v",
             "element face %d" % len(faces), "property list uchar int vertex_indices",
             "end_header"]
    lines += ["%.6f %.6f %.6f %.6f %.6f" % (p + t) for p, t in zip(vertices, tcoords)]
    lines += ["3 %d %d %d" % (3 * f, 3 * f + 1, 3 * f + 2) for f in range(len(faces))]
    with open(path, "w") as out:
        out.write("\n".join(lines) + "\n")


def main():
    torus_obj(os.path.join(OUT_DIR, "torus.obj"))
    icosahedron_ply(os.path.join(OUT_DIR, "icosahedron.ply"))


if __name__ == "__main__":
    main()
