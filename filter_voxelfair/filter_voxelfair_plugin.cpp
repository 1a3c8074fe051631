#include "filter_voxelfair_plugin.h"

#include "maps/normal_bake.h"

#include <cstdio>
#include <exception>
#include <new>

namespace {

// The gutter of a map baked into the atlas' layout (house mask, material maps, normal map):
// `when` qualifies the block rule ("at full size, " for the normal map, which may be halved).
void addMapGutterParameters(RichParameterList &parameters, const QString &when) {
    parameters.addParam(RichInt("dilation", 1, "Gutter rings",
                                "Rings of the map's texels filled around the charts, as the base colour's (half the "
                                "atlas' gutter at full size)."));
    parameters.addParam(RichBool("blocks", true, "Atlas on 2 x 2 blocks",
                                 "The atlas was packed on 2 x 2 blocks (tight packing, the default): " + when +
                                     "after the rings every block a chart touches is filled, as the base colour's, so "
                                     "mip level 1 keeps the charts apart. Off for the paper's packing."));
}

}  // namespace

FilterVoxelfairPlugin::FilterVoxelfairPlugin() {
    typeList << FP_LANCZOS_FAIRING << FP_ATTRIBUTE_SMOOTHING << FP_TEXTURE_ATLAS << FP_NORMAL_MAP << FP_HOUSE_MASK
             << FP_MATERIAL_MAPS;
    for (FilterIDType id : types())
        actionList << new QAction(filterName(id), this);
}

QString FilterVoxelfairPlugin::filterName(FilterIDType filter) const {
    switch (filter) {
    case FP_LANCZOS_FAIRING: return "Voxel Fairing: Modified Lanczos";
    case FP_ATTRIBUTE_SMOOTHING: return "Voxel Fairing: Attribute Smoothing";
    case FP_TEXTURE_ATLAS: return "Voxel Texture Atlas: Greedy Charts";
    case FP_NORMAL_MAP: return "Voxel Texture: Bake Normal Map";
    case FP_HOUSE_MASK: return "Voxel Texture: Bake House Colour Mask";
    case FP_MATERIAL_MAPS: return "Voxel Texture: Bake Material Maps";
    }
    return QString();
}

