#!/usr/bin/env python3
"""Voxel models (.vxl, .vox) to smooth, textured, game-ready meshes with headless MeshLab.

usage: voxelfair_convert.py INPUT [INPUT ...] --output FOLDER [options]

INPUT is a model file or a folder (searched for *.vxl and *.vox). Each model goes through
meshlabserver with voxelfair's plugins:

  --mode full     (default) import, fairing (paper 4.3), attribute smoothing (4.4), texture atlas
                  and baked PNG (4.5), MeshLab's quadric decimation with texture (4.6) of a copy of
                  the faired layer, and the faired layer's shading baked into the decimated mesh's
                  tangent-space normal map (beyond the paper); writes NAME.ply, NAME.obj
                  (+ NAME.obj.mtl naming both maps) and NAME.glb (glTF 2.0, texture embedded, one
                  node per part, animation) with NAME_texture.png and NAME_normal.png beside them;
                  a VXL model's house colours (palette 16-31) as the mask NAME_house.png, also
                  embedded in the .glb (material extras voxelfair_house_colour_mask); a VOX
                  model's MATL materials as NAME_metallic_roughness.png, NAME_emissive.png and
                  NAME_transmission.png (those its voxels need), glTF PBR in the .glb
                  --lods 1,0.25,0.05 (shares of the faired mesh's faces) writes levels of detail
                  instead: NAME_lod0.glb, NAME_lod1.glb, ... from one atlas (NAME_texture.png,
                  shared: decimation with texture keeps the UVs), each decimated copy of the
                  faired layer with its own normal map NAME_lodN_normal.png baked from the full
                  faired mesh, and the same house mask or material maps (not with --no-normal-map)
                  the normal map is the base colour's size, 2x or 4x each side for atlases
                  under 1024 texels (long side at least 1024); --normal-map-resolution atlas
                  keeps the base colour's size, half bakes the normal maps at half its
                  size each side (one texel per 2 x 2 atlas block): a quarter of the memory
  --mode import   the voxel surface only: NAME.ply with face colours and each face's section
  --mode compare  the same input through voxelfair's fairing (paper and constrained modes), through
                  MeshLab's Taubin, HC Laplacian and TwoStep Smooth, and (when the build has
                  it) VTK's windowed sinc: NAME_raw.ply, NAME_voxelfair.ply, NAME_constrained.ply,
                  NAME_taubin.ply, NAME_hc_laplacian.ply, NAME_twostep.ply, NAME_vtk.ply and the
                  seconds of each

A unit is converted once: NAME.vxl brings NAMEtur.vxl and NAMEbarl.vxl along (the importer loads
them), so a tur/barl file whose body is beside it is not converted on its own (--separate-parts
keeps the old behaviour). Axes: glTF is always +Y up with the front towards +Z; OBJ follows its
readers (--up y by default), PLY keeps the voxel model's frame (z up) unless --up y.

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
PLUGIN_PREFIXES = ("io_vxl:", "io_gltf:", "filter_voxelfair:")


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


UNIT_SUFFIXES = ("tur", "barl")


def is_unit_companion(model, models):
    """NAMEtur.vxl / NAMEbarl.vxl whose body NAME.vxl is among the models (same folder)."""
    if model.suffix.lower() != ".vxl":
        return False
    stem = model.stem.lower()
    for suffix in UNIT_SUFFIXES:
        if stem.endswith(suffix) and len(stem) > len(suffix):
            body = stem[: -len(suffix)]
            if any(m.parent == model.parent and m.stem.lower() == body and m.suffix.lower() == ".vxl" for m in models):
                return True
    return False


def collect_inputs(paths, separate_parts=False):
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
    if not separate_parts:
        models = [m for m in models if not is_unit_companion(m, models)]
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
    env["VOXELFAIR_UNIT"] = "0" if args.separate_parts else "1"
    env["VOXELFAIR_TURRET_OFFSET"] = repr(args.turret_offset)
    env["VOXELFAIR_TEXTURE_FILTER"] = args.texture_filter
    env["VOXELFAIR_METRES_PER_VOXEL"] = repr(args.metres_per_voxel)
    return env


def to_y_up(model):
    """(x, y, z) z-up model coordinates -> y-up with the model's front towards +z, as glTF does:
    a VXL unit faces +x, a MagicaVoxel model -y."""
    if model.suffix.lower() == ".vxl":
        return lambda x, y, z: (y, z, x)
    return lambda x, y, z: (x, z, -y)


def turn_obj(path, turn):
    """Rewrites the v and vn lines of an OBJ with `turn`."""
    lines = []
    for line in path.read_text().splitlines():
        parts = line.split()
        if parts and parts[0] in ("v", "vn") and len(parts) >= 4:
            x, y, z = turn(*map(float, parts[1:4]))
            line = " ".join([parts[0], f"{x:.6f}", f"{y:.6f}", f"{z:.6f}"] + parts[4:])
        lines.append(line)
    path.write_text("\n".join(lines) + "\n")


def turn_ply(path, turn):
    """Turns the x y z and nx ny nz float properties of a PLY's vertices (ASCII or binary)."""
    import struct
    data = path.read_bytes()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode("ascii").splitlines()
    fmt = header[1].split()[1]
    kinds = {"char": "b", "uchar": "B", "int8": "b", "uint8": "B", "short": "h", "ushort": "H", "int16": "h",
             "uint16": "H", "int": "i", "uint": "I", "int32": "i", "uint32": "I", "float": "f", "float32": "f",
             "double": "d", "float64": "d"}
    props, count, in_vertex = [], 0, False
    for line in header:
        words = line.split()
        if words[:1] == ["element"]:
            in_vertex = words[1] == "vertex"
            if in_vertex:
                count = int(words[2])
        elif words[:1] == ["property"] and in_vertex:
            if words[1] == "list":
                raise RuntimeError(f"{path}: list properties on vertices are not supported")
            props.append((words[2], kinds[words[1]]))
    names = [n for n, _ in props]
    groups = [[names.index(a) for a in g] for g in (("x", "y", "z"), ("nx", "ny", "nz")) if all(a in names for a in g)]
    if fmt == "ascii":
        text = data[end:].decode("ascii").split("\n")
        for i in range(count):
            values = text[i].split()
            for g in groups:
                turned = turn(*(float(values[k]) for k in g))
                for k, v in zip(g, turned):
                    values[k] = f"{v:.6f}"
            text[i] = " ".join(values)
        path.write_bytes(data[:end] + "\n".join(text).encode("ascii"))
        return
    order = "<" if fmt == "binary_little_endian" else ">"
    record = struct.Struct(order + "".join(k for _, k in props))
    body = bytearray(data[end:])
    for i in range(count):
        values = list(record.unpack_from(body, i * record.size))
        for g in groups:
            for k, v in zip(g, turn(*(values[k] for k in g))):
                values[k] = v
        record.pack_into(body, i * record.size, *values)
    path.write_bytes(data[:end] + bytes(body))


