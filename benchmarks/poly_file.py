"""Writes a Triangle .poly file from Python lists (the benchmarks' generated geometries)."""


def write_poly(path, vertices, segments, holes, first=0):
    """Vertices (x, y), segments (a, b) of 0-based vertex ids and hole points (x, y) into `path`,
    numbered from `first` (Triangle reads 0- or 1-based files alike)."""
    with open(path, "w", encoding="utf-8") as f:
        f.write(f"{len(vertices)} 2 0 0\n")
        f.writelines(f"{i + first} {x!r} {y!r}\n" for i, (x, y) in enumerate(vertices))
        f.write(f"{len(segments)} 0\n")
        f.writelines(f"{i + first} {a + first} {b + first}\n" for i, (a, b) in enumerate(segments))
        f.write(f"{len(holes)}\n")
        f.writelines(f"{i + first} {x!r} {y!r}\n" for i, (x, y) in enumerate(holes))
