// gnomon::nearestName (Error.h), behind every "did you mean" (scenes, commands, flags): the
// nearest name in typing slips, and none when the word is further than a slip or two away.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "gnomon/Error.h"

namespace gnomon {
namespace {

TEST(NearestName, AllowsAFewSlipsByLength) {
    const std::vector<std::string> names = {"render", "score", "tune", "map-size", "map-sizes"};
    EXPECT_EQ(nearestName("rendr", names), "render");       // one left out
    EXPECT_EQ(nearestName("scroe", names), "score");        // two changed
    EXPECT_EQ(nearestName("map-sise", names), "map-size");  // nearer than map-sizes
    EXPECT_EQ(nearestName("map-size", names), "map-size");  // itself, 0 slips
    EXPECT_EQ(nearestName("bench", names), "");             // 4 slips from the nearest
    EXPECT_EQ(nearestName("", names), "");                  // 4 from tune
    EXPECT_EQ(nearestName("rendr", {}), "");
    // Longer words allow a quarter of their letters: 3 slips for 13 letters.
    EXPECT_EQ(nearestName("tutorial-rxxx", {"tutorial-room"}), "tutorial-room");
    EXPECT_EQ(nearestName("tutorial-xxxx", {"tutorial-room"}), "");
}

TEST(NearestName, FirstOfEquallyNearWins) {
    EXPECT_EQ(nearestName("cat", {"bat", "hat"}), "bat");
    EXPECT_EQ(nearestName("cat", {"hat", "bat"}), "hat");
}

}  // namespace
}  // namespace gnomon
