// Images on disk and their comparison (include/gnomon/Image.h): PNG round trips byte for
// byte, 16-bit shadow maps really are 16-bit PNGs in the right byte order, failed writes
// throw gnomon::Error (Io) and leave no temporary file, compareImages counts as goldens need.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "UnitTestUtil.h"
#include "gnomon/Error.h"
#include "gnomon/Image.h"

namespace gnomon {
namespace {

namespace fs = std::filesystem;

std::vector<unsigned char> fileBytes(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<std::string> folderEntries(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir))
        names.push_back(e.path().filename().string());
    return names;
}

Image pattern(int w, int h, int channels) {
    Image img(w, h, channels);
    for (size_t i = 0; i < img.pixels.size(); ++i)
        img.pixels[i] = std::uint8_t((i * 37 + 11) % 256);
    return img;
}

TEST(Image, RgbaRoundTripIsExact) {
    const test::ScopedTempDir dir;
    const std::string path = (dir.path() / "rgba.png").string();
    const Image img = pattern(7, 5, 4);  // odd sizes: no row padding assumptions
    writePng(path, img);
    const Image back = readPng(path);
    EXPECT_EQ(back.width, 7);
    EXPECT_EQ(back.height, 5);
    EXPECT_EQ(back.channels, 4);
    EXPECT_EQ(back.pixels, img.pixels);
    // Written with the usual permissions, not mkstemp's 0600.
    const fs::perms p = fs::status(path).permissions();
    EXPECT_EQ(p & fs::perms::all, fs::perms::owner_read | fs::perms::owner_write |
                                      fs::perms::group_read | fs::perms::others_read);
}

TEST(Image, FewerChannelsReadBackAsRgba) {
    const test::ScopedTempDir dir;
    for (int channels = 1; channels <= 3; ++channels) {
        SCOPED_TRACE(testing::Message() << channels << " channels");
        const std::string path = (dir.path() / ("c" + std::to_string(channels) + ".png")).string();
        const Image img = pattern(4, 3, channels);
        writePng(path, img);
        const Image back = readPng(path);
        ASSERT_EQ(back.channels, 4);
        ASSERT_EQ(back.pixels.size(), size_t(4 * 3 * 4));
        for (int y = 0; y < 3; ++y) {
            for (int x = 0; x < 4; ++x) {
                const std::uint8_t* a = img.at(x, y);
                const std::uint8_t* b = back.at(x, y);
                const bool grey = channels <= 2;
                EXPECT_EQ(b[0], a[0]);
                EXPECT_EQ(b[1], grey ? a[0] : a[1]);
                EXPECT_EQ(b[2], grey ? a[0] : a[2]);
                EXPECT_EQ(b[3], channels == 2 ? a[1] : 255);
            }
        }
    }
}

TEST(Image, SixteenBitWriteIsASixteenBitGreyPng) {
    const test::ScopedTempDir dir;
    const fs::path path = dir.path() / "depth.png";
    Image16 depth;
    depth.width = 3;
    depth.height = 2;
    depth.pixels = {0x0000, 0x1234, 0xAB12, 0xFFFF, 0x8000, 0x00FF};
    writePng(path.string(), depth);
    const std::vector<unsigned char> bytes = fileBytes(path);
    ASSERT_GT(bytes.size(), 33u);
    const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    for (int i = 0; i < 8; ++i)
        EXPECT_EQ(bytes[size_t(i)], signature[i]) << "signature byte " << i;
    // IHDR: length (8..11), "IHDR" (12..15), width (16..19), height (20..23), big-endian,
    // then bit depth (24) and colour type (25, 0 = grey).
    EXPECT_EQ(std::string(bytes.begin() + 12, bytes.begin() + 16), "IHDR");
    EXPECT_EQ(bytes[19], 3);
    EXPECT_EQ(bytes[23], 2);
    EXPECT_EQ(bytes[24], 16);
    EXPECT_EQ(bytes[25], 0);
    // readPng reduces 16 bits to 8 by keeping the high byte: if the samples were written in
    // the wrong byte order, 0xAB12 would read back as 0x12.
    const Image back = readPng(path.string());
    ASSERT_EQ(back.width, 3);
    ASSERT_EQ(back.height, 2);
    for (int i = 0; i < 6; ++i)
        EXPECT_EQ(back.at(i % 3, i / 3)[0], depth.pixels[size_t(i)] >> 8) << "sample " << i;
}

TEST(Image, WriteIntoMissingFolderThrowsIoAndLeavesNothing) {
    const test::ScopedTempDir dir;
    const std::string path = (dir.path() / "missing" / "out.png").string();
    try {
        writePng(path, pattern(2, 2, 4));
        FAIL() << "writePng did not throw";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::Io);
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
    EXPECT_TRUE(folderEntries(dir.path()).empty());
    EXPECT_FALSE(fs::exists(dir.path() / "missing"));
}

TEST(Image, FailedRenameRemovesTheTemporaryFile) {
    // The target is a non-empty folder: the data is written to the temporary file, then the
    // rename fails. The temporary file must be gone and the folder untouched.
    const test::ScopedTempDir dir;
    const fs::path target = dir.path() / "taken.png";
    fs::create_directories(target / "inside");
    try {
        writePng(target.string(), pattern(2, 2, 3));
        FAIL() << "writePng did not throw";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::Io);
        EXPECT_NE(std::string(e.what()).find(target.string()), std::string::npos) << e.what();
    }
    EXPECT_EQ(folderEntries(dir.path()), std::vector<std::string>{"taken.png"});
    EXPECT_TRUE(fs::is_directory(target / "inside"));
}

