#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/) with clang, ASan and UBSan in build-fuzz/, seeds their
# corpora and runs each for a bounded time. Fails on a crash, leak, timeout or out-of-memory
# input (saved under build-fuzz/artifacts/<target>/), and prints executions and coverage.
#
#   tools/fuzz.sh                       every target for 60 s (CI: 5 targets x 60 s)
#   tools/fuzz.sh --seconds 600         a longer run
#   tools/fuzz.sh fuzz_vox fuzz_vxl     only these targets
#
# Seeds: small files written by the test fixtures' writers (fuzz_seeds), plus the shared real
# models of ../shared/models when present (copied into build-fuzz only, never into the project).
# The corpora persist in build-fuzz/corpus/, so repeated runs continue where they stopped.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${VOXELFAIR_FUZZ_BUILD_DIR:-$here/build-fuzz}
models=${VOXELFAIR_MODELS_DIR:-$here/../shared/models}
seconds=60
targets=()
while [ $# -gt 0 ]; do
  case "$1" in
    --seconds) seconds=$2; shift 2 ;;
    --seconds=*) seconds=${1#*=}; shift ;;
    -h|--help) sed -n '2,13p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) targets+=("$1"); shift ;;
  esac
done
[ ${#targets[@]} -gt 0 ] || targets=(fuzz_vxl fuzz_hva fuzz_pal fuzz_vox fuzz_extraction)

as_root() {
  if [ "$(id -u)" -eq 0 ]; then "$@"; elif command -v sudo >/dev/null; then sudo "$@"; else
    echo "fuzz.sh: installing clang needs root (run as root or install sudo)" >&2; exit 1; fi
}

# A clang++ that links libFuzzer with ASan and UBSan, or nothing.
find_clang() {
  local probe='extern "C" int LLVMFuzzerTestOneInput(const unsigned char *, unsigned long) { return 0; }'
  for v in "" -14 -15 -16 -17 -18 -19; do
    if command -v "clang++$v" >/dev/null &&
        echo "$probe" | "clang++$v" -x c++ -fsanitize=fuzzer,address,undefined -o /dev/null - 2>/dev/null; then
      echo "clang++$v"; return 0
    fi
  done
  return 1
}

bash "$here/voxelfair.sh" setup  # the project's packages, installed only when missing
if ! cxx=$(find_clang); then
  echo "fuzz.sh: installing clang-14 and libclang-rt-14-dev"
  as_root apt-get update -q
  as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends \
    clang-14 libclang-rt-14-dev
  cxx=$(find_clang)
fi
cc=${cxx/clang++/clang}

cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_COMPILER="$cc" -DCMAKE_CXX_COMPILER="$cxx" \
  -DVOXELFAIR_BUILD_PLUGINS=OFF -DVOXELFAIR_BUILD_TESTS=OFF -DVOXELFAIR_BUILD_BENCHMARKS=OFF \
  -DVOXELFAIR_SANITIZE=address,undefined -DVOXELFAIR_BUILD_FUZZERS=ON >/dev/null
cmake --build "$build" -j"$(nproc 2>/dev/null || echo 2)" --target fuzz_seeds "${targets[@]}"

# Seed corpora: the fixtures' files always, the shared models of each kind when present. Large
# models are left out: mutating a 500 KB input is slow, and the small ones cover the same code.
corpus=$build/corpus
"$build/fuzz/fuzz_seeds" "$corpus"
seed_models() {  # target, glob under $models
  local target=$1 glob=$2
  [ -d "$models" ] || return 0
  find "$models" -path "$models/$glob" -size -64k -type f -exec cp -n {} "$corpus/$target/" \;
}
seed_models fuzz_vxl 'vxl/*.vxl'
seed_models fuzz_hva 'vxl/*.hva'
seed_models fuzz_pal 'pal/*.pal'
seed_models fuzz_vox 'vox/*.vox'
[ -d "$models" ] || echo "fuzz.sh: $models is absent; seeding from the fixtures only"

# Per target: at most 2 GB of memory (one allocation above it is a failure too), 10 s per input,
# inputs up to 64 KB. Leaks fail the run (LeakSanitizer is on under ASan).
failed=()
summary=()
for target in "${targets[@]}"; do
  artifacts=$build/artifacts/$target
  log=$build/logs/$target.log
  mkdir -p "$artifacts" "$(dirname "$log")" "$corpus/$target"
  echo "== $target: ${seconds} s"
  status=0
  UBSAN_OPTIONS=print_stacktrace=1 "$build/fuzz/$target" "$corpus/$target" \
    -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 -max_len=65536 \
    -print_final_stats=1 -artifact_prefix="$artifacts/" >"$log" 2>&1 || status=$?
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -n 1 | cut -d' ' -f2)
  ft=$(grep -o 'ft: [0-9]*' "$log" | tail -n 1 | cut -d' ' -f2)
  units=$(ls "$corpus/$target" | wc -l)
  line=$(printf '%-16s %12s executions  %6s coverage edges  %6s features  %5s corpus inputs' \
    "$target" "${runs:-?}" "${cov:-?}" "${ft:-?}" "$units")
  if [ "$status" -ne 0 ]; then
    line="$line  FAILED (exit $status)"
    failed+=("$target")
    grep -E 'ERROR|SUMMARY|invariant|runtime error|Test unit written' "$log" | head -n 20 || true
    echo "   full log: $log"
  fi
  summary+=("$line")
done

echo
echo "fuzzing summary (${seconds} s per target):"
printf '  %s\n' "${summary[@]}"
if [ ${#failed[@]} -gt 0 ]; then
  echo "fuzz.sh: failing inputs are in $build/artifacts/<target>/; reproduce with build-fuzz/fuzz/<target> <file>" >&2
  exit 1
fi
