#include "formats/file_bytes.h"
#include "formats/format_error.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

using namespace voxelfair;

namespace {

std::string errorOf(const std::string &path, size_t maxBytes = kMaxModelFileBytes) {
    try {
        readFileBytes(path, maxBytes);
    } catch (const FormatError &e) {
        return e.what();
    }
    return "";
}

// A file in the test's temporary folder, removed at the end of the test.
struct TempFile {
    std::filesystem::path path;
    explicit TempFile(const std::vector<uint8_t> &bytes) {
        path = std::filesystem::temp_directory_path() /
               ("voxelfair_file_bytes_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::ofstream(path, std::ios::binary)
            .write(reinterpret_cast<const char *>(bytes.data()), std::streamsize(bytes.size()));
    }
    ~TempFile() { std::filesystem::remove(path); }
};

}  // namespace

TEST(FileBytes, ReadsTheWholeFile) {
    std::vector<uint8_t> bytes(200000);
    for (size_t i = 0; i < bytes.size(); ++i)
        bytes[i] = uint8_t(i * 31 + 7);
    const TempFile file(bytes);
    EXPECT_EQ(readFileBytes(file.path.string()), bytes);
    const TempFile empty({});
    EXPECT_TRUE(readFileBytes(empty.path.string()).empty());
}

TEST(FileBytes, MissingFileNamesPathAndReason) {
    const std::string path = "/nonexistent/voxelfair/model.vxl";
    EXPECT_EQ(errorOf(path), path + ": cannot open (No such file or directory)");
}

TEST(FileBytes, DirectoryCannotBeRead) {
    const std::string path = std::filesystem::temp_directory_path().string();
    const std::string message = errorOf(path);
    EXPECT_EQ(message.rfind(path + ": cannot", 0), 0u) << message;
}

TEST(FileBytes, RejectsFilesAboveTheLimit) {
    const TempFile file(std::vector<uint8_t>(101, 1));
    EXPECT_EQ(readFileBytes(file.path.string(), 101).size(), 101u);
    EXPECT_NE(errorOf(file.path.string(), 100).find("larger than 100 bytes"), std::string::npos);
}
