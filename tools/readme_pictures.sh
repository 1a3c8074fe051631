#!/bin/bash
# Renders the README's pictures (doc/images) again from this tree's build, so they show what the
# software does now:
#   *_strip.png            comparison_report's panels (raw, Taubin 10 steps, paper's pass,
#                          constrained mode, paper's pass with its baked texture), 280 px each
#   family_*_strip.png     comparison_report's shape-family strips as they are
#   3tnk_texture.png       the wrapper's crisp atlas of the whole 3tnk unit, scaled to 512 by point sampling
#   3tnk_blender_glb.png   the wrapper's 3tnk.glb rendered by Blender (tools/blender_render_glb.py)
#   3tnk_decimated_normal_map.png  the unit decimated to 10%, without and with its normal map
# gui.png is a screenshot of the MeshLab GUI and is not made here.
#
#   bash tools/readme_pictures.sh [BUILD_DIR]     (default: build; needs the shared models, ImageMagick, Blender)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
models="$root/../shared/models"
images="$root/doc/images"
[ -d "$models" ] || { echo "readme_pictures: $models is missing (the shared models)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

for model in robo 3tnk "sphere r12"; do
    "$build/tools/comparison_report" "$work/report" --size 560 --only "$model" > /dev/null
done
for stem in robo 3tnk sphere_r12; do
    montage "$work/report/${stem}_"{raw,taubin,ours,constrained,textured}.png -tile 5x1 -geometry 280x280+0+0 \
        -colors 256 "PNG8:$images/${stem}_strip.png"
done
cp "$work/report/family_rounded_box.png" "$images/family_rounded_box_strip.png"
cp "$work/report/family_box_turned_about_two_axes.png" "$images/family_turned_box_strip.png"
cp "$work/report/family_cylinder.png" "$images/family_cylinder_strip.png"

convert_unit() {  # output folder, then the wrapper's extra options
    local out=$1
    shift
    python3 "$root/meshlab_scripts/voxelfair_convert.py" "$models/vxl/3tnk.vxl" -o "$out" --formats glb \
        --build "$build" "$@" > /dev/null
    [ -s "$out/3tnk.glb" ] || { echo "readme_pictures: the wrapper wrote no $out/3tnk.glb" >&2; exit 1; }
}
blender_render() {
    blender -b --factory-startup --python "$root/tools/blender_render_glb.py" -- "$@" > /dev/null 2>&1
}
convert_unit "$work/full"
convert "$work/full/3tnk_texture.png" -filter point -resize 512x512 -colors 256 "PNG8:$images/3tnk_texture.png"
blender_render "$work/full/3tnk.glb" "$work/glb.png" 640
convert "$work/glb.png" -colors 256 "PNG8:$images/3tnk_blender_glb.png"
convert_unit "$work/decimated" --decimate 0.1
blender_render "$work/decimated/3tnk.glb" "$images/3tnk_decimated_normal_map.png" 640 --pair
echo "readme_pictures: $(ls "$images" | wc -l) pictures in $images"
