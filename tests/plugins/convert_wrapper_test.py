"""The batch wrapper meshlab_scripts/voxelfair_convert.py, run as users run it.

usage: convert_wrapper_test.py BUILD_DIR EXAMPLE_VXL

Each case runs the wrapper from a scratch folder with a relative output folder, and checks what
it wrote, where, and what it said.
"""
import shutil
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

HERE = Path(__file__).resolve().parent
WRAPPER = HERE.parent.parent / "meshlab_scripts" / "voxelfair_convert.py"
BUILD, EXAMPLE = Path(sys.argv[1]), Path(sys.argv[2])


def wrapper(cwd, *arguments):
    result = subprocess.run([sys.executable, str(WRAPPER), "--build", str(BUILD), *arguments], cwd=cwd,
                            capture_output=True, text=True, timeout=600)
    return result.returncode, result.stdout + result.stderr


def glb_json(path):
    import json, struct
    data = path.read_bytes()
    return json.loads(data[20:20 + struct.unpack("<I", data[12:16])[0]])


def vox_with_materials(path):
    """A 6 x 6 x 6 MagicaVoxel cube in layers of colour indices 1..6 whose MATL chunks make them
    diffuse, metal, glass, emit (power 2), blend and an unreadable metal."""
    import struct
    def chunk(name, content):
        return name.encode() + struct.pack("<ii", len(content), 0) + content
    def string(text):
        return struct.pack("<i", len(text)) + text.encode()
    def matl(index, props):
        return chunk("MATL", struct.pack("<ii", index, len(props)) + b"".join(string(k) + string(v) for k, v in props))
    voxels = [(x, y, z, 1 + z) for x in range(6) for y in range(6) for z in range(6)]
    body = chunk("SIZE", struct.pack("<iii", 6, 6, 6))
    body += chunk("XYZI", struct.pack("<i", len(voxels)) + b"".join(struct.pack("<4B", *v) for v in voxels))
    body += matl(2, [("_type", "_metal"), ("_metal", "0.8"), ("_rough", "0.3")])
    body += matl(3, [("_type", "_glass"), ("_alpha", "0.6"), ("_ior", "0.45"), ("_rough", "0.1")])
    body += matl(4, [("_type", "_emit"), ("_emit", "0.75"), ("_flux", "2")])
    body += matl(5, [("_type", "_blend"), ("_metal", "0.5"), ("_trans", "0.2"), ("_emit", "0.1")])
    body += matl(6, [("_type", "_metal"), ("_metal", "shiny")])
    path.write_bytes(b"VOX " + struct.pack("<i", 150) + b"MAIN" + struct.pack("<ii", 0, len(body)) + body)


def ply_header(path):
    data = path.read_bytes()
    return data[:data.index(b"end_header")].decode("ascii", "replace")


