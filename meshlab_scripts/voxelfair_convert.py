#!/usr/bin/env python3
"""Convert voxel models (.vxl, .vox) to meshes with headless MeshLab (meshlabserver).

usage: voxelfair_convert.py INPUT [INPUT ...] --output FOLDER [options]

INPUT is a model file or a folder (searched for *.vxl and *.vox). Each model is imported by voxelfair's
io_vxl plugin inside meshlabserver, optionally run through a .mlx filter script, and saved as
FOLDER/<name>.ply (and/or .obj). Files run in parallel on the available cores.

meshlabserver exits 0 even when it could not save, and never prints an importer's error: this
wrapper checks that every output really was written, relays the plugins' messages, and exits
non-zero with a clear message if anything failed.
"""
import argparse
import concurrent.futures
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

MODEL_SUFFIXES = (".vxl", ".vox")
# meshlabserver -m flags: face colour and face quality (the VXL section of each face).
DEFAULT_SAVE_FLAGS = ["fc", "fq"]


def find_meshlabserver(build):
    """The private runtime in the build tree first, then an installed meshlabserver."""
    candidates = []
    if build:
        candidates.append(Path(build) / "runtime" / "bin" / "meshlabserver")
    candidates.append(Path(__file__).resolve().parent.parent / "build" / "runtime" / "bin" / "meshlabserver")
    for c in candidates:
        if c.is_file() and os.access(c, os.X_OK):
            return str(c)
    found = shutil.which("meshlabserver")
    if found:
        return found
    sys.exit("voxelfair: no meshlabserver found: build the project (bash voxelfair.sh build) or install meshlab")


def collect_inputs(paths):
    models = []
    for p in map(Path, paths):
        if p.is_dir():
            models += sorted(f for f in p.rglob("*") if f.suffix.lower() in MODEL_SUFFIXES and f.is_file())
        elif p.is_file():
            models.append(p)
        else:
            sys.exit(f"voxelfair: {p}: no such file or folder")
    if not models:
        sys.exit("voxelfair: no .vxl or .vox models found in " + ", ".join(paths))
    return [m.resolve() for m in models]


def importer_environment(args):
    """meshlabserver cannot set importer parameters: io_vxl reads these variables instead."""
    env = dict(os.environ)
    if args.palette:
        env["VOXELFAIR_PALETTE"] = str(Path(args.palette).resolve())
    if args.house_colour:
        env["VOXELFAIR_HOUSE_COLOUR"] = args.house_colour
    env["VOXELFAIR_FRAME"] = str(args.frame)
    env["VOXELFAIR_SECTION"] = str(args.section)
    env["VOXELFAIR_TRANSFORMS"] = "0" if args.no_transforms else "1"
    return env


def convert(model, args, server, env):
    """Runs one model through meshlabserver; returns (model, outputs, seconds, error or None)."""
    started = time.monotonic()
    outputs = [Path(args.output) / (model.stem + "." + fmt) for fmt in args.formats]
    with tempfile.TemporaryDirectory(prefix="voxelfair-") as private:
        # Keep MeshLab's settings and runtime files out of the user's home.
        run_env = dict(env, XDG_CONFIG_HOME=private, XDG_RUNTIME_DIR=private, HOME=env.get("HOME", private))
        command = ["xvfb-run", "-a", "-s", "-screen 0 640x480x24", server, "-i", str(model)]
        for out in outputs:
            command += ["-o", str(out), "-m"] + DEFAULT_SAVE_FLAGS + (["wt"] if args.script else [])
        if args.script:
            command += ["-s", str(Path(args.script).resolve())]
        for out in outputs:
            if out.exists():
                out.unlink()
        try:
            result = subprocess.run(command, env=run_env, capture_output=True, text=True, timeout=args.timeout)
        except subprocess.TimeoutExpired:
            return model, outputs, time.monotonic() - started, f"meshlabserver took more than {args.timeout} s"
    seconds = time.monotonic() - started
    plugin_lines = [l for l in (result.stderr + result.stdout).splitlines() if l.startswith(("io_vxl:", "filter_voxelfair:"))]
    missing = [str(o) for o in outputs if not o.is_file() or o.stat().st_size == 0]
    if result.returncode != 0 or missing:
        output_lines = (result.stdout + result.stderr).strip().splitlines()
        reason = "; ".join(plugin_lines) or (output_lines[-1] if output_lines else "no message")
        what = f"meshlabserver exited with {result.returncode}" if result.returncode else "the output was not written"
        return model, outputs, seconds, f"{what}: {reason}"
    return model, outputs, seconds, None


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("inputs", nargs="+", help="model files or folders")
    parser.add_argument("--output", "-o", required=True, help="output folder")
    parser.add_argument("--formats", default="ply", help="comma-separated output formats: ply, obj (default ply)")
    parser.add_argument("--script", help="a .mlx filter script to run after importing")
    parser.add_argument("--palette", help="a .pal file for the voxel colours")
    parser.add_argument("--house-colour", help="house colour for palette entries 16..31 (Red, Blue, Green, Gold, ...)")
    parser.add_argument("--frame", type=int, default=0, help="HVA animation frame (default 0)")
    parser.add_argument("--section", type=int, default=-1, help="only this section (default: all)")
    parser.add_argument("--no-transforms", action="store_true", help="leave sections in voxel space")
    parser.add_argument("--jobs", "-j", type=int, default=os.cpu_count() or 1, help="parallel conversions")
    parser.add_argument("--timeout", type=int, default=600, help="seconds allowed per model")
    parser.add_argument("--build", help="voxelfair build folder holding runtime/ (default: ./build)")
    args = parser.parse_args()
    args.formats = [f.strip().lower() for f in args.formats.split(",") if f.strip()]
    bad = [f for f in args.formats if f not in ("ply", "obj")]
    if bad:
        sys.exit(f"voxelfair: unsupported output format {bad[0]!r} (ply or obj)")
    if args.palette and not Path(args.palette).is_file():
        sys.exit(f"voxelfair: {args.palette}: no such palette file")
    if args.script and not Path(args.script).is_file():
        sys.exit(f"voxelfair: {args.script}: no such script")

    server = find_meshlabserver(args.build)
    models = collect_inputs(args.inputs)
    Path(args.output).mkdir(parents=True, exist_ok=True)
    env = importer_environment(args)

    failures = 0
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        jobs = [pool.submit(convert, m, args, server, env) for m in models]
        for done, job in enumerate(concurrent.futures.as_completed(jobs), 1):
            model, outputs, seconds, error = job.result()
            status = "FAILED " + error if error else "-> " + ", ".join(str(o) for o in outputs)
            print(f"[{done}/{len(models)}] {model.name} {status} ({seconds:.2f} s)", flush=True)
            failures += error is not None
    if failures:
        print(f"voxelfair: {failures} of {len(models)} models failed", file=sys.stderr)
        return 1
    print(f"voxelfair: {len(models)} models converted into {args.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
