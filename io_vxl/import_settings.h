// The importer's pre-open parameters: declared for MeshLab's dialog, read back into options.
//
// meshlabserver cannot set an importer's parameters, so each default can be overridden by an
// environment variable; the batch scripts use them:
//   VOXELFAIR_PALETTE         path of a .pal file (empty: embedded palette, else built-in)
//   VOXELFAIR_HOUSE_COLOUR    one of the house colour names below, case-insensitive ("none" keeps the palette's)
//   VOXELFAIR_FRAME           animation frame (VXL: of the .hva; VOX: of the scene graph), from 0
//   VOXELFAIR_SECTION         section number from 0, or -1 for all sections
//   VOXELFAIR_TRANSFORMS      1 to place sections by their HVA/tailer matrices, 0 to leave them in voxel space
//   VOXELFAIR_UNIT            0 to import NAME.vxl alone, without NAMEtur.vxl and NAMEbarl.vxl beside it
//   VOXELFAIR_TURRET_OFFSET   the unit's TurretOffset in leptons (art rules; not in the files), default 0
#pragma once

#include "formats/palette.h"

#include <common/filter_parameter/rich_parameter_list.h>

#include <QString>
#include <QStringList>
#include <optional>

namespace voxelfair {

struct ImportSettings {
    QString paletteFile;  // empty: none chosen
    std::optional<Rgb> houseColour;
    int frame = 0;
    int section = -1;  // -1: all
    bool applyTransforms = true;
    bool loadUnit = true;  // also NAMEtur.vxl and NAMEbarl.vxl (+ .hva) beside NAME.vxl
    float turretOffsetLeptons = 0.0f;
};

// Adds the VXL parameters, with defaults from the environment. `sectionNames` fills the section
// choice (the GUI shows "All sections", then "0: Body", ...).
void declareImportParameters(RichParameterList &parameters, const QStringList &sectionNames);

// Adds the VOX parameters (the animation frame; `frameCount` frames, when known, for the help text).
void declareVoxImportParameters(RichParameterList &parameters, int frameCount);

// Reads back whichever parameters were declared; the others keep their defaults.
ImportSettings readImportSettings(const RichParameterList &parameters);

}  // namespace voxelfair
