// The VOX tests' check of a rejected file: reading `bytes` throws a FormatError whose message
// contains each of `parts` (the problem and where it is).
#pragma once

#include "formats/format_error.h"
#include "formats/vox.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

namespace voxelfair::test {

inline void expectVoxError(const std::vector<uint8_t> &bytes, std::initializer_list<std::string> parts) {
    try {
        readVox(bytes.data(), bytes.size());
        ADD_FAILURE() << "no error; expected one containing \"" << *parts.begin() << "\"";
    } catch (const FormatError &e) {
        for (const std::string &part : parts)
            EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    }
}

}  // namespace voxelfair::test
