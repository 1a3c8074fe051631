#include "import_settings.h"

#include <QByteArray>
#include <array>
#include <cstdlib>

namespace voxelfair {

namespace {

struct NamedColour {
    const char *name;
    Rgb rgb;
};

// House colours offered for the remap range; the first entry keeps the palette's own ramp.
const std::array<NamedColour, 10> kHouseColours = {{
    {"Palette's own", {}},
    {"Red", {255, 0, 0}},
    {"Blue", {0, 90, 255}},
    {"Green", {0, 190, 40}},
    {"Gold", {255, 200, 0}},
    {"Orange", {255, 120, 0}},
    {"Teal", {0, 200, 200}},
    {"Purple", {150, 40, 220}},
    {"Pink", {255, 100, 180}},
    {"Grey", {170, 170, 170}},
}};

QString env(const char *name) { return QString::fromLocal8Bit(qgetenv(name)); }

int envInt(const char *name, int fallback) {
    bool ok = false;
    const int value = env(name).trimmed().toInt(&ok);
    return ok ? value : fallback;
}

float envFloat(const char *name, float fallback) {
    bool ok = false;
    const float value = env(name).trimmed().toFloat(&ok);
    return ok ? value : fallback;
}

int houseColourIndexFromEnv() {
    const QString wanted = env("VOXELFAIR_HOUSE_COLOUR").trimmed();
    for (size_t i = 1; i < kHouseColours.size(); ++i)
        if (wanted.compare(kHouseColours[i].name, Qt::CaseInsensitive) == 0)
            return int(i);
    return 0;
}

}  // namespace

void declareImportParameters(RichParameterList &parameters, const QStringList &sectionNames) {
    parameters.addParam(
        RichOpenFile("paletteFile", env("VOXELFAIR_PALETTE"), QStringList() << "*.pal", "Palette file (.pal)",
                     "A Westwood 6-bit .pal (768 bytes) or JASC-PAL file giving the voxels' colours, e.g. unittem.pal. "
                     "Empty: the palette embedded in the .vxl, or the built-in default palette when the embedded one "
                     "is all zeros."));

    QStringList houseNames;
    for (const NamedColour &c : kHouseColours)
        houseNames << c.name;
    parameters.addParam(RichEnum("houseColour", houseColourIndexFromEnv(), houseNames, "House colour",
                                 "Regenerates palette entries 16..31 (the player colour in the game) as a "
                                 "brightness ramp of this colour, as the game tools do."));

    parameters.addParam(RichInt("frame", envInt("VOXELFAIR_FRAME", 0), "HVA frame",
                                "The animation frame of the .hva beside the .vxl that places the sections, from 0."));

    QStringList sections;
    sections << "All sections";
    for (int i = 0; i < sectionNames.size(); ++i)
        sections << QString("%1: %2").arg(i).arg(sectionNames[i]);
    parameters.addParam(RichEnum("section", envInt("VOXELFAIR_SECTION", -1) + 1, sections, "Section",
                                 "Import every section, or only one."));

    parameters.addParam(RichBool("applyTransforms", envInt("VOXELFAIR_TRANSFORMS", 1) != 0, "Apply section transforms",
                                 "Place each section with its .hva matrix (or, without an .hva, its own matrix) and "
                                 "bounds, as the game does. Off: every section in its own voxel space, "
                                 "one unit per voxel, x and y horizontal, z up."));

    parameters.addParam(RichBool("loadUnit", envInt("VOXELFAIR_UNIT", 1) != 0, "Load turret and barrel",
                                 "Opening NAME.vxl also loads NAMEtur.vxl and NAMEbarl.vxl (each with its .hva) from "
                                 "the same folder when they exist, as the game draws a vehicle: the whole unit. Not "
                                 "for a tur/barl file itself, nor when one section is chosen."));
    parameters.addParam(RichFloat("turretOffset", envFloat("VOXELFAIR_TURRET_OFFSET", 0.0f), "Turret offset (leptons)",
                                  "The unit's TurretOffset from the game's art rules: turret and barrel move this many "
                                  "leptons along the unit's forward axis (+x). 256 leptons are one cell; converted to "
                                  "voxels with the body's section scale (Det, 1/12)."));
}

void declareVoxImportParameters(RichParameterList &parameters, int frameCount) {
    parameters.addParam(RichInt("frame", envInt("VOXELFAIR_FRAME", 0), "Animation frame",
                                QString("The frame of the scene's animation to import, from 0%1. Hidden objects and "
                                        "hidden layers are left out.")
                                    .arg(frameCount > 1 ? QString(" to %1").arg(frameCount - 1) : QString())));
}

ImportSettings readImportSettings(const RichParameterList &parameters) {
    ImportSettings s;
    if (parameters.hasParameter("paletteFile"))
        s.paletteFile = parameters.getOpenFileName("paletteFile").trimmed();
    if (parameters.hasParameter("houseColour")) {
        const int house = parameters.getEnum("houseColour");
        if (house > 0 && house < int(kHouseColours.size()))
            s.houseColour = kHouseColours[size_t(house)].rgb;
    }
    if (parameters.hasParameter("frame"))
        s.frame = parameters.getInt("frame");
    if (parameters.hasParameter("section"))
        s.section = parameters.getEnum("section") - 1;
    if (parameters.hasParameter("applyTransforms"))
        s.applyTransforms = parameters.getBool("applyTransforms");
    if (parameters.hasParameter("loadUnit"))
        s.loadUnit = parameters.getBool("loadUnit");
    if (parameters.hasParameter("turretOffset"))
        s.turretOffsetLeptons = parameters.getFloat("turretOffset");
    return s;
}

}  // namespace voxelfair