TEST(Image, OverwriteReplacesTheWholeFile) {
    const test::ScopedTempDir dir;
    const std::string path = (dir.path() / "img.png").string();
    writePng(path, pattern(64, 64, 4));
    const Image small = pattern(2, 1, 4);
    writePng(path, small);
    EXPECT_EQ(readPng(path).pixels, small.pixels);
    EXPECT_EQ(folderEntries(dir.path()), std::vector<std::string>{"img.png"});
}

TEST(Image, InvalidImagesAreRejectedBeforeAnyFileExists) {
    const test::ScopedTempDir dir;
    const std::string path = (dir.path() / "bad.png").string();
    Image fiveChannels = pattern(2, 2, 4);
    fiveChannels.channels = 5;
    Image shortPixels = pattern(3, 3, 4);
    shortPixels.pixels.pop_back();
    Image empty;
    for (const Image* img : {&fiveChannels, &shortPixels, &empty}) {
        try {
            writePng(path, *img);
            ADD_FAILURE() << "writePng accepted a malformed image";
        } catch (const Error& e) {
            EXPECT_EQ(e.kind(), ErrorKind::InvalidInput) << e.what();
        }
    }
    Image16 depth;
    depth.width = 4;
    depth.height = 4;
    depth.pixels.resize(15);
    EXPECT_THROW(writePng(path, depth), Error);
    EXPECT_TRUE(folderEntries(dir.path()).empty());
}

TEST(Image, ReadMissingOrCorruptFileThrowsIoNamingIt) {
    const test::ScopedTempDir dir;
    const std::string missing = (dir.path() / "none.png").string();
    const std::string corrupt = (dir.path() / "corrupt.png").string();
    std::ofstream(corrupt) << "not a png at all";
    for (const std::string& path : {missing, corrupt}) {
        try {
            readPng(path);
            ADD_FAILURE() << "readPng did not throw for " << path;
        } catch (const Error& e) {
            EXPECT_EQ(e.kind(), ErrorKind::Io);
            EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
        }
    }
}

TEST(ImageDiff, IdenticalImagesHaveNoDifference) {
    const Image a = pattern(5, 4, 4);
    const ImageDiff d = compareImages(a, a, 0);
    EXPECT_EQ(d.maxChannelDiff, 0);
    EXPECT_EQ(d.failingFraction, 0.0);
    EXPECT_EQ(d.meanAbsDiff, 0.0);
    EXPECT_EQ(d.diff.width, 5);
    EXPECT_EQ(d.diff.height, 4);
    EXPECT_EQ(d.diff.channels, 3);
    EXPECT_EQ(d.diff.pixels, std::vector<std::uint8_t>(5 * 4 * 3, 0));
}

TEST(ImageDiff, OnePixelChangedByTen) {
    // 4 x 3 = 12 pixels, 4 channels; pixel (2, 1) green +10.
    const Image a = pattern(4, 3, 4);
    Image b = a;
    b.at(2, 1)[1] = std::uint8_t(a.at(2, 1)[1] >= 128 ? a.at(2, 1)[1] - 10 : a.at(2, 1)[1] + 10);
    const ImageDiff strict = compareImages(a, b, 5);
    EXPECT_EQ(strict.maxChannelDiff, 10);
    EXPECT_DOUBLE_EQ(strict.failingFraction, 1.0 / 12.0);
    EXPECT_DOUBLE_EQ(strict.meanAbsDiff, 10.0 / (12.0 * 4.0));
    // The visual diff scales x4: 40 in green at (2, 1), 0 elsewhere.
    EXPECT_EQ(strict.diff.at(2, 1)[1], 40);
    EXPECT_EQ(strict.diff.at(2, 1)[0], 0);
    EXPECT_EQ(strict.diff.at(0, 0)[1], 0);
    // "Over the threshold" is strict: a difference equal to it passes.
    EXPECT_EQ(compareImages(a, b, 10).failingFraction, 0.0);
    EXPECT_EQ(compareImages(a, b, 9).failingFraction, 1.0 / 12.0);
}

TEST(ImageDiff, LargeDifferencesSaturateTheVisualDiff) {
    Image a(2, 1, 1), b(2, 1, 1);
    a.pixels = {0, 100};
    b.pixels = {200, 90};
    const ImageDiff d = compareImages(a, b, 0);
    EXPECT_EQ(d.maxChannelDiff, 200);
    EXPECT_EQ(d.failingFraction, 1.0);
    // Grey input: the diff is grey too (the one channel copied into R, G and B).
    for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(d.diff.at(0, 0)[c], 255);  // 200 * 4 saturates
        EXPECT_EQ(d.diff.at(1, 0)[c], 40);
    }
}

TEST(ImageDiff, ShapeMismatchThrows) {
    const Image a = pattern(4, 3, 4);
    EXPECT_THROW(compareImages(a, pattern(3, 3, 4), 0), Error);
    EXPECT_THROW(compareImages(a, pattern(4, 4, 4), 0), Error);
    EXPECT_THROW(compareImages(a, pattern(4, 3, 3), 0), Error);
    try {
        compareImages(a, pattern(4, 4, 4), 0);
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::InvalidInput);
        EXPECT_NE(std::string(e.what()).find("4x3x4 vs 4x4x4"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace gnomon
