#!/usr/bin/env python3
"""Does memory (bandwidth, first touch of the output's fresh pages) explain marching
cubes' 1 -> 2 thread speed-up on the 384^3 volumes? Runs bandwidth_probe, then hmira and
vtkFlyingEdges3D at 1 and 2 threads on the same volumes (wall medians), and prints how much
of hmira's time writing its output to fresh pages would take at the probe's first-touch rate.

usage: bandwidth.py VOLUME_DIR HMIRA_BENCH_BINARY PROBE_BINARY [REPEATS]
VOLUME_DIR as bench_marching_cubes --export writes it."""
import json
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

from peers import vtk_filter

VOLUMES = ("sphere_384", "gyroid_384")


def load(volume_dir, names):
    vols = []
    with open(f"{volume_dir}/manifest.txt") as f:
        for line in f:
            name, nx, ny, nz, iso, *_ = line.split()
            if name in names:
                data = np.fromfile(f"{volume_dir}/{name}.raw", dtype="<f4").reshape(int(nz), int(ny), int(nx))
                vols.append(dict(name=name, dims=(int(nx), int(ny), int(nz)), iso=float(iso), data=data))
    return vols


def hmira(bench, name, threads, repeats):
    """Wall ms (median and fastest), CPU ms (all threads), kernel ms and page faults per call (medians)."""
    with tempfile.NamedTemporaryFile(suffix=".json") as out:
        subprocess.run([bench, f"--benchmark_filter=^hmira_mc/{name}/{threads}/", f"--benchmark_repetitions={repeats}",
                        f"--benchmark_out={out.name}", "--benchmark_out_format=json"], check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        runs = [b for b in json.load(open(out.name))["benchmarks"] if b.get("run_type") == "iteration"]
    med = lambda key: statistics.median(b[key] for b in runs)
    return med("real_time"), min(b["real_time"] for b in runs), med("cpu_time"), med("sys_ms"), med("faults")


def vtk_fe(vol, threads, repeats):
    """Wall ms (median and fastest) and CPU ms (median, all threads) of vtkFlyingEdges3D, and its output's bytes."""
    import vtk
    f = vtk_filter(vtk.vtkFlyingEdges3D, vol, threads)
    times, cpu = [], []
    for _ in range(repeats):
        f.Modified()
        t0, c0 = time.perf_counter(), time.process_time()
        f.Update()
        times.append((time.perf_counter() - t0) * 1000.0)
        cpu.append((time.process_time() - c0) * 1000.0)
    return statistics.median(times), min(times), statistics.median(cpu), f.GetOutput().GetActualMemorySize() * 1024


def cpu_state():
    """(busy, steal, total) seconds of both CPUs from /proc/stat, and this script's own CPU
    seconds with its finished children (the hmira benchmark runs)."""
    with open("/proc/stat") as f:
        v = [int(x) / os.sysconf("SC_CLK_TCK") for x in f.readline().split()[1:9]]
    t = os.times()
    return v[0] + v[1] + v[2] + v[5] + v[6], v[7], sum(v), t.user + t.system + t.children_user + t.children_system


def others(a, b):
    """Share of both CPUs' time used by other processes, and stolen by the hypervisor, between
    two cpu_state() readings: what disturbs a 2-thread measurement on a shared machine."""
    total = max(b[2] - a[2], 1e-9)
    return f"{max(b[0] - a[0] - (b[3] - a[3]), 0) / total:.0%} / {(b[1] - a[1]) / total:.0%}"


def main():
    volume_dir, bench, probe = sys.argv[1:4]
    repeats = int(sys.argv[4]) if len(sys.argv) > 4 else 5
    print(f"load average before: {os.getloadavg()[0]:.2f} {os.getloadavg()[1]:.2f} {os.getloadavg()[2]:.2f}")
    text = subprocess.run([probe, "--reps", str(max(repeats, 5))], check=True, capture_output=True, text=True).stdout
    print(text)
    out_bytes = {m[0]: int(m[1]) for m in re.findall(r"^output (\S+) .*bytes=(\d+)$", text, re.M)}
    fresh = re.search(r"^\| fresh write \(first touch\) \| \S+ \| (\S+) \| (\S+) \|", text, re.M)
    fresh_gbs = {1: float(fresh[1]), 2: float(fresh[2])}
    unmap = re.search(r"^munmap of the fresh output \(serial\): (\S+) ms$", text, re.M)
    unmap_ms_per_byte = float(unmap[1]) / max(out_bytes.values())  # the probe unmaps the larger (gyroid) output

    print("Wall ms: median / fastest of the repetitions; CPU ms: all threads, median. 'fresh-page write' is the probe's first-touch")
    print("time for hmira's output bytes, and its share of hmira's median wall time. 'memory bound': the speed-up if all else halved,")
    print("the first touch scaled as in the probe and the serial munmap of the output did not. 'other processes / stolen CPU': share of")
    print("both CPUs' time used by processes other than these measurements, and stolen by the hypervisor, while that row ran.\n")
    print("| volume | output MB | thr | hmira wall ms | hmira CPU ms | kernel ms/call | faults/call | fresh-page write ms | share | vtkFE wall ms | vtkFE CPU ms | vtkFE output MB | other processes / stolen CPU |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    speedups = []
    for vol in load(volume_dir, VOLUMES):
        name, b = vol["name"], out_bytes.get(vol["name"], 0)
        res = {}
        for t in (1, 2):
            c0 = cpu_state()
            h, hbest, hcpu, sys_ms, faults = hmira(bench, name, t, repeats)
            v, vbest, vcpu, vbytes = vtk_fe(vol, t, repeats)
            disturbed = others(c0, cpu_state())
            touch = b / (fresh_gbs[t] * 1e9) * 1000.0
            res[t] = (h, hbest, hcpu, v, vbest, vcpu, touch)
            print(f"| {name} | {b / 1e6:.1f} | {t} | {h:.1f} / {hbest:.1f} | {hcpu:.1f} | {sys_ms:.1f} | {faults:.0f} | {touch:.1f} | {touch / h:.0%} "
                  f"| {v:.1f} / {vbest:.1f} | {vcpu:.1f} | {vbytes / 1e6:.1f} | {disturbed} |", flush=True)
        (h1, hb1, hc1, v1, vb1, vc1, f1), (h2, hb2, hc2, v2, vb2, vc2, f2) = res[1], res[2]
        # The speed-up if everything else halved, the first touch went at the probe's rates and
        # the caller's munmap of the output (serial, inside the timed loop) did not shrink.
        u = unmap_ms_per_byte * b
        bound = h1 / ((h1 - f1 - u) / 2 + f2 + u)
        speedups.append(f"{name}: 1->2 threads, medians (fastest): hmira {h1 / h2:.2f} ({hb1 / hb2:.2f}), memory bound {bound:.2f}, "
                        f"CPU 2/1 {hc2 / hc1:.2f}; vtkFlyingEdges3D {v1 / v2:.2f} ({vb1 / vb2:.2f}), CPU 2/1 {vc2 / vc1:.2f}")
    print("\n".join(speedups))
    print(f"load average after: {os.getloadavg()[0]:.2f} {os.getloadavg()[1]:.2f} {os.getloadavg()[2]:.2f}")


if __name__ == "__main__":
    main()