QString FilterVoxelfairPlugin::filterInfo(FilterIDType filter) const {
    switch (filter) {
    case FP_LANCZOS_FAIRING:
        return "Smooths a voxel surface in one pass, strongly where the voxel staircase is and gently where "
               "the shape is flat: the modified discrete Laplacian with a Lanczos kernel of "
               "<i>Fast polygonization and texture map extraction from volumetric objects based on surface "
               "fairing using a modified discrete Laplacian operator</i> (SBGames 2010, section 4.3), as its "
               "authors implemented it.<br>Each vertex moves, per axis, by 1 - Lanczos3 of lambda times the mean "
               "unit vector to its neighbours (every vertex sharing a polygon with it, quad diagonals included), "
               "all vertices reading the old positions. Works on any mesh; meant for the quad meshes the VXL "
               "importer produces. The displacement is in voxels, so a scaled model smooths the same.";
    case FP_ATTRIBUTE_SMOOTHING:
        return "Section 4.4 of the SBGames 2010 paper: turns the polygons (quads) into triangles and computes "
               "per-vertex normals as the normalised mean of the <b>distinct</b> normals of the adjacent faces "
               "(repeated directions counted once, so a voxel corner gets the diagonal whatever its faces' sizes) "
               "and per-vertex colours as the mean of the adjacent faces' colours.";
    case FP_TEXTURE_ATLAS:
        return "Section 4.5 of the SBGames 2010 paper: splits the mesh into charts grown greedily from the most "
               "axis-aligned faces (a face joins while its normal stays within the chart angle of the seed face's), "
               "projects each chart orthographically at one texel density, packs them into one square texture and "
               "bakes a diffuse texture, saved as a PNG and referenced by the mesh (per-wedge UVs), ready for "
               "MeshLab's "
               "<i>Quadric Edge Collapse Decimation (with texture)</i> and the PLY/OBJ exporters.<br>"
               "<b>Crisp</b> colours give every texel the colour of the voxel face it lies in, so pixel art keeps "
               "every voxel; <b>smoothed</b> bakes the vertex colours of the attribute smoothing, as the paper does. "
               "<b>Tight</b> packing fills the charts' shapes bottom-left (about 75% coverage); <b>paper</b> is the "
               "authors' guillotine merge of bounding boxes. Save the mesh in the texture's folder: the mesh refers "
               "to the texture by its file name.";
    case FP_NORMAL_MAP:
        return "Beyond the SBGames 2010 paper (its future work: normal maps): bakes the shading of the <b>source</b> "
               "layer (the undecimated faired mesh) into a tangent-space normal map in the atlas of the <b>current</b> "
               "layer (its decimation, which kept the atlas' texture coordinates), so a light mesh keeps the faired "
               "surface's shading.<br>Workflow: Voxel Texture Atlas, <i>Duplicate Current layer</i>, decimate the copy "
               "with <i>Quadric Edge Collapse Decimation (with texture)</i>, then this filter with the original layer "
               "as source.<br>Tangents are MikkTSpace's (the convention of glTF, Blender, Unity, Unreal and Godot), "
               "computed from the current layer's vertex normals and texture coordinates; green is +V (OpenGL / glTF "
               "convention). The map is a PNG with a gutter like the base colour's.";
    case FP_HOUSE_MASK:
        return "Beyond the SBGames 2010 paper: the house (team) colours of a Westwood VXL model as a mask texture in "
               "the atlas' layout. A texel is white where its voxel uses the palette's remap range (indices 16-31), "
               "the colours Tiberian Sun and Red Alert 2 tint per player, black elsewhere; the base colour keeps "
               "the palette's own colours. An engine multiplies the base colour by the player's colour where the "
               "mask is white.<br>Run it right after Voxel Texture Atlas, on the layer the atlas was built on "
               "(before duplicating or decimating: the decimated mesh keeps the atlas' layout, so the mask fits it "
               "too). The glTF exporter embeds the mask and names it in the material's extras "
               "(<tt>voxelfair_house_colour_mask</tt>).";
    case FP_MATERIAL_MAPS:
        return "Beyond the SBGames 2010 paper (its future work: material maps): the MagicaVoxel materials of a .vox "
               "model (MATL chunks: metal, roughness, emission and its power, glass with transmission and index of "
               "refraction) as glTF PBR maps in the atlas' layout: a metallic-roughness map (G roughness, B metallic), "
               "an emissive map (the voxel colour at its emission) and a transmission map, each only when some "
               "voxel needs it. Diffuse voxels stay matte (metallic 0, roughness 0.9).<br>Run it right after Voxel "
               "Texture Atlas, on the layer the atlas was built on (before duplicating or decimating). The glTF "
               "exporter embeds the maps (metallicRoughnessTexture, emissiveTexture with "
               "KHR_materials_emissive_strength above 1, KHR_materials_transmission and KHR_materials_ior).";
    }
    return QString();
}

MeshFilterInterface::FilterClass FilterVoxelfairPlugin::getClass(QAction *action) {
    // Never Generic: a Generic filter makes MeshLab 2020.09 abort plugin loading for everyone.
    switch (ID(action)) {
    case FP_LANCZOS_FAIRING: return MeshFilterInterface::Smoothing;
    case FP_ATTRIBUTE_SMOOTHING: return FilterClass(MeshFilterInterface::Normal | MeshFilterInterface::VertexColoring);
    case FP_TEXTURE_ATLAS: return MeshFilterInterface::Texture;
    case FP_NORMAL_MAP: return MeshFilterInterface::Texture;
    case FP_HOUSE_MASK: return MeshFilterInterface::Texture;
    case FP_MATERIAL_MAPS: return MeshFilterInterface::Texture;
    }
    return MeshFilterInterface::Smoothing;
}

