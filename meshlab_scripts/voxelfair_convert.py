#!/usr/bin/env python3
"""Voxel models (.vxl, .vox) to smooth, textured, game-ready meshes with headless MeshLab.

usage: voxelfair_convert.py INPUT [INPUT ...] --output FOLDER [options]

INPUT is a model file or a folder (searched for *.vxl and *.vox). Each model goes through
meshlabserver with voxelfair's plugins:

  --mode full     (default) import, fairing (paper 4.3), attribute smoothing (4.4), texture atlas
                  and baked PNG (4.5), MeshLab's quadric decimation with texture (4.6); writes
                  NAME.ply and NAME.obj (+ NAME.obj.mtl) with NAME_texture.png beside them
  --mode import   the voxel surface only: NAME.ply with face colours and each face's section
  --mode compare  the same input through voxelfair's fairing (paper and constrained modes), through
                  MeshLab's Taubin, HC Laplacian and TwoStep Smooth, and (when the build has
                  it) VTK's windowed sinc: NAME_raw.ply, NAME_voxelfair.ply, NAME_constrained.ply,
                  NAME_taubin.ply, NAME_hc_laplacian.ply, NAME_twostep.ply, NAME_vtk.ply and the
                  seconds of each

Files run in parallel on the available cores. meshlabserver exits 0 even when it could not save
and never prints an importer's error: this wrapper checks that every output really was written,
relays the plugins' messages, and exits non-zero with a clear message if anything failed.
"""
import argparse
import concurrent.futures
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
MODEL_SUFFIXES = (".vxl", ".vox")
PLUGIN_PREFIXES = ("io_vxl:", "filter_voxelfair:")


def find_meshlabserver(build):
    """The private runtime in the build tree first, then an installed meshlabserver."""
    candidates = [Path(build) / "runtime" / "bin" / "meshlabserver"] if build else []
    candidates.append(HERE.parent / "build" / "runtime" / "bin" / "meshlabserver")
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
    names = {}
    for m in models:
        if m.stem in names:
            sys.exit(f"voxelfair: {m} and {names[m.stem]} would write the same outputs")
        names[m.stem] = m
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


def pipeline_script(args, texture):
    """The full-pipeline .mlx with this run's values; the decimation is left out at ratio 1."""
    text = (HERE / "voxelfair_pipeline.mlx").read_text()
    values = {
        "MODE": "1" if args.fairing == "constrained" else "0",
        "LAMBDA": repr(args.lambda_), "PASSES": str(args.passes),
        "PACKING": "1" if args.packing == "paper" else "0",
        "TEXELS_PER_VOXEL": repr(args.texels_per_voxel),
        "COLOURS": "1" if args.colours == "smoothed" else "0",
        "TEXTURE_FILE": str(texture), "DECIMATION": repr(args.decimate),
    }
    for key, value in values.items():
        text = text.replace(f"@{key}@", value.replace("&", "&amp;").replace('"', "&quot;"))
    if args.decimate >= 1.0:
        text = re.sub(r' <filter name="Simplification:.*?</filter>\n', "", text, flags=re.S)
    return text


class Run:
    """One meshlabserver process in private XDG folders, under xvfb-run."""

    def __init__(self, server, env, timeout):
        self.server, self.env, self.timeout = server, env, timeout

    def __call__(self, arguments):
        with tempfile.TemporaryDirectory(prefix="voxelfair-") as private:
            env = dict(self.env, XDG_CONFIG_HOME=private, XDG_RUNTIME_DIR=private)
            command = ["xvfb-run", "-a", "-s", "-screen 0 640x480x24", self.server] + arguments
            started = time.monotonic()
            try:
                result = subprocess.run(command, env=env, capture_output=True, text=True, timeout=self.timeout)
            except subprocess.TimeoutExpired:
                raise RuntimeError(f"meshlabserver took more than {self.timeout} s")
            output = result.stdout + result.stderr
            return result.returncode, output, time.monotonic() - started


