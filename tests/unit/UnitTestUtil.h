// Helpers shared by the unit tests: element-wise matrix comparison that names the failing
// element (glm is column-major: m[col][row]), finiteness and orthonormality checks for view
// matrices, and a per-test temporary folder that is removed afterwards.
#pragma once

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <glm/glm.hpp>

namespace gnomon::test {

// EXPECT_PRED_FORMAT3(matNear, actual, expected, tolerance)
inline ::testing::AssertionResult matNear(const char* actualExpr, const char* expectedExpr,
                                          const char*, const glm::mat4& actual,
                                          const glm::mat4& expected, float tolerance) {
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            if (!(std::fabs(actual[c][r] - expected[c][r]) <= tolerance)) {
                return ::testing::AssertionFailure()
                       << actualExpr << "[" << c << "][" << r << "] = " << actual[c][r]
                       << ", expected " << expected[c][r] << " (" << expectedExpr << "), tolerance "
                       << tolerance;
            }
        }
    }
    return ::testing::AssertionSuccess();
}

// Component-wise comparison of two vectors.
inline void expectVec(const glm::vec3& actual, const glm::vec3& expected, float tolerance = 1e-5f) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

inline bool allFinite(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

// The upper 3x3 of a rigid view matrix has orthonormal rows and determinant +1.
inline void expectRotationPart(const glm::mat4& m, float tolerance = 1e-5f) {
    const glm::mat3 r(m);
    const glm::mat3 rrt = r * glm::transpose(r);
    for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(rrt[c][k], c == k ? 1.0f : 0.0f, tolerance)
                << "R*R^T[" << c << "][" << k << "]";
    EXPECT_NEAR(glm::determinant(r), 1.0f, tolerance);
}

// A fresh folder under the system temp folder, unique per test, removed on destruction.
class ScopedTempDir {
public:
    ScopedTempDir() {
        const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
        std::string name = "gnomon-unit-" + std::to_string(::getpid());
        if (info) name += std::string("-") + info->test_suite_name() + "-" + info->name();
        for (char& ch : name)
            if (ch == '/') ch = '_';
        mPath = std::filesystem::temp_directory_path() / name;
        std::filesystem::remove_all(mPath);
        std::filesystem::create_directories(mPath);
    }
    ~ScopedTempDir() {
        std::error_code ec;
        std::filesystem::remove_all(mPath, ec);
    }
    ScopedTempDir(const ScopedTempDir&) = delete;
    ScopedTempDir& operator=(const ScopedTempDir&) = delete;
    const std::filesystem::path& path() const { return mPath; }

private:
    std::filesystem::path mPath;
};

}  // namespace gnomon::test