int FilterVoxelfairPlugin::getPreConditions(QAction *) const { return MeshModel::MM_FACENUMBER; }

int FilterVoxelfairPlugin::getRequirements(QAction *action) {
    switch (ID(action)) {
    case FP_ATTRIBUTE_SMOOTHING: return MeshModel::MM_VERTCOLOR;
    case FP_TEXTURE_ATLAS: return MeshModel::MM_WEDGTEXCOORD;
    default: return MeshModel::MM_NONE;
    }
}

int FilterVoxelfairPlugin::postCondition(QAction *action) const {
    switch (ID(action)) {
    case FP_LANCZOS_FAIRING: return MeshModel::MM_VERTCOORD | MeshModel::MM_VERTNORMAL | MeshModel::MM_FACENORMAL;
    case FP_ATTRIBUTE_SMOOTHING:
        return MeshModel::MM_VERTNORMAL | MeshModel::MM_FACENORMAL | MeshModel::MM_VERTCOLOR | MeshModel::MM_FACEFLAG |
               MeshModel::MM_POLYGONAL;
    case FP_TEXTURE_ATLAS: return MeshModel::MM_WEDGTEXCOORD;
    case FP_NORMAL_MAP: return MeshModel::MM_NONE;
    case FP_HOUSE_MASK: return MeshModel::MM_NONE;
    case FP_MATERIAL_MAPS: return MeshModel::MM_NONE;
    }
    return MeshModel::MM_ALL;
}