def check(outputs, code, output):
    """Raises with the plugins' own words when meshlabserver failed or wrote nothing."""
    missing = [str(o) for o in outputs if not o.is_file() or o.stat().st_size == 0]
    if code == 0 and not missing:
        return
    plugin_lines = [line for line in output.splitlines() if line.startswith(PLUGIN_PREFIXES)]
    other_lines = [line for line in output.strip().splitlines() if line.strip()]
    reason = plugin_lines[-1] if plugin_lines else (other_lines[-1] if other_lines else "no message")
    what = f"meshlabserver exited with {code}" if code else "not written: " + ", ".join(missing)
    raise RuntimeError(f"{what}: {reason}")


def convert(model, args, run):
    """Returns (outputs, seconds, details) for one model; raises RuntimeError on failure."""
    out = Path(args.output)
    name = model.stem
    for stale in out.glob(f"{name}*"):
        if stale.is_file() and stale.name.startswith((name + ".", name + "_")):
            stale.unlink()
    started = time.monotonic()
    details = []

    if args.mode == "import":
        ply = out / f"{name}.ply"
        code, output, _ = run(["-i", str(model), "-o", str(ply), "-m", "fc", "fq"])
        check([ply], code, output)
        return [ply], time.monotonic() - started, details

    if args.mode == "compare":
        outputs = []
        for label, script in (("raw", None), ("voxelfair", "compare_voxelfair.mlx"),
                              ("constrained", "compare_constrained.mlx"), ("taubin", "compare_taubin.mlx"),
                              ("hc_laplacian", "compare_hc_laplacian.mlx"), ("twostep", "compare_twostep.mlx")):
            ply = out / f"{name}_{label}.ply"
            arguments = ["-i", str(model), "-o", str(ply), "-m", "fc", "vn"]
            if script:
                arguments += ["-s", str(HERE / script)]
            code, output, seconds = run(arguments)
            check([ply], code, output)
            outputs.append(ply)
            details.append(f"{label} {seconds:.2f} s")
        vtk_tool = Path(args.build or HERE.parent / "build") / "tools" / "voxelfair_vtk_smooth"
        if vtk_tool.is_file():  # VTK's discrete marching cubes + windowed sinc (tools/vtk_smooth.cpp)
            ply, begun = out / f"{name}_vtk.ply", time.monotonic()
            command = [str(vtk_tool), str(model), str(ply)] + (["--palettes", str(Path(args.palette).parent)]
                                                                if args.palette else [])
            result = subprocess.run(command, capture_output=True, text=True, timeout=args.timeout)
            if result.returncode != 0 or not ply.is_file():
                raise RuntimeError(f"VTK: {(result.stderr or result.stdout).strip() or 'no output'}")
            outputs.append(ply)
            details.append(f"vtk {time.monotonic() - begun:.2f} s")
        return outputs, time.monotonic() - started, details

    ply, obj = out / f"{name}.ply", out / f"{name}.obj"
    texture = out / f"{name}_texture.png"
    with tempfile.TemporaryDirectory(prefix="voxelfair-script-") as tmp:
        script = Path(tmp) / "pipeline.mlx"
        script.write_text(pipeline_script(args, texture))
        # Saved without face colours: the texture holds them now, and vcglib's OBJ writer would
        # otherwise make one material per face colour.
        code, output, _ = run(["-i", str(model), "-o", str(ply), "-m", "wt", "vn", "-s", str(script)])
    check([ply, texture], code, output)
    details += [line.split(": ", 1)[1] for line in output.splitlines() if line.startswith("filter_voxelfair: Texture Atlas")]
    if "obj" in args.formats:
        code, output, _ = run(["-i", str(ply), "-o", str(obj), "-m", "wt", "vn"])
        check([obj, out / f"{name}.obj.mtl"], code, output)
    outputs = [ply, texture] + ([obj] if "obj" in args.formats else [])
    if "ply" not in args.formats:
        ply.unlink()
        outputs.remove(ply)
    return outputs, time.monotonic() - started, details


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__.split("\n\n", 2)[2])
    parser.add_argument("inputs", nargs="+", help="model files or folders")
    parser.add_argument("--output", "-o", required=True, help="output folder")
    parser.add_argument("--mode", choices=("full", "import", "compare"), default="full")
    parser.add_argument("--formats", default="ply,obj", help="full mode: ply, obj or both (default ply,obj)")
    parser.add_argument("--palette", help="a .pal file for VXL colours")
    parser.add_argument("--house-colour", help="house colour for palette entries 16..31 (Red, Blue, Green, Gold, ...)")
    parser.add_argument("--frame", type=int, default=0, help="animation frame (VXL: .hva; VOX: scene graph), default 0")
    parser.add_argument("--section", type=int, default=-1, help="VXL: only this section (default: all)")
    parser.add_argument("--no-transforms", action="store_true", help="VXL: leave sections in voxel space")
    parser.add_argument("--fairing", choices=("paper", "constrained"), default="paper",
                        help="fairing mode: the paper's operator (default) or the constrained mode beyond it")
    parser.add_argument("--lambda", dest="lambda_", type=float, default=4.0 / 3.0, help="fairing lambda (default 4/3)")
    parser.add_argument("--passes", type=int, default=1, help="fairing passes (default 1)")
    parser.add_argument("--texels-per-voxel", type=float, default=8.0, help="texture resolution (default 8)")
    parser.add_argument("--packing", choices=("tight", "paper"), default="tight", help="atlas packer (default tight)")
    parser.add_argument("--colours", choices=("crisp", "smoothed"), default="crisp", help="texture colours (default crisp)")
    parser.add_argument("--decimate", type=float, default=0.5,
                        help="keep this share of the faces with MeshLab's quadric decimation (default 0.5; 1 = none)")
    parser.add_argument("--jobs", "-j", type=int, default=os.cpu_count() or 1, help="models converted at once")
    parser.add_argument("--timeout", type=int, default=600, help="seconds allowed per meshlabserver run")
    parser.add_argument("--build", help="voxelfair build folder holding runtime/ (default: ./build)")
    args = parser.parse_args()
    args.formats = [f.strip().lower() for f in args.formats.split(",") if f.strip()]
    if not args.formats or any(f not in ("ply", "obj") for f in args.formats):
        sys.exit("voxelfair: --formats takes ply, obj or ply,obj")
    if not 0.0 < args.decimate <= 1.0:
        sys.exit("voxelfair: --decimate takes a share of the faces in (0, 1]")
    if args.passes < 1 or args.texels_per_voxel <= 0:
        sys.exit("voxelfair: --passes must be at least 1 and --texels-per-voxel positive")
    if args.palette and not Path(args.palette).is_file():
        sys.exit(f"voxelfair: {args.palette}: no such palette file")
    # Absolute, so the texture goes where the meshes go: the filter resolves a relative texture
    # name against the folder of the mesh's file, which is the input model's.
    args.output = str(Path(args.output).resolve())

    run = Run(find_meshlabserver(args.build), importer_environment(args), args.timeout)
    models = collect_inputs(args.inputs)
    Path(args.output).mkdir(parents=True, exist_ok=True)

    failures = 0
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        jobs = {pool.submit(convert, m, args, run): m for m in models}
        for done, job in enumerate(concurrent.futures.as_completed(jobs), 1):
            model = jobs[job]
            try:
                outputs, seconds, details = job.result()
                extra = f" [{'; '.join(details)}]" if details else ""
                print(f"[{done}/{len(models)}] {model.name} -> {', '.join(o.name for o in outputs)} "
                      f"({seconds:.2f} s){extra}", flush=True)
            except RuntimeError as error:
                failures += 1
                print(f"[{done}/{len(models)}] {model.name} FAILED: {error}", flush=True)
    if failures:
        print(f"voxelfair: {failures} of {len(models)} models failed", file=sys.stderr)
        return 1
    print(f"voxelfair: {len(models)} models converted into {args.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
