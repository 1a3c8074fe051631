// The gutter of a baked normal map (normal_bake.h), as the base colour's (atlas/bake.h, paper
// section 4.5): `rings` rings of texels around the painted ones take the renormalised mean of
// their painted 8-neighbours (texel_dilation.h); then, with `blockSide` > 0 (an atlas packed on
// aligned 2 x 2 blocks, PackOptions::mipBlocks: 2 for a map of the atlas' size, 2f for one f
// times finer), the unpainted texels of every aligned blockSide x blockSide block with a painted
// texel take the renormalised mean of its painted ones, so box-filtered mips down to the block's
// never mix charts. 0: no block fill.
// Texels are RGBA8 unit vectors (c + 1) / 2 * 255, rows from the top (image row height - 1 - y
// holds state row y); the means decode (2 c - 255) / 255 in integers. Renormalised means of zero
// length leave a texel unpainted (it keeps its colour). `state` marks painted texels with
// kTexelPainted (other bits are kept); filled texels get it too. Rows are split into bands run on
// `threads` threads: the result does not depend on the thread count.
#pragma once

#include <cstdint>

namespace voxelfair {

void fillNormalGutter(int width, int height, uint8_t *state, uint8_t *rgba, int rings, int blockSide, int threads);

}  // namespace voxelfair