def matte_mtl(path):
    """No specular highlight: vcglib writes Ks 1 1 1, which makes painted voxels look like wet plastic."""
    lines = ["Ks 0.000000 0.000000 0.000000" if line.split()[:1] == ["Ks"] else line
             for line in path.read_text().splitlines()]
    path.write_text("\n".join(lines) + "\n")


def pipeline_script(args, texture, normal, house=None, materials=None):
    """The full-pipeline .mlx with this run's values; the decimation (and with it the layer copy and
    the normal map) is left out at ratio 1, the house colour mask without `house` (not a VXL), the
    material maps without `materials` (not a VOX: metallic-roughness, emissive, transmission paths)."""
    text = (HERE / "voxelfair_pipeline.mlx").read_text()
    values = {
        "MODE": "1" if args.fairing == "constrained" else "0",
        "LAMBDA": repr(args.lambda_), "PASSES": str(args.passes),
        "PACKING": "1" if args.packing == "paper" else "0",
        "TEXELS_PER_VOXEL": repr(args.texels_per_voxel), "MAX_TEXTURE_SIZE": str(args.max_texture_size),
        "COLOURS": "1" if args.colours == "smoothed" else "0",
        "TEXTURE_FILE": str(texture), "DECIMATION": repr(args.decimate), "NORMAL_FILE": str(normal),
        "HOUSE_FILE": str(house or ""), "NORMAL_LEVEL": "1" if args.normal_map_resolution == "half" else "0",
        "NORMAL_MIN_SIDE": "0" if args.normal_map_resolution == "atlas" else "1024",
        "BLOCKS": "false" if args.packing == "paper" else "true",
    }
    for key, path in zip(("METAL_ROUGH_FILE", "EMISSIVE_FILE", "TRANSMISSION_FILE"), materials or ("", "", "")):
        values[key] = str(path)
    for key, value in values.items():
        text = text.replace(f"@{key}@", value.replace("&", "&amp;").replace('"', "&quot;"))
    if args.decimate >= 1.0 or args.no_normal_map:
        text = text.replace(' <filter name="Duplicate Current layer"/>\n', "")
        text = re.sub(r' <filter name="Voxel Texture: Bake Normal Map">.*?</filter>\n', "", text, flags=re.S)
    if args.decimate >= 1.0:
        text = re.sub(r' <filter name="Simplification:.*?</filter>\n', "", text, flags=re.S)
    if house is None:
        text = re.sub(r' <filter name="Voxel Texture: Bake House Colour Mask">.*?</filter>\n', "", text, flags=re.S)
    if materials is None:
        text = re.sub(r' <filter name="Voxel Texture: Bake Material Maps">.*?</filter>\n', "", text, flags=re.S)
    return text