class ConvertWrapper(unittest.TestCase):
    def setUp(self):
        self.work = Path(tempfile.mkdtemp(prefix="voxelfair-wrapper-"))
        self.inputs = self.work / "models"
        self.inputs.mkdir()
        shutil.copy(EXAMPLE, self.inputs / "tank.vxl")
        if EXAMPLE.with_suffix(".hva").is_file():
            shutil.copy(EXAMPLE.with_suffix(".hva"), self.inputs / "tank.hva")
        self.before = sorted(p.name for p in self.inputs.iterdir())

    def tearDown(self):
        shutil.rmtree(self.work)

    def test_full_mode_writes_everything_into_a_relative_output_folder(self):
        code, output = wrapper(self.work, "models/tank.vxl", "-o", "out")
        self.assertEqual(code, 0, output)
        out = self.work / "out"
        for name in ("tank.ply", "tank.obj", "tank.obj.mtl", "tank_texture.png", "tank_normal.png", "tank_house.png",
                     "tank.glb"):
            self.assertTrue((out / name).is_file() and (out / name).stat().st_size > 0, f"{name} missing\n{output}")
        self.assertEqual((out / "tank_texture.png").read_bytes()[:8], b"\x89PNG\r\n\x1a\n")
        self.assertIn("comment TextureFile tank_texture.png", ply_header(out / "tank.ply"))
        self.assertIn("tank_texture.png", (out / "tank.obj.mtl").read_text())
        # The decimated mesh's normal map, baked from the copy of the faired layer, named by the MTL.
        self.assertEqual((out / "tank_normal.png").read_bytes()[:8], b"\x89PNG\r\n\x1a\n")
        self.assertIn("map_Bump tank_normal.png", (out / "tank.obj.mtl").read_text())
        self.assertIn("Bake Normal Map:", output)
        # By default a small atlas gets a finer normal map (2x or 4x each side, the least that brings
        # the long side to 1024; NormalBakeOptions::minSide); the validator reads it below.
        import struct
        texture = struct.unpack(">II", (out / "tank_texture.png").read_bytes()[16:24])
        scale = next(f for f in (1, 2, 4) if max(texture) * f >= 1024 or f == 4)
        self.assertGreater(scale, 1, texture)  # the example tank's atlas is small: the test sees a finer map
        self.assertEqual(struct.unpack(">II", (out / "tank_normal.png").read_bytes()[16:24]),
                         (texture[0] * scale, texture[1] * scale))
        self.assertIn(f"(x{scale})", output)
        # Matte: no specular highlight.
        self.assertIn("Ks 0.000000 0.000000 0.000000", (out / "tank.obj.mtl").read_text())
        self.assertNotIn("Ks 1", (out / "tank.obj.mtl").read_text())
        self.assertEqual((out / "tank.glb").read_bytes()[:4], b"glTF")
        validator = subprocess.run(["node", str(HERE.parent.parent / "tools" / "gltf_validate.js"), str(out / "tank.glb")],
                                   capture_output=True, text=True)
        self.assertEqual(validator.returncode, 0, validator.stdout + validator.stderr)
        self.assertIn("0 errors, 0 warnings", validator.stdout)
        # The decimated mesh's normal map and the MikkTSpace tangents it was baked against.
        import json
        data = (out / "tank.glb").read_bytes()
        gltf = json.loads(data[20:20 + struct.unpack("<I", data[12:16])[0]])
        self.assertIn("normalTexture", gltf["materials"][0])
        self.assertTrue(all("TANGENT" in p["attributes"] for m in gltf["meshes"] for p in m["primitives"]))
        # The house colour mask (palette 16-31) beside the base colour and in the material's extras,
        # the same PNG embedded.
        self.assertEqual((out / "tank_house.png").read_bytes()[:8], b"\x89PNG\r\n\x1a\n")
        self.assertIn("Bake House Colour Mask:", output)
        mask = gltf["materials"][0]["extras"]["voxelfair_house_colour_mask"]
        view = gltf["bufferViews"][gltf["images"][gltf["textures"][mask["index"]]["source"]]["bufferView"]]
        binary = 20 + struct.unpack("<I", data[12:16])[0] + 8
        start = binary + view.get("byteOffset", 0)
        self.assertEqual(data[start:start + view["byteLength"]], (out / "tank_house.png").read_bytes())
        # Nothing written beside the input model.
        self.assertEqual(sorted(p.name for p in self.inputs.iterdir()), self.before)
        self.assertIn("Texture Atlas:", output)

    def test_obj_is_y_up_unless_asked_and_ply_keeps_the_model_frame(self):
        def vertices(path):
            return [tuple(map(float, line.split()[1:4])) for line in path.read_text().splitlines()
                    if line.startswith("v ")]
        code, output = wrapper(self.work, "models/tank.vxl", "-o", "y", "--formats", "obj", "--decimate", "1")
        self.assertEqual(code, 0, output)
        code, output = wrapper(self.work, "models/tank.vxl", "-o", "z", "--formats", "obj", "--up", "z",
                               "--decimate", "1")
        self.assertEqual(code, 0, output)
        y_up, z_up = vertices(self.work / "y" / "tank.obj"), vertices(self.work / "z" / "tank.obj")
        self.assertEqual(len(y_up), len(z_up))
        for (x, y, z), turned in zip(z_up, y_up):  # a VXL unit faces +x: (x, y, z) -> (y, z, x)
            for a, b in zip((y, z, x), turned):
                self.assertAlmostEqual(a, b, places=4)
        # PLY: the model's frame unless --up y.
        code, output = wrapper(self.work, "models/tank.vxl", "-o", "p", "--formats", "ply", "--up", "y",
                               "--decimate", "1")
        self.assertEqual(code, 0, output)
        self.assertTrue((self.work / "p" / "tank.ply").is_file(), output)

    def test_a_unit_is_converted_once(self):
        shared = Path(__file__).resolve().parents[3] / "shared" / "models" / "vxl"
        if not (shared / "3tnktur.vxl").is_file():
            self.skipTest(f"the shared models are absent: {shared}")
        for name in ("3tnk", "3tnktur", "3tnkbarl"):
            for ext in (".vxl", ".hva"):
                shutil.copy(shared / (name + ext), self.inputs / (name + ext))
        code, output = wrapper(self.work, "models", "-o", "units", "--mode", "import")
        self.assertEqual(code, 0, output)
        self.assertEqual(sorted(p.name for p in (self.work / "units").iterdir()), ["3tnk.ply", "tank.ply"], output)
        code, output = wrapper(self.work, "models", "-o", "parts", "--mode", "import", "--separate-parts")
        self.assertEqual(code, 0, output)
        self.assertEqual(sorted(p.name for p in (self.work / "parts").iterdir()),
                         ["3tnk.ply", "3tnkbarl.ply", "3tnktur.ply", "tank.ply"], output)

    def test_levels_of_detail_share_one_atlas_and_keep_their_shares_of_the_faces(self):
        shared = Path(__file__).resolve().parents[3] / "shared" / "models"
        if not (shared / "vxl" / "3tnktur.vxl").is_file() or not (shared / "vox" / "robo.vox").is_file():
            self.skipTest(f"the shared models are absent: {shared}")
        for name in ("3tnk", "3tnktur", "3tnkbarl"):
            for ext in (".vxl", ".hva"):
                shutil.copy(shared / "vxl" / (name + ext), self.inputs / (name + ext))
        shutil.copy(shared / "vox" / "robo.vox", self.inputs / "robo.vox")
        shares = (1.0, 0.25, 0.05)
        code, output = wrapper(self.work, "models/3tnk.vxl", "models/robo.vox", "-o", "lods", "--lods",
                               ",".join(map(str, shares)))
        self.assertEqual(code, 0, output)
        import json, struct

        def glb(path):
            data = path.read_bytes()
            length = struct.unpack("<I", data[12:16])[0]
            gltf = json.loads(data[20:20 + length])
            return gltf, data[20 + length + 8:]

        def image(gltf, binary, texture):
            view = gltf["bufferViews"][gltf["images"][gltf["textures"][texture]["source"]]["bufferView"]]
            return binary[view.get("byteOffset", 0):view.get("byteOffset", 0) + view["byteLength"]]

        for name in ("3tnk", "robo"):
            faces, base_colours = [], []
            for level in range(len(shares)):
                path = self.work / "lods" / f"{name}_lod{level}.glb"
                self.assertTrue(path.is_file(), f"{path.name} missing\n{output}")
                self.assertTrue((self.work / "lods" / f"{name}_lod{level}_normal.png").is_file(), output)
                validator = subprocess.run(["node", str(HERE.parent.parent / "tools" / "gltf_validate.js"), str(path)],
                                           capture_output=True, text=True)
                self.assertEqual(validator.returncode, 0, validator.stdout + validator.stderr)
                self.assertIn("0 errors, 0 warnings", validator.stdout, path.name)
                gltf, binary = glb(path)
                faces.append(sum(gltf["accessors"][p["indices"]]["count"] // 3
                                 for m in gltf["meshes"] for p in m["primitives"]))
                material = gltf["materials"][0]
                self.assertIn("normalTexture", material, path.name)
                base_colours.append(image(gltf, binary, material["pbrMetallicRoughness"]["baseColorTexture"]["index"]))
                # The maps in the atlas' layout reach every level: the unit's house colour mask,
                # robo's emitter.
                if name == "3tnk":
                    mask = material["extras"]["voxelfair_house_colour_mask"]["index"]
                    self.assertEqual(image(gltf, binary, mask), (self.work / "lods" / "3tnk_house.png").read_bytes())
                else:
                    self.assertEqual(image(gltf, binary, material["emissiveTexture"]["index"]),
                                     (self.work / "lods" / "robo_emissive.png").read_bytes())
            # Level 0 is the faired mesh itself (share 1); each level within 20% of its share of it.
            for level, share in enumerate(shares):
                self.assertLessEqual(abs(faces[level] / faces[0] - share), 0.2 * share, f"{name}: {faces}")
            # One atlas: every level embeds the same base colour, the PNG written beside them.
            texture = (self.work / "lods" / f"{name}_texture.png").read_bytes()
            for level, colour in enumerate(base_colours):
                self.assertEqual(colour, texture, f"{name} level {level}")
        self.assertFalse(any(p.name.endswith((".ply", ".obj")) for p in (self.work / "lods").iterdir()), output)

    def test_levels_of_detail_without_normal_maps_are_refused_before_anything_is_written(self):
        code, output = wrapper(self.work, "models/tank.vxl", "-o", "lods", "--lods", "1,0.25", "--no-normal-map")
        self.assertNotEqual(code, 0, output)
        self.assertIn("--lods bakes a normal map for every level", output)
        self.assertFalse((self.work / "lods").exists(), output)

    def test_a_half_resolution_normal_map_is_half_the_base_colour_each_side(self):
        code, output = wrapper(self.work, "models/tank.vxl", "-o", "half", "--formats", "glb",
                               "--normal-map-resolution", "half")
        self.assertEqual(code, 0, output)
        import struct
        def size(png):
            return struct.unpack(">II", png.read_bytes()[16:24])
        texture = size(self.work / "half" / "tank_texture.png")
        self.assertEqual(size(self.work / "half" / "tank_normal.png"), ((texture[0] + 1) // 2, (texture[1] + 1) // 2))
        self.assertIn("level 1", output)
        validator = subprocess.run(["node", str(HERE.parent.parent / "tools" / "gltf_validate.js"),
                                    str(self.work / "half" / "tank.glb")], capture_output=True, text=True)
        self.assertIn("0 errors, 0 warnings", validator.stdout)

    def test_a_smaller_largest_texture_lowers_the_density_to_fit_it(self):
        import struct
        def size(png):
            return struct.unpack(">II", png.read_bytes()[16:24])
        code, output = wrapper(self.work, "models/tank.vxl", "-o", "free", "--formats", "glb")
        self.assertEqual(code, 0, output)
        free_output = output
        free = size(self.work / "free" / "tank_texture.png")
        self.assertGreater(max(free), 128, output)  # the example needs more than 128 at 8 texels per voxel
        code, output = wrapper(self.work, "models/tank.vxl", "-o", "capped", "--formats", "glb",
                               "--max-texture-size", "128")
        self.assertEqual(code, 0, output)
        self.assertEqual(size(self.work / "capped" / "tank_texture.png"), (128, 128))
        self.assertIn("reduced to fit the maximum size", output)
        self.assertIn("--max-texture-size 256 keeps more texels per voxel", output)  # the way out, named
        self.assertNotIn("keeps more texels per voxel", free_output)  # not where nothing was reduced
        validator = subprocess.run(["node", str(HERE.parent.parent / "tools" / "gltf_validate.js"),
                                    str(self.work / "capped" / "tank.glb")], capture_output=True, text=True)
        self.assertIn("0 errors, 0 warnings", validator.stdout)
        for bad in ("100", "8", "32768"):
            code, output = wrapper(self.work, "models/tank.vxl", "-o", "bad", "--max-texture-size", bad)
            self.assertNotEqual(code, 0, bad)
            self.assertIn("--max-texture-size must be a power of two", output)
        self.assertFalse((self.work / "bad").exists())

    def test_without_decimation_or_with_no_normal_map_no_normal_map_is_written(self):
        for options in (["--decimate", "1"], ["--no-normal-map"]):
            code, output = wrapper(self.work, "models/tank.vxl", "-o", "plain", "--formats", "obj", *options)
            self.assertEqual(code, 0, output)
            self.assertFalse((self.work / "plain" / "tank_normal.png").exists(), options)
            self.assertNotIn("map_Bump", (self.work / "plain" / "tank.obj.mtl").read_text())

    def test_import_and_compare_modes(self):
        code, output = wrapper(self.work, "models", "-o", "imported", "--mode", "import")
        self.assertEqual(code, 0, output)
        self.assertIn("element face", ply_header(self.work / "imported" / "tank.ply"))
        code, output = wrapper(self.work, "models/tank.vxl", "-o", "compared", "--mode", "compare")
        self.assertEqual(code, 0, output)
        labels = ["raw", "voxelfair", "constrained", "taubin", "hc_laplacian", "twostep"]
        if (BUILD / "tools" / "voxelfair_vtk_smooth").is_file():
            labels.append("vtk")
        for label in labels:
            self.assertTrue((self.work / "compared" / f"tank_{label}.ply").is_file(), f"{label}\n{output}")
        # MeshLab's smoothers really moved the voxel surface (TwoStep keeps its 90-degree steps as
        # features: it may leave a voxel surface as it is).
        raw = (self.work / "compared" / "tank_raw.ply").read_bytes()
        for label in ("taubin", "hc_laplacian"):
            self.assertNotEqual((self.work / "compared" / f"tank_{label}.ply").read_bytes(), raw, label)

    def test_vox_materials_become_valid_gltf_pbr(self):
        vox_with_materials(self.inputs / "cube.vox")
        models = [self.inputs / "cube.vox"]
        shared = Path(__file__).resolve().parents[3] / "shared" / "models" / "vox" / "robo.vox"
        if shared.is_file():
            shutil.copy(shared, self.inputs / "robo.vox")
            models.append(self.inputs / "robo.vox")
        code, output = wrapper(self.work, *map(str, models), "-o", "out", "--formats", "glb")
        self.assertEqual(code, 0, output)
        out = self.work / "out"
        for name in ("metallic_roughness", "emissive", "transmission"):
            self.assertTrue((out / f"cube_{name}.png").is_file(), f"{name}\n{output}")
        self.assertIn("1 unreadable MATL values", output)
        validator = subprocess.run(["node", str(HERE.parent.parent / "tools" / "gltf_validate.js"),
                                    *(str(out / (m.stem + ".glb")) for m in models)], capture_output=True, text=True)
        self.assertEqual(validator.returncode, 0, validator.stdout + validator.stderr)
        self.assertEqual(validator.stdout.count("0 errors, 0 warnings"), len(models), validator.stdout)
        cube = glb_json(out / "cube.glb")
        material = cube["materials"][0]
        self.assertIn("metallicRoughnessTexture", material["pbrMetallicRoughness"])
        self.assertIn("emissiveTexture", material)
        self.assertAlmostEqual(material["extensions"]["KHR_materials_emissive_strength"]["emissiveStrength"], 3.0, 5)
        self.assertIn("transmissionTexture", material["extensions"]["KHR_materials_transmission"])
        self.assertAlmostEqual(material["extensions"]["KHR_materials_ior"]["ior"], 1.45, 5)
        self.assertEqual(sorted(cube["extensionsUsed"]), ["KHR_materials_emissive_strength", "KHR_materials_ior",
                                                           "KHR_materials_transmission"])
        self.assertNotIn("extras", material)  # no house colours outside VXL
        if len(models) > 1:  # robo.vox's emitter: an emissive material, no other map
            robo = glb_json(out / "robo.glb")["materials"][0]
            self.assertIn("emissiveTexture", robo)
            self.assertEqual(robo["emissiveFactor"], [1.0, 1.0, 1.0])
            self.assertNotIn("metallicRoughnessTexture", robo["pbrMetallicRoughness"])
            self.assertFalse((out / "robo_transmission.png").exists())

    def test_a_broken_model_is_named_with_the_importers_reason_and_the_others_still_convert(self):
        (self.inputs / "broken.vxl").write_bytes(b"Voxel Animation\0" + b"\xff" * 40)
        code, output = wrapper(self.work, "models", "-o", "out", "--mode", "import")
        self.assertNotEqual(code, 0, output)
        self.assertIn("broken.vxl FAILED", output)
        self.assertIn(f"io_vxl: {self.inputs.resolve() / 'broken.vxl'}: ", output)
        self.assertTrue((self.work / "out" / "tank.ply").is_file(), output)
        self.assertIn("1 of 2 models failed", output)


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1], verbosity=2)
