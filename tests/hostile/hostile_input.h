// Shared machinery of the hostile-input suite: run a reader on untrusted bytes and check that it
// either accepts them or throws a FormatError naming the problem, within a heap bound and without
// hanging. Any other exception fails the test where it is thrown.
#pragma once

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <random>
#include <string>
#include <vector>

namespace voxelfair::test {

using Bytes = std::vector<uint8_t>;

// Parses and discards (a lambda around readVxl, readVox, ...).
using Reader = void (*)(const uint8_t *data, size_t size);

// Heap a reader may use for an input of n bytes: perByte * n + fixed. `fixed` covers what the
// documented limits let a short header claim (doc/limits.md); `perByte` the per-byte overheads.
struct HeapBound {
    size_t perByte;
    size_t fixed;
    size_t bytesFor(size_t n) const { return perByte * n + fixed; }
};

struct Attempt {
    bool accepted = false;
    std::string error;  // the FormatError's message when not accepted
    size_t peakBytes = 0;
    double seconds = 0;
};

Attempt attempt(Reader read, const Bytes &bytes);

// An input that takes longer than this is a hang: real files of a few KB parse in well under a
// millisecond, even under the sanitizers.
constexpr double kHangSeconds = 5.0;

// Longest acceptable error message: it names the problem and where, never dumps file content.
constexpr size_t kMaxMessageLength = 400;

// Accepted or a FormatError with a short, non-empty message; within `bound`; not hanging (a test
// working at a documented limit may allow more time).
::testing::AssertionResult survived(const Attempt &a, const HeapBound &bound, size_t inputSize,
                                    double maxSeconds = kHangSeconds);

// A FormatError (not acceptance) whose message contains every part.
::testing::AssertionResult rejectedWith(const Attempt &a, std::initializer_list<const char *> parts);
// ... or at least one of `anyOf`.
::testing::AssertionResult rejectedWithAnyOf(const Attempt &a, std::initializer_list<const char *> anyOf);

// The worst case over many attempts, printed once so that the figures in doc/limits.md can be
// checked against a run.
struct SweepRecord {
    size_t inputs = 0, accepted = 0;
    size_t maxPeakBytes = 0;
    double maxSeconds = 0;
    size_t longestMessage = 0;
    void add(const Attempt &a);
    void print(const char *what) const;
};

// Every proper prefix of `file` (a cut at each byte): each must survive within `bound` and be
// rejected with a message containing one of `anyOf`. Prints the record as `what`.
void sweepTruncations(Reader read, const Bytes &file, const HeapBound &bound, std::initializer_list<const char *> anyOf,
                      const char *what);

// Bit-flipped variants of a file, from a fixed seed: each variant inverts 1..maxFlips random bits,
// every other one only within `focus` (where a format's offsets, counts and sizes are; flips in
// the payload mostly change colours), the rest anywhere (all of them when `focus` is empty).
struct ByteRange {
    size_t begin, end;
};
struct BitFlipSweep {
    uint32_t seed = 1;
    int variants = 1000;
    int maxFlips = 8;
    std::vector<ByteRange> focus;
};

// Each variant must survive within `bound`; when `rejectedAnyOf` is not empty, a rejection must
// name one of its parts. Adds every attempt to `record`.
void sweepBitFlips(Reader read, const Bytes &base, const BitFlipSweep &sweep, const HeapBound &bound,
                   SweepRecord &record, std::initializer_list<const char *> rejectedAnyOf = {});

// A file of the shared models folder (VOXELFAIR_MODELS_DIR), or empty when it is absent; tests
// then skip with a message naming the folder.
std::filesystem::path modelsDir();
Bytes loadModel(const std::string &relativePath);

// `bytes` with `flips` randomly chosen bits inverted.
Bytes flipBits(Bytes bytes, std::mt19937 &rng, int flips);

void patch32(Bytes &bytes, size_t offset, uint32_t value);
uint32_t load32(const Bytes &bytes, size_t offset);

}  // namespace voxelfair::test

// Skips the test when the shared model is missing.
#define VOXELFAIR_LOAD_MODEL_OR_SKIP(var, path)                                                                        \
    const ::voxelfair::test::Bytes var = ::voxelfair::test::loadModel(path);                                           \
    if (var.empty())                                                                                                   \
    GTEST_SKIP() << "shared model " << (::voxelfair::test::modelsDir() / (path)).string() << " is absent"