void FilterVoxelfairPlugin::initParameterSet(QAction *action, MeshModel &m, RichParameterList &parameters) {
    switch (ID(action)) {
    case FP_LANCZOS_FAIRING:
        parameters.addParam(RichEnum(
            "mode", 0,
            QStringList() << "Paper"
                          << "Constrained",
            "Mode",
            "Paper: the SBGames 2010 operator exactly (lambda and passes below). Constrained (beyond the paper): "
            "staircase-aware normal filtering and vertex fitting, every vertex kept inside its voxel cell: about "
            "2.5 times more accurate on curved shapes, flat faces and straight edges kept sharp, thin parts and "
            "volume kept; slower (two passes of its own; lambda and passes are not used)."));
        parameters.addParam(
            RichFloat("lambda", 4.0f / 3.0f, "Lambda",
                      "Scales the estimated frequency (eq. 8). 4/3 is the authors' value; the paper's "
                      "text says 1.3. Higher smooths more; above 1.5 the staircase starts to overshoot."));
        parameters.addParam(
            RichInt("passes", 1, "Passes", "The paper needs one pass; each further pass smooths more."));
        parameters.addParam(RichFloat("voxelSize", 0.0f, "Voxel size",
                                      "Length of a voxel in mesh units: the unit of the displacement. 0 detects it as "
                                      "the mesh's dominant edge length, so a scaled model smooths the same; on an "
                                      "imported model, per section or instance."));
        parameters.addParam(RichBool("Selected", m.cm.svn > 0, "Affect only selected vertices",
                                     "Only selected vertices move; the others still act as neighbours."));
        break;
    case FP_ATTRIBUTE_SMOOTHING:
        parameters.addParam(RichBool("distinctNormals", true, "Count each normal direction once",
                                     "The paper's rule: a vertex normal is the mean of the distinct adjacent face "
                                     "normals. Off: the plain mean of all adjacent faces."));
        parameters.addParam(RichBool("triangulate", true, "Quads to triangles",
                                     "Make the polygons plain triangles (as the paper does before the atlas). Off "
                                     "keeps MeshLab's polygon (faux edge) flags."));
        break;
    case FP_TEXTURE_ATLAS:
        parameters.addParam(RichFloat("chartAngle", 45.573f, "Chart angle (degrees)",
                                      "A face joins a chart while its normal is within this angle of the chart's seed "
                                      "face normal. 45.57 (cos 0.7) is the authors' value; the paper's text says 60."));
        parameters.addParam(RichEnum("packing", 0,
                                     QStringList() << "Tight"
                                                   << "Paper",
                                     "Packing",
                                     "Tight: bottom-left fill of the charts' rasterised shapes with quarter turns "
                                     "(dense). Paper: the authors' guillotine merge of bounding boxes."));
        parameters.addParam(RichFloat("texelsPerVoxel", 8.0f, "Texels per voxel",
                                      "The least texture resolution: texels along one voxel edge. The texture is the "
                                      "smallest power of two holding the charts at it (square or 2:1); thin faces get "
                                      "more texels or their own charts so every face keeps its voxel colour."));
        parameters.addParam(RichInt("textureSize", 0, "Texture size (0: from the density)",
                                    "0: the size follows Texels per voxel (above). Otherwise this square size, at the "
                                    "highest texels per voxel that fits it."));
        parameters.addParam(
            RichBool("fillTexture", true, "Fill the texture",
                     "With a size from the density: raise the density until the charts fill the "
                     "texture chosen, instead of leaving what rounding up to a power of two left empty."));
        parameters.addParam(
            RichBool("wideTextures", true, "Allow 2:1 textures",
                     "With a size from the density: a texture twice as wide as tall when the charts fit "
                     "one, half the memory of the square."));
        parameters.addParam(RichInt("maxTextureSize", 4096, "Maximum texture size",
                                    "The largest texture side; if the charts do not fit, the resolution is lowered."));
        parameters.addParam(RichFloat("voxelSize", 0.0f, "Voxel size",
                                      "Length of a voxel in mesh units; 0 detects it from the dominant edge length."));
        parameters.addParam(RichInt("gutter", 2, "Gutter (texels)",
                                    "Empty texels between charts; half of it is filled with the chart's colours, "
                                    "and charts sit on 2 x 2 texel blocks of their own, so bilinear filtering and "
                                    "the first mip level do not bleed."));
        parameters.addParam(RichEnum("colours", 0,
                                     QStringList() << "Crisp voxel colours"
                                                   << "Smoothed vertex colours",
                                     "Texture colours",
                                     "Crisp: each texel takes its face's colour (from face colours). Smoothed: the "
                                     "vertex colours interpolated, as the paper does."));
        parameters.addParam(RichString("textureFile", defaultTextureName(m), "Texture file",
                                       "The PNG to write: a relative name is put beside the mesh's file."));
        break;
    case FP_HOUSE_MASK:
        parameters.addParam(RichString("houseFile", defaultHouseMaskName(m), "House colour mask file",
                                       "The PNG to write (greyscale, the base colour's size): a relative name is put "
                                       "beside the mesh's file."));
        addMapGutterParameters(parameters, "");
        break;
    case FP_MATERIAL_MAPS:
        parameters.addParam(
            RichString("metallicRoughnessFile", defaultMaterialMapName(m, "_metallic_roughness.png"),
                       "Metallic-roughness map file",
                       "The PNG to write (G roughness, B metallic) when some voxel is metal or rough; a "
                       "relative name is put beside the mesh's file."));
        parameters.addParam(RichString("emissiveFile", defaultMaterialMapName(m, "_emissive.png"), "Emissive map file",
                                       "The PNG to write when some voxel emits light."));
        parameters.addParam(RichString("transmissionFile", defaultMaterialMapName(m, "_transmission.png"),
                                       "Transmission map file", "The PNG to write when some voxel is glass."));
        addMapGutterParameters(parameters, "");
        break;
    }
}

