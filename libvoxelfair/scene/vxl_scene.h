// Turns a parsed VXL (and its HVA) into a VoxelScene according to the import options.
#pragma once

#include "formats/hva.h"
#include "formats/vxl.h"
#include "scene/voxel_scene.h"

#include <optional>
#include <string>
#include <vector>

namespace voxelfair {

struct VxlSceneOptions {
    int section = -1;                          // -1: every section; otherwise only this one
    int frame = 0;                             // HVA frame
    bool applyTransforms = true;               // false: each section in its own voxel space (x, y, z in [0, size])
    const Palette *externalPalette = nullptr;  // a .pal the user chose; wins over the embedded one
    std::optional<Rgb> houseColour;            // regenerate the remap range 16..31 in this colour
};

// Which palette a VXL is shown with, and why (for the log).
struct PaletteChoice {
    Palette palette;
    std::string source;  // "external .pal", "embedded", "built-in default"
};

// External .pal if given; else the embedded palette unless it is all zeros; else the built-in
// default. Then the house-colour range is remapped when asked.
PaletteChoice chooseVxlPalette(const VxlModel &model, const VxlSceneOptions &options);

// Places the chosen sections: with transforms, by sectionToModel() with the HVA matrix of
// options.frame (or the tailer matrix when `hva` is null). Throws FormatError when the section
// or frame does not exist, or the HVA's section count differs from the VXL's.
VoxelScene vxlScene(const VxlModel &model, const HvaAnimation *hva, const VxlSceneOptions &options);

}  // namespace voxelfair
