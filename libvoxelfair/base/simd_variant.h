// Which vector code the constrained fairing (fairing/constrained_fairing.h) and the normal bake's
// fast path (maps/normal_bake.cpp) are compiled with, and the inline namespace that keeps the
// fairing's two variants apart.
//
// SSE2 where the target has it (every x86-64), plain C++ otherwise or when VOXELFAIR_NO_SIMD is
// defined (the CMake option of the same name defines it for vf_fairing and its users and for
// vf_maps, as meshoptimizer's MESHOPTIMIZER_NO_SIMD does). The fairing's two variants give the
// same results up to float rounding: the SIMD kernels sum in another order
// (tests/fairing/simd_equivalence_test.cpp states and checks the tolerance); the bake's give the
// same map bit for bit (each lane repeats the scalar operations in their order). The variant names an inline namespace around fairConstrained and
// every internal of the constrained fairing, so that a program can link both variants side by
// side (voxelfair::sse2::fairConstrained, voxelfair::scalar::fairConstrained); callers just write
// voxelfair::fairConstrained.
#pragma once

#if !defined(VOXELFAIR_NO_SIMD) && (defined(__SSE2__) || defined(_M_X64) || defined(_M_AMD64))
#define VOXELFAIR_SSE2 1
#define VOXELFAIR_SIMD_VARIANT sse2
#else
#define VOXELFAIR_SIMD_VARIANT scalar
#endif
