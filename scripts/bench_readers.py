#!/usr/bin/env python3
"""Reader benchmark: time and peak memory of every file reader against the input's size.

For each reader, a hostile input of many small values (the pattern that costs a reader most per
byte: empty objects, empty arrays, single digits, bare newlines, a CSV line of commas, CSV rows of
8 bytes) is written at a size S and at 4 S, with 4 S the smaller of the reader's documented size
limit and 64 MB (docs/limits.md). The command that reads it runs as a child process; its wall time
and peak resident memory (getrusage's ru_maxrss of that child alone, run from a small launcher
process) are measured. The readers refuse most of these files (not valid documents), while reading
them when the memory bound is reached, else after reading them whole.

Bounds (issue 45, docs/limits.md "Reading cost"): time(4 S) / time(S) <= 5 (linear, not quadratic:
quadratic would be 16), peak memory <= 10 x the file's size + 200 MB.

    /usr/bin/python3 scripts/bench_readers.py --dspbr build/dspbr [--json out.json] [--scale 0.25]

--scale shrinks every size (0.25: a quarter; the test in tests/python/test_bench_readers.py runs
it small). Exit status 1 when a bound is exceeded, 2 on bad usage.
"""
import argparse
import json
import os
import struct
import subprocess
import sys
import tempfile
import time

MB = 1 << 20
DOCUMENT = 16 * MB  # kDocumentBytes: parameter definitions, instances, conformance files
GLTF = 256 * MB  # kGltfBytes
TABLE = 1 << 30  # kTableFileBytes
CAP = 64 * MB  # the largest input the benchmark writes


