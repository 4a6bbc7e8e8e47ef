"""One timed read of FILE by READER, printed as "<seconds> <faces>" (bench/io/formats.sh).

READER: hmira (hmira.read_mesh), trimesh (trimesh.load(..., process=False)), pyvista (pyvista.read).
Only the read call is timed; imports are done first.
"""
import sys
import time


def main(reader: str, path: str) -> None:
    if reader == "hmira":
        import hmira
        t0 = time.perf_counter()
        m = hmira.read_mesh(path)
        dt = time.perf_counter() - t0
        faces = m.face_count
    elif reader == "trimesh":
        import trimesh
        t0 = time.perf_counter()
        m = trimesh.load(path, process=False, force="mesh")
        dt = time.perf_counter() - t0
        faces = len(m.faces)
    elif reader == "pyvista":
        import pyvista
        t0 = time.perf_counter()
        m = pyvista.read(path)
        dt = time.perf_counter() - t0
        faces = m.n_cells
    else:
        raise SystemExit(f"unknown reader {reader}")
    print(f"{dt:.4f} {faces}")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
