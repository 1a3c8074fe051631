#include "hostile_input.h"

#include "allocation_meter.h"
#include "formats/file_bytes.h"
#include "formats/format_error.h"

#include <algorithm>
#include <chrono>
#include <cstdio>

namespace voxelfair::test {

Attempt attempt(Reader read, const Bytes &bytes) {
    Attempt a;
    const auto start = std::chrono::steady_clock::now();
    {
        AllocationMeter meter;
        try {
            read(bytes.data(), bytes.size());
            a.accepted = true;
        } catch (const FormatError &e) {
            a.error = e.what();
        }
        a.peakBytes = meter.peakBytes();
    }
    a.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return a;
}

::testing::AssertionResult survived(const Attempt &a, const HeapBound &bound, size_t inputSize, double maxSeconds) {
    if (!a.accepted && a.error.empty())
        return ::testing::AssertionFailure() << "FormatError with an empty message";
    if (a.error.size() > kMaxMessageLength)
        return ::testing::AssertionFailure()
               << "message of " << a.error.size() << " characters: " << a.error.substr(0, 200);
    if (a.peakBytes > bound.bytesFor(inputSize))
        return ::testing::AssertionFailure()
               << "peak heap " << a.peakBytes << " bytes for " << inputSize << " input bytes, over the bound "
               << bound.bytesFor(inputSize) << (a.accepted ? " (accepted)" : " (rejected: " + a.error + ")");
    if (a.seconds > maxSeconds)
        return ::testing::AssertionFailure() << "took " << a.seconds << " s";
    return ::testing::AssertionSuccess();
}

::testing::AssertionResult rejectedWith(const Attempt &a, std::initializer_list<const char *> parts) {
    if (a.accepted)
        return ::testing::AssertionFailure() << "accepted";
    for (const char *part : parts)
        if (a.error.find(part) == std::string::npos)
            return ::testing::AssertionFailure() << "\"" << a.error << "\" does not mention \"" << part << "\"";
    return ::testing::AssertionSuccess();
}

::testing::AssertionResult rejectedWithAnyOf(const Attempt &a, std::initializer_list<const char *> anyOf) {
    if (a.accepted)
        return ::testing::AssertionFailure() << "accepted";
    for (const char *part : anyOf)
        if (a.error.find(part) != std::string::npos)
            return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "\"" << a.error << "\" names none of the expected problems";
}

void SweepRecord::add(const Attempt &a) {
    ++inputs;
    accepted += a.accepted;
    maxPeakBytes = std::max(maxPeakBytes, a.peakBytes);
    maxSeconds = std::max(maxSeconds, a.seconds);
    longestMessage = std::max(longestMessage, a.error.size());
}

void SweepRecord::print(const char *what) const {
    std::printf("[ hostile  ] %s: %zu inputs, %zu accepted, peak heap %zu bytes, slowest %.4f s, longest message %zu\n",
                what, inputs, accepted, maxPeakBytes, maxSeconds, longestMessage);
}

void sweepTruncations(Reader read, const Bytes &file, const HeapBound &bound, std::initializer_list<const char *> anyOf,
                      const char *what) {
    SweepRecord record;
    for (size_t n = 0; n < file.size(); ++n) {
        const Bytes cut(file.begin(), file.begin() + std::ptrdiff_t(n));
        const Attempt a = attempt(read, cut);
        record.add(a);
        ASSERT_TRUE(survived(a, bound, n)) << "cut at " << n;
        ASSERT_TRUE(rejectedWithAnyOf(a, anyOf)) << "cut at " << n;
    }
    record.print(what);
}

std::filesystem::path modelsDir() { return VOXELFAIR_MODELS_DIR; }

Bytes loadModel(const std::string &relativePath) {
    const std::filesystem::path path = modelsDir() / relativePath;
    if (!std::filesystem::is_regular_file(path))
        return {};
    return readFileBytes(path.string());
}

Bytes flipBits(Bytes bytes, std::mt19937 &rng, int flips) {
    if (bytes.empty())
        return bytes;
    std::uniform_int_distribution<size_t> bit(0, 8 * bytes.size() - 1);
    for (int i = 0; i < flips; ++i) {
        const size_t b = bit(rng);
        bytes[b / 8] ^= uint8_t(1u << (b % 8));
    }
    return bytes;
}

void sweepBitFlips(Reader read, const Bytes &base, const BitFlipSweep &sweep, const HeapBound &bound,
                   SweepRecord &record, std::initializer_list<const char *> rejectedAnyOf) {
    const auto bitsOf = [&](const ByteRange &r) {
        const size_t end = std::min(r.end, base.size());
        return r.begin < end ? 8 * (end - r.begin) : size_t(0);
    };
    size_t focusBits = 0;
    for (const ByteRange &r : sweep.focus)
        focusBits += bitsOf(r);
    std::mt19937 rng(sweep.seed);
    std::uniform_int_distribution<int> flips(1, sweep.maxFlips);
    for (int i = 0; i < sweep.variants; ++i) {
        Bytes b = base;
        if (i % 2 == 1 && focusBits > 0) {
            std::uniform_int_distribution<size_t> bit(0, focusBits - 1);
            for (int f = flips(rng); f > 0; --f) {
                size_t k = bit(rng);
                for (const ByteRange &r : sweep.focus) {
                    const size_t bits = bitsOf(r);
                    if (k < bits) {
                        b[r.begin + k / 8] ^= uint8_t(1u << (k % 8));
                        break;
                    }
                    k -= bits;
                }
            }
        } else {
            b = flipBits(std::move(b), rng, flips(rng));
        }
        const Attempt a = attempt(read, b);
        record.add(a);
        ASSERT_TRUE(survived(a, bound, b.size())) << "seed " << sweep.seed << ", variant " << i;
        if (!a.accepted && rejectedAnyOf.size() > 0) {
            ASSERT_TRUE(rejectedWithAnyOf(a, rejectedAnyOf)) << "seed " << sweep.seed << ", variant " << i;
        }
    }
}

void patch32(Bytes &bytes, size_t offset, uint32_t value) {
    for (int i = 0; i < 4; ++i)
        bytes.at(offset + size_t(i)) = uint8_t(value >> (8 * i));
}

uint32_t load32(const Bytes &bytes, size_t offset) {
    uint32_t v = 0;
    for (int i = 0; i < 4; ++i)
        v |= uint32_t(bytes.at(offset + size_t(i))) << (8 * i);
    return v;
}

}  // namespace voxelfair::test