def repeated(head, unit, sep, tail, size):
    """head + unit (sep unit)* + tail of about `size` bytes."""
    n = max(1, (size - len(head) - len(tail)) // (len(unit) + len(sep)))
    return head + sep.join([unit] * n) + tail


def glb(json_bytes):
    """A GLB container (glTF 2.0 binary) holding `json_bytes` as its JSON chunk."""
    pad = (-len(json_bytes)) % 4
    chunk = json_bytes + b" " * pad
    total = 12 + 8 + len(chunk)
    return struct.pack("<III", 0x46546C67, 2, total) + struct.pack("<II", len(chunk), 0x4E4F534A) + chunk


# (name, the reader's size limit, writer(size) -> (file suffix, bytes), argv(path, tmp) -> command)
def readers(dspbr, vectors):
    def check_results(path, tmp):  # a results file against the valid vectors
        return [dspbr, "conformance", "check", vectors, path, "--no-html", "--out", os.path.join(tmp, "r")]

    def csv(unit, sep, tail=b""):  # a results CSV: its header, then the units
        return lambda size: (".csv", repeated(b"id,f_cos_r,f_cos_g,f_cos_b\n", unit, sep, tail, size))

    gltf_nodes = lambda size: (".gltf", repeated(b'{"asset":{"version":"2.0"},"nodes":[', b"{}", b",", b"]}", size))
    return [
        ("parameter definitions (params list)", DOCUMENT,
         lambda size: (".json", repeated(b'{"materials":{"generic":{"parameters":{}}},"x":[', b"[]", b",", b"]}", size)),
         lambda p, t: [dspbr, "params", "list", p]),
        ("material instance (params check)", DOCUMENT,
         lambda size: (".json", repeated(b'{"material":"generic","values":{},"x":[', b"{}", b",", b"]}", size)),
         lambda p, t: [dspbr, "params", "check", p]),
        ("glTF (scene analyze)", GLTF, gltf_nodes, lambda p, t: [dspbr, "scene", "analyze", p]),
        ("glTF image URIs (scene analyze)", GLTF,
         lambda size: (".gltf", repeated(b'{"asset":{"version":"2.0"},"images":[', b'{"uri":"textures/image_0000000.png"}',
                                         b",", b"]}", size)),
         lambda p, t: [dspbr, "scene", "analyze", p]),
        ("GLB (scene analyze)", GLTF,
         lambda size: (".glb", glb(gltf_nodes(size - 20)[1])),
         lambda p, t: [dspbr, "scene", "analyze", p]),
        ("table file (validate --luts)", TABLE,
         lambda size: (".json", repeated(b'{"version":1,"tables":{},"x":[', b"0", b",", b"]}", size)),
         lambda p, t: [dspbr, "validate", "--luts", p, "--quick", "--out", os.path.join(t, "report")]),
        ("conformance vectors (conformance check)", DOCUMENT,
         lambda size: (".json", repeated(b'{"vectors":[', b"{}", b",", b"]}", size)),
         lambda p, t: [dspbr, "conformance", "check", p, vectors, "--no-html", "--out", os.path.join(t, "r")]),
        ("conformance results, JSON (conformance check)", DOCUMENT,
         lambda size: (".json", repeated(b'{"results":[', b"{}", b",", b"]}", size)),
         check_results),
        ("conformance results, CSV newlines (conformance check)", DOCUMENT, csv(b"", b"\n"), check_results),
        ("conformance results, CSV one line of commas (conformance check)", DOCUMENT, csv(b"", b","), check_results),
        ("conformance results, CSV rows (conformance check)", DOCUMENT, csv(b"a,0,0,0", b"\n", b"\n"), check_results),
    ]


# A small launcher process forks and runs the command: the benchmark's own process holds the input
# and its peak, which a child spawned from it directly (vfork) would inherit in ru_maxrss.
LAUNCHER = """
import os, sys, time
start = time.monotonic()
pid = os.fork()
if pid == 0:
    null = os.open(os.devnull, os.O_WRONLY)
    os.dup2(null, 1)
    os.execv(sys.argv[1], sys.argv[1:])
_, status, usage = os.wait4(pid, 0)
print(time.monotonic() - start, usage.ru_maxrss, os.waitstatus_to_exitcode(status))
"""


def measure(argv):
    """Wall seconds, peak resident MB, exit status and last line of stderr of one command."""
    p = subprocess.run([sys.executable, "-c", LAUNCHER, *argv], capture_output=True, text=True, check=True)
    wall, peak_kb, code = p.stdout.split()
    stderr = p.stderr.strip().splitlines()
    return float(wall), int(peak_kb) / 1024.0, int(code), stderr[-1] if stderr else ""


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--dspbr", default="build/dspbr", help="the dspbr executable (default: build/dspbr)")
    ap.add_argument("--json", help="write the measurements to this file")
    ap.add_argument("--scale", type=float, default=1.0, help="multiply every input size (default 1)")
    args = ap.parse_args()
    if not (0 < args.scale <= 1):
        ap.error("--scale must be in (0, 1]")
    if not os.access(args.dspbr, os.X_OK):
        ap.error(f"{args.dspbr}: not an executable (build first: bash scripts/build.sh)")
    rows, failed = [], False
    with tempfile.TemporaryDirectory(prefix="dspbr-bench-readers-") as tmp:
        # A valid vectors file of the built-in materials (one direction pair each) for the results readers.
        subprocess.run([args.dspbr, "conformance", "generate", "--out", os.path.join(tmp, "v"), "--directions", "1",
                        "--no-scenes", "--no-albedo"], check=True, stdout=subprocess.DEVNULL)
        vectors = os.path.join(tmp, "v", "vectors.json")
        print(f"{'reader':64} {'size MB':>8} {'time s':>7} {'peak MB':>8} {'bound MB':>8}  exit  message", flush=True)
        for name, limit, write, argv in readers(args.dspbr, vectors):
            large = int(min(limit - MB, CAP) * args.scale)
            runs = []
            for size in (large // 4, large):
                suffix, data = write(size)
                path = os.path.join(tmp, "input" + suffix)
                with open(path, "wb") as f:
                    f.write(data)
                size = len(data)
                del data
                wall, peak, code, message = measure(argv(path, tmp))
                bound = 10 * size / 1e6 + 200
                runs.append({"bytes": size, "seconds": wall, "peak_mb": peak, "exit": code, "message": message})
                print(f"{name:64} {size / 1e6:8.2f} {wall:7.2f} {peak:8.0f} {bound:8.0f}  {code:4}  {message[:60]}",
                      flush=True)
                os.unlink(path)
                if peak > bound or code not in (0, 1, 2):
                    failed = True
            ratio = runs[1]["seconds"] / max(runs[0]["seconds"], 1e-3)
            if ratio > 5:
                failed = True
            print(f"{'':64} time ratio 4x size: {ratio:.2f} (bound 5)", flush=True)
            rows.append({"reader": name, "runs": runs, "time_ratio": ratio})
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"scale": args.scale, "readers": rows}, f, indent=1)
    print("FAIL: a bound is exceeded" if failed else "PASS: every reader within the bounds")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