def name_normal_map(mtl, normal):
    """vcglib's OBJ writer knows one texture: the MTL gets the normal map too (map_Bump, which
    Blender's and most importers read as a normal map, and norm, the PBR extension's name)."""
    out = []
    for line in mtl.read_text().splitlines():
        out.append(line)
        if line.strip().startswith("map_Kd"):
            out += [f"map_Bump {normal.name}", f"norm {normal.name}"]
    mtl.write_text("\n".join(out) + "\n")


def lod_script(text, lods, normals):
    """The pipeline .mlx with its tail (copy of the faired layer, decimation, normal map) once per
    level of detail: the faired layer (0) made current again, copied (the copy becomes layer k + 1),
    decimated to its share (not at 1), its normal map baked from layer 0. Everything before the
    tail (fairing, atlas, maps in the atlas' layout) runs once."""
    begin = text.index(' <filter name="Duplicate Current layer"/>')
    end = text.index("</FilterScript>")
    tail = text[begin:end]
    blocks = []
    for level, (share, normal) in enumerate(zip(lods, normals)):
        block = tail
        if share >= 1.0:
            block = re.sub(r' <filter name="Simplification:.*?</filter>\n', "", block, flags=re.S)
        block = re.sub(r'(name="TargetPerc" value=")[^"]*"', lambda m: m.group(1) + repr(share) + '"', block)
        block = re.sub(r'(name="normalFile" value=")[^"]*"',
                       lambda m: m.group(1) + str(normal).replace("&", "&amp;").replace('"', "&quot;") + '"', block)
        if level > 0:
            block = ' <filter name="Change the current layer">\n  <Param type="RichMesh" name="layer" value="0"/>\n' \
                    ' </filter>\n' + block
        blocks.append(block)
    return text[:begin] + "".join(blocks) + text[end:]


def layout_maps(model, out):
    """The maps baked in the atlas' layout that fit the input: a VXL's house colour mask (the
    remap range), a VOX's material maps (metallic-roughness, emissive, transmission; each written
    only when some voxel needs it). Returns (house or None, materials or None)."""
    name = model.stem
    house = out / f"{name}_house.png" if model.suffix.lower() == ".vxl" else None
    materials = None
    if model.suffix.lower() == ".vox":
        materials = tuple(out / f"{name}_{m}.png" for m in ("metallic_roughness", "emissive", "transmission"))
    return house, materials


