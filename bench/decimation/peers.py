"""Open3D's simplify_quadric_decimation on the input decimation_bench wrote, timed the same way
(median of --reps runs, wall and process CPU time); writes open3d.off beside it.
Usage: peers.py DIR TARGET_FACES [REPS]"""
import statistics
import sys
import time

import open3d as o3d


def main() -> None:
    out, target = sys.argv[1], int(sys.argv[2])
    reps = int(sys.argv[3]) if len(sys.argv) > 3 else 3
    mesh = o3d.io.read_triangle_mesh(f"{out}/input.off")
    wall, cpu, faces = [], [], 0
    for i in range(reps):
        w0, c0 = time.perf_counter(), time.process_time()
        result = mesh.simplify_quadric_decimation(target_number_of_triangles=target)
        cpu.append(time.process_time() - c0)
        wall.append(time.perf_counter() - w0)
        faces = len(result.triangles)
        if i == 0:
            o3d.io.write_triangle_mesh(f"{out}/open3d.off", result)
    print(f"{'open3d_simplify_quadric':28s} {statistics.median(wall):8.3f} s wall {statistics.median(cpu):8.3f} s cpu  {faces:8d} faces")


if __name__ == "__main__":
    main()