void FilterVoxelfairPlugin::initParameterSet(QAction *action, MeshDocument &md, RichParameterList &parameters) {
    if (ID(action) != FP_NORMAL_MAP) {
        if (md.mm() != nullptr)
            initParameterSet(action, *md.mm(), parameters);
        return;
    }
    // The default source: the first other layer (the faired layer the current one was duplicated from).
    MeshModel *source = nullptr;
    for (MeshModel *m : md.meshList)
        if (m != md.mm()) {
            source = m;
            break;
        }
    parameters.addParam(RichMesh("sourceMesh", source ? source : md.mm(), &md, "Source layer",
                                 "The undecimated faired mesh whose shading is baked (the layer the current one was "
                                 "duplicated from before decimating)."));
    parameters.addParam(
        RichString("normalFile", md.mm() ? defaultNormalMapName(*md.mm()) : QString("voxelfair_normal.png"),
                   "Normal map file", "The PNG to write: a relative name is put beside the mesh's file."));
    parameters.addParam(RichInt("textureSize", 0, "Texture size",
                                "Side of a square normal map in texels; 0 takes the base colour texture's width x "
                                "height (the atlas' layout)."));
    parameters.addParam(RichEnum("level", 0,
                                 QStringList() << "Atlas size"
                                               << "Half (one texel per 2 x 2 block)",
                                 "Resolution",
                                 "Atlas size: the base colour's texel density. Half: half each side, one texel per "
                                 "2 x 2 texel block of the atlas (its mip 1; the charts are packed on such blocks): a "
                                 "quarter of the texels, memory and baking time, for smooth surfaces that need no "
                                 "pixel-art resolution."));
    parameters.addParam(RichInt("minSide", voxelfair::NormalBakeOptions().minSide, "Finer map for small atlases",
                                "At atlas size, a small atlas gets a finer normal map (same UVs): each side times 2 or "
                                "4, the least that brings the long side to at least this many texels (atlases of "
                                "1024 or more stay 1:1 at the default 1024); 0: the atlas' size. Not with a given "
                                "texture size or at half."));
    addMapGutterParameters(parameters, "at full size, ");
}

void FilterVoxelfairPlugin::report(const QString &message) {
    Log(message.toStdString());
    std::fprintf(stderr, "filter_voxelfair: %s\n", message.toLocal8Bit().constData());
}

bool FilterVoxelfairPlugin::fail(const QString &message) {
    errorMessage = message;
    Log(GLLogStream::WARNING, message.toStdString());
    std::fprintf(stderr, "filter_voxelfair: %s\n", message.toLocal8Bit().constData());
    return false;
}

bool FilterVoxelfairPlugin::applyFilter(QAction *action, MeshDocument &md, const RichParameterList &parameters,
                                        vcg::CallBackPos *cb) {
    // Nothing may escape into MeshLab: every failure becomes this filter's error.
    try {
        MeshModel *m = md.mm();
        if (m == nullptr)
            return fail("there is no current mesh");
        switch (ID(action)) {
        case FP_LANCZOS_FAIRING: return applyLanczosFairing(*m, parameters, cb);
        case FP_ATTRIBUTE_SMOOTHING: return applyAttributeSmoothing(*m, parameters, cb);
        case FP_TEXTURE_ATLAS: return applyTextureAtlas(*m, parameters, cb);
        case FP_NORMAL_MAP: return applyNormalMap(md, parameters, cb);
        case FP_HOUSE_MASK: return applyHouseMask(*m, parameters, cb);
        case FP_MATERIAL_MAPS: return applyMaterialMaps(*m, parameters, cb);
        }
        return fail("unknown filter");
    } catch (const std::bad_alloc &) {
        return fail(action->text() + ": not enough memory");
    } catch (const std::exception &e) {
        return fail(action->text() + ": " + e.what());
    } catch (...) {
        return fail(action->text() + ": unexpected error");
    }
}

MESHLAB_PLUGIN_NAME_EXPORTER(FilterVoxelfairPlugin)