def convert_lods(model, args, run):
    """--lods: one meshlabserver run writes NAME_lodN.glb for every share (layer N + 1 of the
    document); returns (outputs, details)."""
    out, name = Path(args.output), model.stem
    texture = out / f"{name}_texture.png"
    glbs = [out / f"{name}_lod{level}.glb" for level in range(len(args.lods))]
    normals = [out / f"{name}_lod{level}_normal.png" for level in range(len(args.lods))]
    with tempfile.TemporaryDirectory(prefix="voxelfair-script-") as tmp:
        script = Path(tmp) / "pipeline.mlx"
        # The single-mesh script with a copy and a normal map (decimation below 1), then repeated.
        single = argparse.Namespace(**dict(vars(args), decimate=0.5, no_normal_map=False))
        house, materials = layout_maps(model, out)
        text = lod_script(pipeline_script(single, texture, normals[0], house, materials), args.lods, normals)
        script.write_text(text)
        arguments = ["-i", str(model)]
        for level, glb in enumerate(glbs):
            arguments += ["-o", str(glb), "-l", str(level + 1), "-m", "wt", "vn"]
        code, output, _ = run(arguments + ["-s", str(script)])
    maps = normals + ([house] if house else [])
    check([texture] + maps + glbs, code, output)
    maps += [m for m in materials or () if m.is_file()]
    details = [line.split(": ", 1)[1] for line in output.splitlines()
               if line.startswith(("filter_voxelfair: Texture Atlas", "filter_voxelfair: Bake Normal Map",
                                   "filter_voxelfair: Bake House Colour Mask", "filter_voxelfair: Bake Material Maps"))]
    return [texture] + maps + glbs, details


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

    if args.lods:
        outputs, details = convert_lods(model, args, run)
        return outputs, time.monotonic() - started, details

    ply, obj, glb = out / f"{name}.ply", out / f"{name}.obj", out / f"{name}.glb"
    texture = out / f"{name}_texture.png"
    normal = out / f"{name}_normal.png"
    with_normal = args.decimate < 1.0 and not args.no_normal_map
    house, materials = layout_maps(model, out)
    maps = [normal] if with_normal else []
    maps += [house] if house else []
    with tempfile.TemporaryDirectory(prefix="voxelfair-script-") as tmp:
        script = Path(tmp) / "pipeline.mlx"
        script.write_text(pipeline_script(args, texture, normal, house, materials))
        # Saved without face colours: the texture holds them now, and vcglib's OBJ writer would
        # otherwise make one material per face colour. The .glb is written by the same run: the
        # parts' node tree travels with the imported mesh through the filters.
        arguments = ["-i", str(model), "-o", str(ply), "-m", "wt", "vn"]
        if "glb" in args.formats:
            arguments += ["-o", str(glb), "-m", "wt", "vn"]
        code, output, _ = run(arguments + ["-s", str(script)])
    check([ply, texture] + maps + ([glb] if "glb" in args.formats else []), code, output)
    details += [line.split(": ", 1)[1] for line in output.splitlines()
                if line.startswith(("filter_voxelfair: Texture Atlas", "filter_voxelfair: Bake Normal Map",
                                    "filter_voxelfair: Bake House Colour Mask",
                                    "filter_voxelfair: Bake Material Maps"))]
    maps += [m for m in materials or () if m.is_file()]
    details += ["glTF " + line.split(": ", 2)[2] for line in output.splitlines() if line.startswith("io_gltf: ")]
    if "obj" in args.formats:
        code, output, _ = run(["-i", str(ply), "-o", str(obj), "-m", "wt", "vn"])
        check([obj, out / f"{name}.obj.mtl"], code, output)
        matte_mtl(out / f"{name}.obj.mtl")
        if with_normal:
            name_normal_map(out / f"{name}.obj.mtl", normal)
        if args.up_obj == "y":
            turn_obj(obj, to_y_up(model))
    if "ply" in args.formats and args.up_ply == "y":
        turn_ply(ply, to_y_up(model))
    outputs = [ply, texture] + maps + [out / f"{name}.{f}" for f in ("obj", "glb") if f in args.formats]
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
    parser.add_argument("--formats", default="ply,obj,glb", help="full mode: any of ply, obj, glb (default ply,obj,glb)")
    parser.add_argument("--up", choices=("y", "z"),
                        help="up axis of OBJ and PLY (default: OBJ y, as its readers expect; PLY z, the model's frame)")
    parser.add_argument("--texture-filter", choices=("nearest", "linear"), default="nearest",
                        help="glTF texture sampling: nearest keeps pixel art crisp (default), linear blurs")
    parser.add_argument("--metres-per-voxel", type=float, default=0.1, help="glTF scale: metres per voxel (default 0.1)")
    parser.add_argument("--turret-offset", type=float, default=0.0,
                        help="VXL units: the art rules' TurretOffset in leptons (default 0)")
    parser.add_argument("--separate-parts", action="store_true",
                        help="VXL: convert NAMEtur/NAMEbarl files on their own and bodies without them")
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
    parser.add_argument("--max-texture-size", type=int, default=4096,
                        help="largest texture side, a power of two from 16 to 16384 (default 4096); a model that "
                             "needs more at --texels-per-voxel gets a lower density (doc/limits.md: large models)")
    parser.add_argument("--packing", choices=("tight", "paper"), default="tight", help="atlas packer (default tight)")
    parser.add_argument("--colours", choices=("crisp", "smoothed"), default="crisp", help="texture colours (default crisp)")
    parser.add_argument("--decimate", type=float, default=0.5,
                        help="keep this share of the faces with MeshLab's quadric decimation (default 0.5; 1 = none)")
    parser.add_argument("--lods", help="levels of detail instead of one mesh: shares of the faired mesh's faces, "
                        "e.g. 1,0.25,0.05 -> NAME_lod0.glb, NAME_lod1.glb, NAME_lod2.glb (glTF only)")
    parser.add_argument("--no-normal-map", action="store_true",
                        help="do not bake the faired mesh's shading into a normal map for the decimated mesh")
    parser.add_argument("--normal-map-resolution", choices=("full", "atlas", "half"), default="full",
                        help="full (default): the base colour's size, or 2x / 4x each side for atlases under 1024 "
                        "texels on the long side (the map's long side at least 1024; same UVs); atlas: the base "
                        "colour's size always; half: half each side, one texel per 2 x 2 block of the atlas (its "
                        "mip 1): a quarter of the texels, memory and baking time")
    parser.add_argument("--jobs", "-j", type=int, default=os.cpu_count() or 1, help="models converted at once")
    parser.add_argument("--timeout", type=int, default=600, help="seconds allowed per meshlabserver run")
    parser.add_argument("--build", help="voxelfair build folder holding runtime/ (default: ./build)")
    args = parser.parse_args()
    args.formats = [f.strip().lower() for f in args.formats.split(",") if f.strip()]
    if not args.formats or any(f not in ("ply", "obj", "glb") for f in args.formats):
        sys.exit("voxelfair: --formats takes a comma-separated list of ply, obj, glb")
    args.up_obj = args.up or "y"
    args.up_ply = args.up or "z"
    if not args.metres_per_voxel > 0:
        sys.exit("voxelfair: --metres-per-voxel must be positive")
    if not 0.0 < args.decimate <= 1.0:
        sys.exit("voxelfair: --decimate takes a share of the faces in (0, 1]")
    if args.lods:
        try:
            args.lods = [float(share) for share in args.lods.split(",") if share.strip()]
        except ValueError:
            args.lods = []
        if not args.lods or any(not 0.0 < share <= 1.0 for share in args.lods):
            sys.exit("voxelfair: --lods takes a comma-separated list of shares of the faces in (0, 1], e.g. 1,0.25,0.05")
        if args.mode != "full":
            sys.exit("voxelfair: --lods needs --mode full")
        if args.no_normal_map:
            # Each level is a decimated copy of the faired layer; its normal-map bake is also what
            # gives the copy back its parts (one glTF node per part) and its maps in the atlas' layout.
            sys.exit("voxelfair: --lods bakes a normal map for every level (the bake also gives each decimated "
                     "copy back its parts and maps); drop --no-normal-map, or use --decimate for one mesh without it")
    if args.passes < 1 or args.texels_per_voxel <= 0:
        sys.exit("voxelfair: --passes must be at least 1 and --texels-per-voxel positive")
    if not 16 <= args.max_texture_size <= 16384 or args.max_texture_size & (args.max_texture_size - 1):
        sys.exit("voxelfair: --max-texture-size must be a power of two from 16 to 16384")
    if args.palette and not Path(args.palette).is_file():
        sys.exit(f"voxelfair: {args.palette}: no such palette file")
    # Absolute, so the texture goes where the meshes go: the filter resolves a relative texture
    # name against the folder of the mesh's file, which is the input model's.
    args.output = str(Path(args.output).resolve())

    run = Run(find_meshlabserver(args.build), importer_environment(args), args.timeout)
    models = collect_inputs(args.inputs, args.separate_parts)
    Path(args.output).mkdir(parents=True, exist_ok=True)

    failures = 0
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        jobs = {pool.submit(convert, m, args, run): m for m in models}
        for done, job in enumerate(concurrent.futures.as_completed(jobs), 1):
            model = jobs[job]
            try:
                outputs, seconds, details = job.result()
                if args.max_texture_size < 16384 and any("reduced to fit the maximum size" in d for d in details):
                    details.append(f"the texture is capped at {args.max_texture_size} x {args.max_texture_size}: "
                                   f"--max-texture-size {2 * args.max_texture_size} keeps more texels per voxel")
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
