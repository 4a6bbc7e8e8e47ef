#!/usr/bin/env python3
"""hmira against vtkFlyingEdges3D in CPU time (user + system, all threads), medians, side by side
in one run: on a shared machine wall times mostly measure the other processes.

usage: cpu_side_by_side.py VOLUME_DIR HMIRA_BENCH_BINARY REPEATS THREADS...
VOLUME_DIR as bench_marching_cubes --export writes it (only the volumes in its manifest run)."""
import json
import statistics
import subprocess
import sys
import tempfile
import time

from peers import load, vtk_filter


def hmira_cpu_ms(bench, name, threads, repeats):
    with tempfile.NamedTemporaryFile(suffix=".json") as out:
        subprocess.run([bench, f"--benchmark_filter=^hmira_mc/{name}/{threads}/", f"--benchmark_repetitions={repeats}",
                        f"--benchmark_out={out.name}", "--benchmark_out_format=json"], check=True, stdout=subprocess.DEVNULL)
        runs = [b for b in json.load(open(out.name))["benchmarks"] if b.get("run_type") == "iteration"]
    return statistics.median(b["cpu_time"] for b in runs)


def vtk_cpu_ms(vol, threads, repeats):
    import vtk
    f = vtk_filter(vtk.vtkFlyingEdges3D, vol, threads)
    times = []
    for _ in range(repeats):
        f.Modified()
        c0 = time.process_time()
        f.Update()
        times.append((time.process_time() - c0) * 1000.0)
    return statistics.median(times)


def main():
    volume_dir, bench, repeats, threads = sys.argv[1], sys.argv[2], int(sys.argv[3]), [int(t) for t in sys.argv[4:]]
    print("| volume | threads | hmira CPU ms | vtkFlyingEdges3D CPU ms | hmira/vtk |")
    print("|---|---|---|---|---|")
    for vol in load(volume_dir):
        for t in threads:
            h = hmira_cpu_ms(bench, vol["name"], t, repeats)
            v = vtk_cpu_ms(vol, t, repeats)
            print(f"| {vol['name']} | {t} | {h:.2f} | {v:.2f} | {h / v:.2f} |", flush=True)


if __name__ == "__main__":
    main()
