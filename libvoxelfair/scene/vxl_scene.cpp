#include "scene/vxl_scene.h"

#include "formats/format_error.h"
#include "formats/vxl_placement.h"

namespace voxelfair {

PaletteChoice chooseVxlPalette(const VxlModel &model, const VxlSceneOptions &options) {
    PaletteChoice choice;
    if (options.externalPalette != nullptr) {
        choice = {*options.externalPalette, "external .pal"};
    } else if (!model.embeddedPalette.allZero()) {
        choice = {model.embeddedPalette, "embedded"};
    } else {
        choice = {defaultPalette(), "built-in default (the embedded palette is all zeros)"};
    }
    if (options.houseColour)
        remapHouseColours(choice.palette, *options.houseColour, model.remapFirst, model.remapLast);
    return choice;
}

VoxelScene vxlScene(const VxlModel &model, const HvaAnimation *hva, const VxlSceneOptions &options) {
    const int sections = int(model.sections.size());
    if (options.section < -1 || options.section >= sections)
        throw FormatError("there is no section " + std::to_string(options.section) + " (the model has " +
                          std::to_string(sections) + ")");
    if (options.applyTransforms && hva != nullptr) {
        if (hva->sectionCount() != sections)
            throw FormatError("the .hva describes " + std::to_string(hva->sectionCount()) +
                              " sections but the .vxl has " + std::to_string(sections));
        if (options.frame < 0 || options.frame >= hva->frameCount)
            throw FormatError("there is no HVA frame " + std::to_string(options.frame) + " (the .hva has " +
                              std::to_string(hva->frameCount) + " frames, numbered from 0)");
    }

    VoxelScene scene;
    scene.palette = chooseVxlPalette(model, options).palette;
    for (int s = 0; s < sections; ++s) {
        if (options.section != -1 && s != options.section)
            continue;
        const VxlSection &section = model.sections[size_t(s)];
        PlacedVolume part;
        part.volume = &section.volume;
        part.part = s;
        part.name = section.name;
        if (options.applyTransforms)
            part.toModel = sectionToModel(section, hva ? &hva->matrix(options.frame, s) : nullptr);
        scene.parts.push_back(part);
    }
    return scene;
}

}  // namespace voxelfair
