#!/usr/bin/env bash
# Builds the fairing library and its tests with VOXELFAIR_NO_SIMD=ON (the constrained fairing's
# scalar code, see libvoxelfair/base/simd_variant.h) in build-nosimd/, and runs them with CTest,
# the SSE2/scalar equivalence test included (there it links the SSE2 variant beside the scalar
# default). The default build runs the same tests the other way round. The normal bake's unit
# tests run there too: its scalar loop (normal_bake.cpp without the 4-texel SSE2 fast path) must
# read the same normal fields back on generated planes and give the same map on any thread count.
#
#   tools/no_simd.sh               configure, build and run the fairing and normal bake tests
#   tools/no_simd.sh -R Equivalence  extra arguments go to ctest
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${VOXELFAIR_NO_SIMD_BUILD_DIR:-$here/build-nosimd}
jobs=$(nproc 2>/dev/null || echo 2)

bash "$here/voxelfair.sh" setup

cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release -DVOXELFAIR_NO_SIMD=ON \
  -DVOXELFAIR_BUILD_PLUGINS=OFF -DVOXELFAIR_BUILD_BENCHMARKS=OFF -DVOXELFAIR_BUILD_TESTS=ON >/dev/null
targets=(fairing_test fairing_fidelity_test fairing_constrained_test fairing_family_test fairing_simd_equivalence_test
  fairing_information_limit_test
  maps_test)
cmake --build "$build" -j"$jobs" --target "${targets[@]}"
ctest --test-dir "$build" --output-on-failure -j"$jobs" -R '^(fairing_|maps_test\.)' "$@"
